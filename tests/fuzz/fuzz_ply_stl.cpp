// libFuzzer target: PLY and STL through Assimp, then our checks and the BVH, must turn any
// bytes into a scene or one rt::Error. Input that starts like a PLY header is loaded as
// a .ply, anything else as an .stl (ASCII or binary, as Assimp decides).
#include <cstring>

#include "fuzz_load.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const bool ply = size >= 3 && std::memcmp(data, "ply", 3) == 0;
    return fuzz_load(data, size, ply ? ".ply" : ".stl");
}
