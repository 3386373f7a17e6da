#pragma once
// A file's kind by its extension, case-insensitively (".OBJ" is an OBJ file).

#include <cctype>
#include <filesystem>
#include <string>

namespace rt {

inline std::string lower_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

}  // namespace rt
