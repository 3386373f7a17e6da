#pragma once
// Where a program finds what it ships beside itself (shaders, scenes, the image codec
// module), in the layout `cmake --install` writes and the build tree mirrors:
//   PREFIX/bin/PROGRAM  ->  PREFIX/share/rtview/..., PREFIX/lib/rtview/...
// The build tree's programs sit one folder deeper (build/app/render/rtrender,
// build/tests/rt_tests), and a copied bundle keeps everything in the program's folder.
// No path of the source tree is compiled in: an installed program runs anywhere.

#include <filesystem>

namespace rt {

// The folder of the running program (/proc/self/exe), or empty if it cannot be read.
std::filesystem::path program_dir();

// The first that exists of PROGRAM_DIR/../IN_PREFIX, PROGRAM_DIR/../../IN_PREFIX and
// PROGRAM_DIR/NAME (NAME: IN_PREFIX's last part); if none does, the first, so that a
// message names where it should be.
std::filesystem::path find_beside_program(const std::filesystem::path& in_prefix);

}  // namespace rt
