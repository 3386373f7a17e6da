// Image files through OpenImageIO: orientation, sRGB encoding, EXR linear floats.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <thread>

#include "core/error.h"
#include "core/image.h"
#include "test_util.h"

namespace rt {
namespace {

Image gradient() {
    Image image(8, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x)
            image.at(x, y) = {static_cast<float>(x) / 7.0f, static_cast<float>(y) / 3.0f, 0.25f};
    image.at(0, 0) = {1.0f, 0.0f, 0.0f};  // bottom left is red
    return image;
}

TEST(Image, SrgbTransferFunction) {
    EXPECT_FLOAT_EQ(srgb_encode(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(srgb_encode(1.0f), 1.0f);
    EXPECT_NEAR(srgb_encode(0.5f), 0.7353569f, 1e-6f);
    EXPECT_NEAR(srgb_encode(0.002f), 0.002f * 12.92f, 1e-7f);  // the linear toe
    EXPECT_FLOAT_EQ(srgb_encode(7.0f), 1.0f);                  // clamped
    for (float x = 0.0f; x <= 1.0f; x += 0.05f) EXPECT_NEAR(srgb_decode(srgb_encode(x)), x, 1e-5f);
}

// srgb8, the table that writes PNGs, is lround(255 srgb_encode(c)) bit for bit: over a
// sample of all the floats of [0, 1] (where the formula must never fall, which the table
// relies on), a few thousand floats either side of each byte's boundary, and outside [0, 1].
TEST(Image, Srgb8IsTheFormulaBitForBit) {
    const auto formula = [](float c) {
        return static_cast<int>(std::lround(srgb_encode(c) * 255.0f));
    };
    int differing = 0, falling = 0, last = 0;
    for (std::uint32_t b = 0; b <= std::bit_cast<std::uint32_t>(1.0f); b += 97) {
        const float c = std::bit_cast<float>(b);
        const int f = formula(c);
        differing += srgb8(c) != f;
        falling += f < last;
        last = f;
    }
    for (int v = 1; v < 256; ++v) {
        const float boundary = srgb_decode((static_cast<float>(v) - 0.5f) / 255.0f);
        const auto at = static_cast<std::int64_t>(std::bit_cast<std::uint32_t>(boundary));
        for (std::int64_t b = std::max<std::int64_t>(0, at - 3000); b <= at + 3000; ++b) {
            const float c = std::bit_cast<float>(static_cast<std::uint32_t>(b));
            differing += srgb8(c) != formula(c);
        }
    }
    EXPECT_EQ(differing, 0);
    EXPECT_EQ(falling, 0);
    for (const float c : {-1.0f, -0.0f, 1e-45f, 1.0f, 1.0000001f, 7.0f, 3.0e38f,
                          std::numeric_limits<float>::infinity()})
        EXPECT_EQ(srgb8(c), formula(c)) << c;
    EXPECT_EQ(srgb8(-std::numeric_limits<float>::infinity()), 0);
    EXPECT_EQ(srgb8(std::numeric_limits<float>::quiet_NaN()), 0);
}

TEST(Image, PngIsSrgbWithTheBottomRowLast) {
    const auto dir = test::temp_dir("png");
    const Image image = gradient();
    write_image(image, dir / "g.png");
    const std::vector<std::uint8_t> bytes = to_srgb8(image);
    // The first bytes of the file's pixels are the top-left pixel, (0, 3) in memory.
    EXPECT_EQ(bytes[0], 0);
    EXPECT_EQ(bytes[1], 255);
    const Image back = read_image(dir / "g.png");
    ASSERT_EQ(back.width, 8);
    ASSERT_EQ(back.height, 4);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(srgb_encode(back.pixels[i][k]), srgb_encode(image.pixels[i][k]),
                        0.5f / 255.0f + 1e-6f);
    EXPECT_FLOAT_EQ(back.at(0, 0).x, 1.0f);
}

TEST(Image, ExrKeepsLinearValuesAboveOne) {
    const auto dir = test::temp_dir("exr");
    Image image = gradient();
    image.at(3, 2) = {4.0f, 0.001f, 100.0f};
    write_image(image, dir / "g.exr");
    const Image back = read_image(dir / "g.exr");
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(back.pixels[i][k], image.pixels[i][k], 1e-3f * (1.0f + image.pixels[i][k]));
}

// The threads this process runs now.
std::size_t threads_now() {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& task : std::filesystem::directory_iterator("/proc/self/task"))
        ++n;
    return n;
}

// The count once it holds still (three readings 10 ms apart alike, for at most 2 s): the
// codec's libraries start threads as they load, and some of those end soon after.
std::size_t settled_threads() {
    std::size_t last = threads_now();
    for (int alike = 0, k = 0; alike < 2 && k < 200; ++k) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        const std::size_t now = threads_now();
        alike = now == last ? alike + 1 : 0;
        last = now;
    }
    return last;
}

// An EXR frame is read and written on the caller's thread (core/image_codec_oiio.cpp):
// OpenEXR's own pool of threads would outlive the frame and end only while the process
// exits (where LeakSanitizer's check once crashed on such threads). The codec is opened
// first through a PNG (its libraries start threads of their own as they load), then the
// EXR must add none (some of the libraries' may end meanwhile: at most as many as
// before). Meaningful in a process of its own, as CTest runs each test: an earlier test's
// EXR would have started the pool already.
TEST(Image, ExrIsReadAndWrittenOnTheCallersThread) {
    const auto dir = test::temp_dir("exr_thread");
    const Image image = gradient();
    write_image(image, dir / "g.png");
    (void)read_image(dir / "g.png");  // through the codec module: it is open now
    const std::size_t before = settled_threads();
    write_image(image, dir / "g.exr");
    (void)read_image(dir / "g.exr");
    EXPECT_LE(threads_now(), before);
}

// PNG (libpng) and EXR (the image codec) are written by different code: the same image's
// rows must come back in the same places from both.
TEST(Image, ExrAndPngHoldTheSameRows) {
    const auto dir = test::temp_dir("rows");
    const Image image = gradient();
    write_image(image, dir / "g.png");
    write_image(image, dir / "g.exr");
    const Image png = read_image(dir / "g.png"), exr = read_image(dir / "g.exr");
    ASSERT_EQ(exr.width, png.width);
    ASSERT_EQ(exr.height, png.height);
    for (std::size_t i = 0; i < png.pixels.size(); ++i)
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(srgb_encode(exr.pixels[i][k]), srgb_encode(png.pixels[i][k]),
                        0.5f / 255.0f + 1e-3f)
                << i;
}

TEST(Image, UnwritablePathIsAnError) {
    EXPECT_THROW(write_image(gradient(), "/nonexistent-dir/x.png"), Error);
    EXPECT_THROW(write_image(gradient(), test::temp_dir("bmp") / "x.bmp"), Error);
}

// A disk that fills while the PNG is written (libpng's error, by longjmp out of the
// encoder) is an rt::Error naming the file, not a crash or a truncated file said written.
TEST(Image, AFullDiskIsAnError) {
    const auto path = test::temp_dir("full") / "x.png";
    std::filesystem::create_symlink("/dev/full", path);
    Image big(512, 512);
    for (std::size_t i = 0; i < big.pixels.size(); ++i)
        big.pixels[i] = vec3(static_cast<float>(i % 251) / 251.0f, 0.5f, 0.25f);
    try {
        write_image(big, path);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.file(), path.string());
        EXPECT_EQ(e.where(), "output");
        EXPECT_NE(e.detail().find("No space left on device"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace rt
