#pragma once
// A name table (core/names.h's Named<E>, or any entries with `name` and `value`) as a
// CLI11 transform: an option bound to an enum accepts exactly the table's names (not the
// enum's numbers), its help lists them, and anything else is refused by name:
//   rtrender: command line: --mode: "bogus" is not one of trace, raster, both or itembuffer

#include <string>

#include <CLI/CLI.hpp>

#include "core/names.h"

namespace rt::app {

template <class Entry, std::size_t N>
CLI::Validator cli_names(const Entry (&table)[N]) {  // table: static storage, as all are
    std::string choices;
    for (const Entry& e : table) choices += (choices.empty() ? "" : ",") + std::string(e.name);
    return CLI::Validator(
        [&table](std::string& input) -> std::string {
            for (const Entry& e : table)
                if (input == e.name) {
                    input = std::to_string(static_cast<long long>(e.value));
                    return {};
                }
            return "\"" + input + "\" is not one of " + names_list(table);
        },
        "{" + choices + "}");
}

}  // namespace rt::app
