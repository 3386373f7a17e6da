// libFuzzer target: the JSON scene loader must turn any bytes into a scene or one
// rt::Error, never a crash, a hang or a sanitizer report.
#include <unistd.h>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "core/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // The loader reads files (meshes are relative to the scene): give it one.
    static const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                              ("rtview_fuzz_" + std::to_string(getpid()) + ".json");
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    try {
        rt::LoadedScene loaded = rt::load_scene(path);
        loaded.scene.build();
    } catch (const rt::Error&) {
    }
    return 0;
}
