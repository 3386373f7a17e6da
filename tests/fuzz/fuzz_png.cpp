// libFuzzer target: the PNG texture reader (core/png_file.cpp, libpng behind a longjmp)
// must turn any bytes into pixels of the size it says, or one line saying what is wrong.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "core/png_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    rt::codec::Pixels<std::uint8_t> px;
    const std::string problem = rt::decode_png(data, size, px);
    if (problem.empty()) {
        const auto expected = static_cast<std::size_t>(px.width) *
                              static_cast<std::size_t>(px.height) *
                              static_cast<std::size_t>(px.channels);
        if (px.channels < 1 || px.channels > 4 || px.data.size() != expected) std::abort();
    } else if (problem.find('\n') != std::string::npos) {
        std::abort();
    }
    return 0;
}
