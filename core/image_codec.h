#pragma once
// The boundary between rtview and OpenImageIO. The codec is a module of rtview's own
// (core/image_codec_oiio.cpp, built as lib/rtview/librtview_image_oiio.so) that the
// programs open with dlopen the first time they read or write an image file
// (core/image_io.cpp), not a library they link: Debian's OpenImageIO brings 261 shared
// libraries (OpenCV, FFmpeg, GStreamer, GDAL...) whose loading took 0.26-0.38 s of every
// process start here, before main (docs/BENCHMARKS.md). `--help`, an error message, the
// viewer's window and every unit test that touches no image file now start without it,
// and so do a render to PNG and a scene whose textures are PNG: PNG files are written and
// read by libpng directly (core/png_file.h).
//
// Both sides are built from this tree by the same compiler, so the table may pass C++
// types; nothing throws across it: each call returns an empty string, or one line saying
// what went wrong, which the loader turns into rt::Error with the file and place.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rt::codec {

// Bumped whenever the table below changes shape: a module from another build refuses.
inline constexpr int kVersion = 2;

// The most texels a texture may have, 8192 x 8192: a larger one is refused unread, by the
// codec and by rtview's own PNG and JPEG readers alike.
inline constexpr long long kMaxTexels = 1ll << 26;

// Pixels as the file holds them: rows top first, `channels` interleaved.
template <typename T>
struct Pixels {
    int width = 0, height = 0, channels = 0;
    std::vector<T> data;
};

struct ImageCodec {
    int version = kVersion;
    // Linear float RGB, stored as half floats: the file's top row at `top_row`, each next
    // row `row_step` floats on (negative for an image kept bottom row first, as rt::Image).
    std::string (*write_exr)(const std::string& path, int width, int height, const float* top_row,
                             std::ptrdiff_t row_step) = nullptr;
    // Any format OpenImageIO reads, as floats; `encoded` when the file held 8-bit values.
    std::string (*read_floats)(const std::string& path, Pixels<float>& out,
                               bool& encoded) = nullptr;
    // 8 bits a channel (textures), from a file or from bytes in memory of the format
    // `extension` names (".png"); an image over 8192 x 8192 texels is refused unread.
    std::string (*read_bytes)(const std::string& path, Pixels<std::uint8_t>& out) = nullptr;
    std::string (*decode_bytes)(const unsigned char* bytes, std::size_t size,
                                const std::string& extension, Pixels<std::uint8_t>& out) = nullptr;
};

// The module's one exported symbol.
inline constexpr const char* kEntryPoint = "rtview_image_codec";
inline constexpr const char* kModuleName = "librtview_image_oiio.so";
using EntryPoint = const ImageCodec* (*)();

// The module, opened the first time it is asked for (core/image_io.cpp); where it cannot
// be, rt::Error at `file` and `where` saying why.
const ImageCodec& module(const std::string& file, const std::string& where);

}  // namespace rt::codec
