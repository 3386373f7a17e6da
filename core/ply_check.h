#pragma once
// What rtview checks of a PLY file before Assimp reads it (core/assimp_loader.cpp): that
// its header ends, and that its body holds every element the header declares, each with
// all its values. Assimp's reader loops for ever on a header without its end_header
// line, takes minutes over a hundred million vertices declared in a few bytes, and reads
// a body cut short as if it were whole (an ASCII file's missing faces left out, its last
// face's missing indices made up, a binary file's indices read past its end): a silently
// wrong mesh, or its own message with no place in the file. Instead, one located error:
// the line of an ASCII file, or the element of a binary one, where it ends or a value is
// missing.

#include <cstdint>
#include <istream>
#include <string>

namespace rt {

// Reads `in` (positioned at the file's first byte, after any byte order mark) to its
// end; `file_bytes` is the file's size. Throws rt::Error with `file` and the place.
void check_ply(const std::string& file, std::istream& in, std::uint64_t file_bytes);

}  // namespace rt
