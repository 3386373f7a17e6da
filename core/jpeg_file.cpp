#include "core/jpeg_file.h"

// jpeglib.h needs FILE and size_t declared before it.
#include <cstdio>

#include <jerror.h>
#include <jpeglib.h>
#include <csetjmp>

namespace rt {
namespace {

// libjpeg's error manager, extended with where to jump on an error and what it said.
struct ErrorJump {
    jpeg_error_mgr manager;
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
    bool ended_early;
};

ErrorJump& error_of(j_common_ptr info) { return *reinterpret_cast<ErrorJump*>(info->err); }

[[noreturn]] void on_error(j_common_ptr info) {
    ErrorJump& e = error_of(info);
    info->err->format_message(info, e.message);
    std::longjmp(e.jump, 1);
}

// Warnings are not printed; the one that means the data ran out is remembered.
void on_message(j_common_ptr info, int level) {
    if (level < 0 && info->err->msg_code == JWRN_JPEG_EOF) error_of(info).ended_early = true;
}

// libjpeg reports an error by longjmp to the setjmp below: nothing in this frame has a
// destructor, and `out` is resized before the decompression that may jump.
bool decode(const unsigned char* bytes, std::size_t size, codec::Pixels<std::uint8_t>& out,
            bool& handled, ErrorJump& error) {
    jpeg_decompress_struct info{};
    info.err = jpeg_std_error(&error.manager);
    error.manager.error_exit = on_error;
    error.manager.emit_message = on_message;
    if (setjmp(error.jump)) {
        jpeg_destroy_decompress(&info);
        return false;
    }
    jpeg_create_decompress(&info);
    jpeg_mem_src(&info, bytes, static_cast<unsigned long>(size));
    jpeg_read_header(&info, TRUE);
    if (info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK) {
        handled = false;
        jpeg_destroy_decompress(&info);
        return true;
    }
    if (static_cast<long long>(info.image_width) * info.image_height > codec::kMaxTexels) {
        std::snprintf(error.message, sizeof error.message,
                      "the image is %u x %u (at most 8192 x 8192)", info.image_width,
                      info.image_height);
        jpeg_destroy_decompress(&info);
        return false;
    }
    info.out_color_space = info.num_components == 1 ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_start_decompress(&info);
    const auto row = static_cast<std::size_t>(info.output_width) * info.output_components;
    out.width = static_cast<int>(info.output_width);
    out.height = static_cast<int>(info.output_height);
    out.channels = info.output_components;
    out.data.resize(row * info.output_height);
    while (info.output_scanline < info.output_height) {
        JSAMPROW at = out.data.data() + row * info.output_scanline;
        jpeg_read_scanlines(&info, &at, 1);
    }
    jpeg_finish_decompress(&info);
    jpeg_destroy_decompress(&info);
    if (error.ended_early) {
        std::snprintf(error.message, sizeof error.message, "the file ends early");
        return false;
    }
    return true;
}

}  // namespace

bool is_jpeg(const unsigned char* bytes, std::size_t size) {
    return size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF;
}

JpegRead decode_jpeg(const unsigned char* bytes, std::size_t size,
                     codec::Pixels<std::uint8_t>& out) {
    JpegRead result;
    if (!is_jpeg(bytes, size)) {
        result.problem = "not a JPEG file";
        return result;
    }
    ErrorJump error{};
    if (!decode(bytes, size, out, result.handled, error)) result.problem = error.message;
    return result;
}

}  // namespace rt
