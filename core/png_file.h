#pragma once
// PNG files written by libpng itself, not through the image codec module: a render to PNG,
// the common case, then never loads OpenImageIO's 261 libraries (core/image_codec.h).

#include <cstdint>
#include <string>

namespace rt {

// 8-bit RGB, rows top first, into a new file at `path`. Returns an empty string, or one
// line saying what went wrong. Each row is filtered with SUB alone (libpng would try all
// five on every row: twice the encoder's instructions for a 1280 x 720 frame, files as
// small; docs/BENCHMARKS.md).
std::string write_png_file(const std::string& path, int width, int height, const std::uint8_t* rgb);

}  // namespace rt
