#include "core/png_file.h"

#include <png.h>
#include <zlib.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace rt {
namespace {

using Message = char[256];

void on_error(png_structp png, png_const_charp what) {
    auto* message = static_cast<char*>(png_get_error_ptr(png));
    std::snprintf(message, sizeof(Message), "%s", what);
    png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {}

// libpng reports an error by longjmp to the setjmp below: nothing in this frame has a
// destructor to skip, and nothing set before setjmp changes after it.
bool encode(std::FILE* file, int width, int height, const std::uint8_t* rgb, Message& message) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, message, on_error, on_warning);
    if (!png) {
        std::snprintf(message, sizeof(Message), "out of memory");
        return false;
    }
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        if (!*message) std::snprintf(message, sizeof(Message), "out of memory");
        return false;
    }
    png_init_io(png, file);
    png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
                 PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
    // zlib's default strategy, as OpenImageIO's writer chose (libpng's own for filtered
    // rows is Z_FILTERED, 1.5 % larger here): the image data is byte for byte what rtview
    // wrote through OpenImageIO; only its empty oFFs chunk is gone.
    png_set_compression_strategy(png, Z_DEFAULT_STRATEGY);
    png_write_info(png, info);
    const std::size_t row = static_cast<std::size_t>(width) * 3;
    for (int y = 0; y < height; ++y) png_write_row(png, rgb + static_cast<std::size_t>(y) * row);
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

}  // namespace

std::string write_png_file(const std::string& path, int width, int height,
                           const std::uint8_t* rgb) {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) return std::strerror(errno);
    Message message = "";
    errno = 0;
    const bool encoded = encode(file, width, height, rgb, message);
    const int write_error = std::ferror(file) ? errno : 0;  // libpng says only "Write Error"
    const bool closed = std::fclose(file) == 0;
    if (write_error) return std::string("cannot write the file: ") + std::strerror(write_error);
    if (!encoded) return message;
    if (!closed) return std::string("cannot write the file: ") + std::strerror(errno);
    return {};
}

}  // namespace rt
