#pragma once
// An enum's names, written once in a table that parsing, printing and the programs'
// command-line checks all read (app/common/cli_names.h feeds CLI11 from the same table).
//
//   inline constexpr Named<AccelKind> kAccelNames[] = {{"bvh", AccelKind::kBvh}, ...};
//   parse_named(kAccelNames, "grid") == AccelKind::kGrid;  name_of(kAccelNames, kGrid) == "grid"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace rt {

template <class E>
struct Named {
    const char* name;
    E value;
};

template <class E, std::size_t N>
constexpr std::optional<E> parse_named(const Named<E> (&table)[N], std::string_view name) {
    for (const Named<E>& n : table)
        if (name == n.name) return n.value;
    return std::nullopt;
}

template <class E, std::size_t N>
constexpr const char* name_of(const Named<E> (&table)[N], E value) {
    for (const Named<E>& n : table)
        if (n.value == value) return n.name;
    return "?";
}

// "a, b or c", for messages (of any table whose entries have a `name`).
template <class Entry, std::size_t N>
std::string names_list(const Entry (&table)[N]) {
    std::string out;
    for (std::size_t i = 0; i < N; ++i)
        out += (i == 0 ? "" : i + 1 == N ? " or " : ", ") + std::string(table[i].name);
    return out;
}

}  // namespace rt
