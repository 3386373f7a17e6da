#pragma once
// Shared by the fuzz targets: the loaders read files (meshes are relative to the
// scene), so each input is written to a per-process temporary file with the given
// extension, loaded and built; rt::Error is the expected way to refuse it.

#include <unistd.h>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "core/scene_loader.h"

inline int fuzz_load(const std::uint8_t* data, std::size_t size, const char* extension) {
    static const std::filesystem::path path =
        std::filesystem::temp_directory_path() /
        ("rtview_fuzz_" + std::to_string(getpid()) + extension);
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    try {
        rt::LoadedScene loaded = rt::load_scene(path);
        const rt::Scene scene(std::move(loaded.scene));  // the build, too, must survive it
    } catch (const rt::Error&) {
    }
    return 0;
}
