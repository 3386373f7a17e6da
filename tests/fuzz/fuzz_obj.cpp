// libFuzzer target: the OBJ path (tinyobjloader, then our checks, normals and BVH) must
// turn any bytes into a mesh or one rt::Error.
#include <unistd.h>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "core/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                              ("rtview_fuzz_" + std::to_string(getpid()) + ".obj");
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    try {
        rt::LoadedScene loaded = rt::load_scene(path);  // a bare .obj: framed, lit, built
        loaded.scene.build();
    } catch (const rt::Error&) {
    }
    return 0;
}
