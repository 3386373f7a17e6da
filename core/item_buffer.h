#pragma once
// What the raster side hands the tracer (Weghorst, Hooper & Greenberg 1984): for each
// pixel, which object covers it first and which triangle of that object. Plain data:
// the GL pass fills it, core reads it; core never sees GL.

#include <cstdint>
#include <cstring>
#include <vector>

#include "core/simd.h"

namespace rt {

struct ItemBuffer {
    static constexpr std::uint32_t kEmpty = 0;  // no object at this pixel

    int width = 0;
    int height = 0;
    std::vector<std::uint32_t> object;  // object index + 1, or kEmpty; bottom row first
    std::vector<std::uint32_t> prim;    // triangle index within the object (meshes; the
                                        // raster draws none where the scene has no mesh: 0)

    using Ids = std::uint32_t __attribute__((vector_size(4 * kPacketWidth)));
    static Ids load(const std::uint32_t* p) {
        Ids v;
        std::memcpy(&v, p, sizeof v);
        return v;
    }

    ItemBuffer() = default;
    ItemBuffer(int w, int h)
        : width(w),
          height(h),
          object(static_cast<std::size_t>(w) * h, kEmpty),
          prim(object.size(), 0) {}

    // As Image::resize: the storage kept, the ids left for the caller to overwrite.
    void resize(int w, int h) {
        width = w, height = h;
        object.resize(static_cast<std::size_t>(w) * h);
        prim.resize(object.size());
    }

    std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }

    // True when the four pixels beside (x, y), left, right, below and above (those inside
    // the image), name the same object as it: the pixel is not on a silhouette or where two
    // objects meet, so the raster answer can be trusted for the analytic shapes too. Why
    // the four and not the eight of the 3 x 3 block: the raster's outline of a shape lies
    // within a quarter of a pixel of the true one (a sphere's level of detail is chosen so,
    // up to a radius of about 3,300 pixels; a mesh is drawn as it is; docs/BENCHMARKS.md,
    // "sixteenth session"), so an object in front whose true outline
    // reached this pixel's centre would have its raster outline within a quarter pixel of
    // it, and an outline that covers a diagonal neighbour's centre but no side neighbour's
    // cannot come that close, unless the object is under a pixel or two across (which the
    // block of nine misses as well: it may cover no pixel centre at all; the renderer tests
    // such objects itself, core/small_objects.h). many_spheres: 27 % fewer pixels on edges,
    // the same pixels unlike a trace without the item buffer.
    bool interior(int x, int y) const {
        const std::uint32_t id = object[index(x, y)];
        if (x > 0 && y > 0 && x + 1 < width && y + 1 < height) {
            // Away from the image's edges: the four compared at once, no branch each.
            const std::uint32_t* at = &object[index(x, y)];
            return ((at[-1] ^ id) | (at[1] ^ id) | (at[-width] ^ id) | (at[width] ^ id)) == 0;
        }
        const int beside[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
        for (const auto& [dx, dy] : beside) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
            if (object[index(nx, ny)] != id) return false;
        }
        return true;
    }

    // Which of the n (<= 32) values from values[at] on equal `value`, as bits.
    static unsigned same_run(const std::vector<std::uint32_t>& values, std::size_t at, int n,
                             std::uint32_t value) {
        unsigned mask = 0;
        int k = 0;
        for (; k + kPacketWidth <= n; k += kPacketWidth) {
            const Ids v = load(&values[at + static_cast<std::size_t>(k)]);
            const Lanes<kPacketWidth>::Mask same = v == (Ids{} + value);
            mask |= bits(same) << k;
        }
        for (; k < n; ++k)
            mask |= static_cast<unsigned>(values[at + static_cast<std::size_t>(k)] == value) << k;
        return mask;
    }

    // interior() for the pixels x .. x + n - 1 of row y (n <= 32), as bits (pixel x
    // lowest). Away from the image's edges kPacketWidth pixels at a time: each of the four
    // neighbours' ids is one load of kPacketWidth, compared across the pixels at once.
    unsigned interior_run(int x, int y, int n) const {
        unsigned mask = 0;
        int k = 0;
        if (y > 0 && y + 1 < height && x > 0) {
            for (; k + kPacketWidth <= n && x + k + kPacketWidth < width; k += kPacketWidth) {
                const std::uint32_t* centre = &object[index(x + k, y)];
                const Ids id = load(centre);
                const auto w = static_cast<std::ptrdiff_t>(width);
                const Ids differ = (load(centre - 1) ^ id) | (load(centre + 1) ^ id) |
                                   (load(centre - w) ^ id) | (load(centre + w) ^ id);
                const Lanes<kPacketWidth>::Mask same = differ == Ids{};
                mask |= bits(same) << k;
            }
        }
        for (; k < n; ++k) mask |= static_cast<unsigned>(interior(x + k, y)) << k;
        return mask;
    }
};

}  // namespace rt
