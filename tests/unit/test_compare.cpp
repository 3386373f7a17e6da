// compare_images and difference_image: the judges of the item-buffer, GUI and raster
// agreement tests, checked directly against values worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "core/compare.h"
#include "core/item_buffer.h"

namespace rt {
namespace {

Image flat(int w, int h, vec3 c) {
    Image image(w, h);
    for (vec3& p : image.pixels) p = c;
    return image;
}

TEST(Compare, IdenticalImagesAreIdentical) {
    const Image a = flat(4, 3, vec3(0.2f, 0.5f, 0.8f));
    const ImageDiff d = compare_images(a, a);
    EXPECT_TRUE(d.identical());
    EXPECT_EQ(d.pixels_over, 0u);
    EXPECT_EQ(d.mean_abs_error, 0.0);
}

TEST(Compare, ErrorsAreMeasuredOnTheEncodedValues) {
    // Black against linear 0.5 in one channel of one pixel of four: the encoded value of
    // 0.5 is 0.7354; mean over 12 channels, RMS, PSNR and the share follow by hand.
    const Image a = flat(2, 2, vec3(0.0f));
    Image b = a;
    b.at(1, 0) = vec3(0.0f, 0.5f, 0.0f);
    const ImageDiff d = compare_images(a, b);
    const double e = 0.735357;
    EXPECT_NEAR(d.mean_abs_error, e / 12.0, 1e-5);
    EXPECT_NEAR(d.rms, std::sqrt(e * e / 12.0), 1e-5);
    EXPECT_NEAR(d.psnr_db, 20.0 * std::log10(1.0 / std::sqrt(e * e / 12.0)), 1e-3);
    EXPECT_NEAR(d.max_error, e, 1e-5);
    EXPECT_EQ(d.pixels_over, 1u);
    EXPECT_DOUBLE_EQ(d.share_over, 0.25);
    EXPECT_FALSE(d.identical());
}

TEST(Compare, ThresholdIsStrict) {
    // One 8-bit step of 2/255 in sRGB is not over a 2/255 threshold; 3/255 is.
    const float base = srgb_decode(100.0f / 255.0f);
    const Image a = flat(1, 1, vec3(base));
    EXPECT_EQ(compare_images(a, flat(1, 1, vec3(srgb_decode(101.5f / 255.0f)))).pixels_over, 0u);
    EXPECT_EQ(compare_images(a, flat(1, 1, vec3(srgb_decode(103.0f / 255.0f)))).pixels_over, 1u);
}

TEST(Compare, NonFinitePixelsDifferAndNoStatisticIsNaN) {
    const Image a = flat(10, 10, vec3(0.3f));
    Image b = a;
    b.at(3, 4) = vec3(std::numeric_limits<float>::quiet_NaN(), 0.3f, 0.3f);
    b.at(5, 5) = vec3(kInfinity);
    const ImageDiff d = compare_images(a, b);
    EXPECT_EQ(d.non_finite, 2u);
    EXPECT_EQ(d.pixels_over, 2u);
    EXPECT_TRUE(std::isfinite(d.mean_abs_error));
    EXPECT_TRUE(std::isfinite(d.rms));
    EXPECT_TRUE(std::isfinite(d.psnr_db));
    EXPECT_DOUBLE_EQ(d.max_error, 1.0);
}

TEST(Compare, SizesMustMatch) {
    EXPECT_THROW(compare_images(Image(2, 2), Image(2, 3)), std::invalid_argument);
    EXPECT_THROW(difference_image(Image(2, 2), Image(3, 2), 1.0f), std::invalid_argument);
}

TEST(Compare, DifferenceImageMapsErrorsOntoTheScale) {
    const Image a = flat(8, 8, vec3(0.0f));
    Image b = a;
    b.at(2, 2) = vec3(1.0f);  // error 1: the top of a scale of 1
    b.at(5, 5) = vec3(std::numeric_limits<float>::quiet_NaN());
    const Image d = difference_image(a, b, 1.0f);
    EXPECT_GT(d.width, a.width);  // the colour bar
    const auto near = [](vec3 p, vec3 q) { return glm::length(p - q) < 1e-4f; };
    EXPECT_TRUE(near(d.at(0, 0), heat_colour(0.0f)));
    EXPECT_TRUE(near(d.at(2, 2), heat_colour(1.0f)));
    EXPECT_TRUE(near(d.at(5, 5), heat_colour(1.0f)));
    EXPECT_FALSE(near(d.at(1, 1), heat_colour(1.0f)));
}

// interior() against its definition, pixel by pixel, on random ids of a few values (so
// that blocks of one id occur), edges and corners included: the four pixels beside it
// (inside the image) name its object; the diagonal ones do not count.
TEST(ItemBuffer, InteriorMeansTheNeighboursInsideTheImageShareTheId) {
    for (const auto& [w, h] :
         {std::pair{1, 1}, std::pair{2, 7}, std::pair{9, 6}, std::pair{33, 17}}) {
        ItemBuffer ib(w, h);
        std::uint32_t state = 12345u;
        for (std::uint32_t& id : ib.ids) {
            state = state * 1664525u + 1013904223u;
            id = (state >> 24) % 7 == 0 ? 2u : 1u;
        }
        int interior = 0;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                bool expected = true;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int nx = x + dx, ny = y + dy;
                        if (dx != 0 && dy != 0) continue;  // a diagonal neighbour
                        if (nx >= 0 && ny >= 0 && nx < w && ny < h)
                            expected &= ib.ids[ib.index(nx, ny)] == ib.ids[ib.index(x, y)];
                    }
                EXPECT_EQ(ib.interior(x, y), expected) << w << "x" << h << " at " << x << ", " << y;
                interior += expected;
            }
        }
        if (w * h > 50) {
            EXPECT_GT(interior, 0);  // both answers occur
            EXPECT_LT(interior, w * h);
        }
    }
}

TEST(Compare, ItemBufferImageColoursIdsAndLeavesEmptyBlack) {
    ItemBuffer ib;
    ib.width = 2;
    ib.height = 1;
    ib.ids = {ItemBuffer::kEmpty, 7};
    ib.prim = {0, 0};
    const Image image = item_buffer_image(ib);
    EXPECT_EQ(image.at(0, 0), vec3(0.0f));
    EXPECT_EQ(image.at(1, 0), item_colour(7));
    EXPECT_NE(item_colour(7), item_colour(8));
}

}  // namespace
}  // namespace rt
