#pragma once
// Where rtview's programs find their shaders and shipped assets (scenes, models), in this
// order:
//   1. $RTVIEW_SHADER_DIR, $RTVIEW_ASSET_DIR, when set;
//   2. share/rtview/shaders and share/rtview/assets one or two folders above the program:
//      PREFIX/bin/rtview -> PREFIX/share/rtview, the layout `cmake --install` writes; the
//      build tree mirrors it (build/share/rtview holds links to the source tree's folders,
//      so an edited shader needs no build);
//   3. shaders/ and assets/ in the program's own folder (a copied bundle).
// (core/program_dir.h: the image codec module is found the same way, in lib/rtview.)
// No path of the source tree is compiled in: an installed program runs anywhere.

#include <filesystem>

namespace rt::app {

std::filesystem::path shader_dir();
std::filesystem::path asset_dir();

}  // namespace rt::app
