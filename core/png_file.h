#pragma once
// PNG files written and read by libpng itself, not through the image codec module: a
// render to PNG, the common case, and a scene whose textures are PNG then never load
// OpenImageIO's 261 libraries (core/image_codec.h).

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/image_codec.h"

namespace rt {

// 8-bit RGB, rows top first, into a new file at `path`. Returns an empty string, or one
// line saying what went wrong. Each row is filtered with SUB alone (libpng would try all
// five on every row: twice the encoder's instructions for a 1280 x 720 frame, files as
// small; docs/BENCHMARKS.md).
std::string write_png_file(const std::string& path, int width, int height, const std::uint8_t* rgb);

// Whether the bytes begin with PNG's signature.
bool is_png(const unsigned char* bytes, std::size_t size);

// A PNG's pixels at 8 bits a channel, rows top first, with the channels OpenImageIO gives
// (grey 1, grey and alpha 2, RGB 3, RGBA 4): a palette expanded to RGB, a tRNS chunk to an
// alpha channel, grey below 8 bits scaled to 8, 16 bits rounded to the nearest 8-bit value
// as it rounds them, no gamma applied. Unlike OpenImageIO, colour is not premultiplied by
// alpha: it is what the file stores (Texture.PngFilesReadAsTheCodecReadsThem). An image
// over 8192 x 8192 is refused unread, as the codec does. Returns an empty string, or one
// line saying what went wrong.
std::string decode_png(const unsigned char* bytes, std::size_t size,
                       codec::Pixels<std::uint8_t>& out);
std::string read_png_file(const std::string& path, codec::Pixels<std::uint8_t>& out);

}  // namespace rt
