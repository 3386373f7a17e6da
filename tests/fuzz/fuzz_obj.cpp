// libFuzzer target: the OBJ path (tinyobjloader, then our checks, normals and BVH) must
// turn any bytes into a framed, lit scene or one rt::Error.
#include "fuzz_load.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return fuzz_load(data, size, ".obj");
}
