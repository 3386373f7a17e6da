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

    // True when every pixel of the 3x3 block around (x, y) (inside the image) names the
    // same object: the pixel is not on a silhouette or where two objects meet, so the
    // raster answer can be trusted for the analytic shapes too.
    bool interior(int x, int y) const {
        const std::uint32_t id = object[index(x, y)];
        if (x > 0 && y > 0 && x + 1 < width && y + 1 < height) {
            // Away from the image's edges: the nine compared at once, no branch each.
            const std::uint32_t* below = &object[index(x - 1, y - 1)];
            const std::uint32_t* row = below + width;
            const std::uint32_t* above = row + width;
            std::uint32_t differ = 0;
            for (int dx = 0; dx < 3; ++dx)
                differ |= (below[dx] ^ id) | (row[dx] ^ id) | (above[dx] ^ id);
            return differ == 0;
        }
        for (int dy = -1; dy <= 1; ++dy) {
            for (int dx = -1; dx <= 1; ++dx) {
                const int nx = x + dx, ny = y + dy;
                if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
                if (object[index(nx, ny)] != id) return false;
            }
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
    // lowest). Away from the image's edges kPacketWidth pixels at a time: each of the nine
    // neighbours' ids is one load of kPacketWidth, compared across the pixels at once.
    unsigned interior_run(int x, int y, int n) const {
        unsigned mask = 0;
        int k = 0;
        if (y > 0 && y + 1 < height && x > 0) {
            for (; k + kPacketWidth <= n && x + k + kPacketWidth < width; k += kPacketWidth) {
                const std::uint32_t* centre = &object[index(x + k, y)];
                const Ids id = load(centre);
                Ids differ{};
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx)
                        differ |= load(centre + dy * static_cast<std::ptrdiff_t>(width) + dx) ^ id;
                const Lanes<kPacketWidth>::Mask same = differ == Ids{};
                mask |= bits(same) << k;
            }
        }
        for (; k < n; ++k) mask |= static_cast<unsigned>(interior(x + k, y)) << k;
        return mask;
    }
};

}  // namespace rt
