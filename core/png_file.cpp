#include "core/png_file.h"

#include <png.h>
#include <zlib.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <vector>

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

// Where libpng reads from: the bytes in memory.
struct Source {
    const unsigned char* bytes;
    std::size_t size, at;
};

void read_from(png_structp png, png_bytep to, png_size_t n) {
    auto* source = static_cast<Source*>(png_get_io_ptr(png));
    if (n > source->size - source->at) png_error(png, "the file ends early");
    std::memcpy(to, source->bytes + source->at, n);
    source->at += n;
}

// The 8-bit value nearest v / 65535 of the range, as OpenImageIO rounds 16 bits to 8.
std::uint8_t to_8_bits(unsigned v) {
    return static_cast<std::uint8_t>((v * 255u + 32767u) / 65535u);
}

// The storage a decode fills, owned by its caller: libpng reports an error by longjmp to
// the setjmp in decode, whose frame therefore holds nothing with a destructor.
struct Decoded {
    codec::Pixels<std::uint8_t>& out;
    std::vector<png_byte> rows_16;  // 16-bit samples, big-endian, before rounding to 8
    std::vector<png_bytep> row_pointers;
};

bool decode(Source& source, Decoded& to, Message& message) {
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, message, on_error, on_warning);
    if (!png) {
        std::snprintf(message, sizeof(Message), "out of memory");
        return false;
    }
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_read_struct(&png, &info, nullptr);
        if (!*message) std::snprintf(message, sizeof(Message), "out of memory");
        return false;
    }
    png_set_read_fn(png, &source, read_from);
    png_read_info(png, info);
    const png_uint_32 width = png_get_image_width(png, info),
                      height = png_get_image_height(png, info);
    if (static_cast<long long>(width) * height > codec::kMaxTexels) {
        std::snprintf(message, sizeof(Message), "the image is %u x %u (at most 8192 x 8192)", width,
                      height);
        png_destroy_read_struct(&png, &info, nullptr);
        return false;
    }
    png_set_expand(png);  // a palette to RGB, grey to 8 bits, tRNS to alpha
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    const int channels = png_get_channels(png, info);
    const int depth = png_get_bit_depth(png, info);
    const png_size_t row_bytes = png_get_rowbytes(png, info);
    to.out.width = static_cast<int>(width), to.out.height = static_cast<int>(height);
    to.out.channels = channels;
    std::vector<png_byte>& samples = depth == 16 ? to.rows_16 : to.out.data;
    samples.resize(row_bytes * height);
    to.row_pointers.resize(height);
    for (png_uint_32 y = 0; y < height; ++y) to.row_pointers[y] = samples.data() + y * row_bytes;
    png_read_image(png, to.row_pointers.data());
    png_read_end(png, nullptr);
    png_destroy_read_struct(&png, &info, nullptr);
    return true;
}

}  // namespace

bool is_png(const unsigned char* bytes, std::size_t size) {
    return size >= 8 && png_sig_cmp(bytes, 0, 8) == 0;
}

std::string decode_png(const unsigned char* bytes, std::size_t size,
                       codec::Pixels<std::uint8_t>& out) {
    if (!is_png(bytes, size)) return "not a PNG file";
    Source source{bytes, size, 0};
    Decoded to{out, {}, {}};
    Message message = "";
    if (!decode(source, to, message)) return message;
    const std::vector<png_byte>& wide = to.rows_16;
    if (!wide.empty()) {
        out.data.resize(wide.size() / 2);
        for (std::size_t i = 0; i < out.data.size(); ++i)
            out.data[i] = to_8_bits(256u * wide[2 * i] + wide[2 * i + 1]);
    }
    return {};
}

std::string read_png_file(const std::string& path, codec::Pixels<std::uint8_t>& out) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return "cannot read the image \"" + path + "\": " + std::strerror(errno);
    const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                           std::istreambuf_iterator<char>());
    if (in.bad()) return "cannot read the image \"" + path + "\": " + std::strerror(errno);
    const std::string problem = decode_png(bytes.data(), bytes.size(), out);
    return problem.empty() ? problem : "cannot read the image \"" + path + "\": " + problem;
}

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
