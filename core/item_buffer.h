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
    // Per pixel, bottom row first: the object index + 1 (kEmpty for none), shifted left by
    // prim_bits, the triangle within the object in the bits below where they are packed
    // (the raster's one target, read back as it is: unpacking 1280 x 720 ids into two
    // arrays took 0.6 ms, a copy 0.24 ms). object_id() and triangle() read them.
    std::vector<std::uint32_t> ids;
    // The triangles where they are not packed in `ids` (a mesh too large to share the 32
    // bits); empty where they are, or where the scene has no mesh (every triangle 0).
    std::vector<std::uint32_t> prim;
    int prim_bits = 0;

    using Ids = std::uint32_t __attribute__((vector_size(4 * kPacketWidth)));
    static Ids load(const std::uint32_t* p) {
        Ids v;
        std::memcpy(&v, p, sizeof v);
        return v;
    }

    ItemBuffer() = default;
    // Ids and triangles apart, all empty, for the caller to fill.
    ItemBuffer(int w, int h)
        : width(w), height(h), ids(static_cast<std::size_t>(w) * h, kEmpty), prim(ids.size(), 0) {}

    // As Image::resize: the storage kept, the ids left for the caller to overwrite, laid
    // out as `bits` says (the triangles apart when `separate`).
    void resize(int w, int h, int bits, bool separate) {
        width = w, height = h, prim_bits = bits;
        ids.resize(static_cast<std::size_t>(w) * h);
        prim.resize(separate ? ids.size() : 0);
    }

    std::uint32_t object_id(std::size_t i) const { return ids[i] >> prim_bits; }
    std::uint32_t triangle(std::size_t i) const {
        return prim.empty() ? ids[i] & prim_mask() : prim[i];
    }
    std::uint32_t prim_mask() const { return (std::uint32_t{1} << prim_bits) - 1u; }
    // The object ids of the kPacketWidth pixels from i.
    Ids object_ids(std::size_t i) const { return load(&ids[i]) >> prim_bits; }
    // The triangles of the n (<= kPacketWidth) pixels from i, into out.
    void triangles(std::size_t i, int n, std::uint32_t* out) const {
        if (n == kPacketWidth) {
            const Ids t = prim.empty() ? load(&ids[i]) & prim_mask() : load(&prim[i]);
            std::memcpy(out, &t, sizeof t);
            return;
        }
        for (int k = 0; k < n; ++k) out[k] = triangle(i + static_cast<std::size_t>(k));
    }
    // The same pixels and objects, however the ids are laid out.
    bool same_objects(const ItemBuffer& o) const {
        if (width != o.width || height != o.height) return false;
        for (std::size_t i = 0; i < ids.size(); ++i)
            if (object_id(i) != o.object_id(i) || triangle(i) != o.triangle(i)) return false;
        return true;
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
        const std::uint32_t id = ids[index(x, y)];
        if (x > 0 && y > 0 && x + 1 < width && y + 1 < height) {
            // Away from the image's edges: the four compared at once, no branch each (the
            // triangles' bits shifted out).
            const std::uint32_t* at = &ids[index(x, y)];
            return ((at[-1] ^ id) | (at[1] ^ id) | (at[-width] ^ id) | (at[width] ^ id)) >>
                       prim_bits ==
                   0;
        }
        const int beside[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
        for (const auto& [dx, dy] : beside) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
            if ((ids[index(nx, ny)] ^ id) >> prim_bits != 0) return false;
        }
        return true;
    }

    // Which of the n (<= 32) pixels from ids[at] on name object `id`, as bits.
    unsigned same_object_run(std::size_t at, int n, std::uint32_t id) const {
        unsigned mask = 0;
        int k = 0;
        for (; k + kPacketWidth <= n; k += kPacketWidth) {
            const Lanes<kPacketWidth>::Mask same =
                object_ids(at + static_cast<std::size_t>(k)) == (Ids{} + id);
            mask |= bits(same) << k;
        }
        for (; k < n; ++k)
            mask |= static_cast<unsigned>(object_id(at + static_cast<std::size_t>(k)) == id) << k;
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
                const std::uint32_t* centre = &ids[index(x + k, y)];
                const Ids id = load(centre);
                const auto w = static_cast<std::ptrdiff_t>(width);
                const Ids differ = ((load(centre - 1) ^ id) | (load(centre + 1) ^ id) |
                                    (load(centre - w) ^ id) | (load(centre + w) ^ id)) >>
                                   prim_bits;
                const Lanes<kPacketWidth>::Mask same = differ == Ids{};
                mask |= bits(same) << k;
            }
        }
        for (; k < n; ++k) mask |= static_cast<unsigned>(interior(x + k, y)) << k;
        return mask;
    }
};

}  // namespace rt
