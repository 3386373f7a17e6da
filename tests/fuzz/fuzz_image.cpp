// libFuzzer target: the PNG and JPEG texture readers (core/png_file.cpp, core/jpeg_file.cpp:
// libpng and libjpeg behind their longjmps) must turn any bytes into pixels of the size
// they say, or one line saying what is wrong. Bytes that begin as neither go to both.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/jpeg_file.h"
#include "core/png_file.h"

namespace {

void check(const std::string& problem, const rt::codec::Pixels<std::uint8_t>& px) {
    if (problem.empty()) {
        const auto expected = static_cast<std::size_t>(px.width) *
                              static_cast<std::size_t>(px.height) *
                              static_cast<std::size_t>(px.channels);
        if (px.channels < 1 || px.channels > 4 || px.data.size() != expected) std::abort();
    } else if (problem.find('\n') != std::string::npos) {
        std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const bool jpeg = rt::is_jpeg(data, size), png = rt::is_png(data, size);
    if (png || !jpeg) {
        rt::codec::Pixels<std::uint8_t> px;
        check(rt::decode_png(data, size, px), px);
    }
    if (jpeg || !png) {
        rt::codec::Pixels<std::uint8_t> px;
        const rt::JpegRead read = rt::decode_jpeg(data, size, px);
        if (read.handled) check(read.problem, px);
    }
    return 0;
}
