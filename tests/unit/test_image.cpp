// Image files through OpenImageIO: orientation, sRGB encoding, EXR linear floats.
#include <gtest/gtest.h>

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

TEST(Image, UnwritablePathIsAnError) {
    EXPECT_THROW(write_image(gradient(), "/nonexistent-dir/x.png"), Error);
    EXPECT_THROW(write_image(gradient(), test::temp_dir("bmp") / "x.bmp"), Error);
}

}  // namespace
}  // namespace rt
