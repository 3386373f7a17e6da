// libFuzzer target: the glTF path (tinygltf, then our accessor and hierarchy checks, the
// material mapping and the BVH) must turn any bytes into a scene or one rt::Error. Input
// that starts like a binary glTF is loaded as a .glb, anything else as a .gltf.
#include <cstring>

#include "fuzz_load.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    return fuzz_load(data, size, binary ? ".glb" : ".gltf");
}
