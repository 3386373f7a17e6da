#pragma once
// JPEG textures read by libjpeg itself, not through the image codec module: a scene whose
// textures are JPEG (most glTF models') then never loads OpenImageIO's 261 libraries
// (core/image_codec.h), as one whose textures are PNG does not (core/png_file.h).

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/image_codec.h"

namespace rt {

// Whether the bytes begin as a JPEG file does (its start-of-image marker).
bool is_jpeg(const unsigned char* bytes, std::size_t size);

struct JpegRead {
    bool handled = true;  // false: a CMYK or YCCK file, left to the codec, which converts it
    std::string problem;  // empty, or one line saying what went wrong
};

// A JPEG's pixels at 8 bits a channel, rows top first: grey 1 channel, colour 3 (RGB),
// decoded as OpenImageIO decodes them (libjpeg's defaults: the accurate integer inverse
// DCT, fancy upsampling; Texture.JpegFilesReadAsTheCodecReadsThem), except that a file
// that ends before its last row is an error, where OpenImageIO filled the missing rows
// with grey and said nothing. An image over 8192 x 8192 is refused unread.
JpegRead decode_jpeg(const unsigned char* bytes, std::size_t size,
                     codec::Pixels<std::uint8_t>& out);

}  // namespace rt
