#pragma once
// A tile's camera rays (core/renderer.cpp's primary step): one Ray per pixel, and for the
// pixel centres the terms they are made of, from which a run of pixels gets its rays as
// SIMD lanes.

#include <algorithm>
#include <array>
#include <cstring>
#include <vector>

#include "core/camera.h"
#include "core/ray_lanes.h"
#include "core/renderer.h"
#include "core/tile_runner.h"

namespace rt::detail {

// A tile's camera rays for sample s, row by row: one Ray per pixel (the shading reads
// them), and for one sample per pixel (the pixel centres) each column's and each row's
// term of the direction, computed once (Camera::across, Camera::upward): the same rays as
// Camera::ray without two divisions a pixel, and a row's run of pixels as lanes
// (RayLanes) from the terms, not read back from its Rays one by one.
class TileRays {
  public:
    std::vector<Ray> rays;

    // Its arrays sized for tile t up front: make() then allocates nothing, so the time of
    // the primary step is the rays' own.
    explicit TileRays(const Tile& t)
        : rays(static_cast<std::size_t>(t.x1 - t.x0) * (t.y1 - t.y0)),
          columns_(static_cast<std::size_t>(t.x1 - t.x0)),
          rows_(static_cast<std::size_t>(t.y1 - t.y0)),
          row_start_(6 * columns_.size()) {
        for (auto& axis : by_axis_) axis.resize(padded(columns_.size()));
    }

    void make(const Camera& camera, const Tile& t, int s, int spp) {
        t_ = t;
        eye_ = camera.eye;
        const int w = t.x1 - t.x0;
        rays.resize(static_cast<std::size_t>(w) * (t.y1 - t.y0));
        centres_ = spp <= 1;
        std::size_t i = 0;
        if (!centres_) {
            for (int y = t.y0; y < t.y1; ++y)
                for (int x = t.x0; x < t.x1; ++x) rays[i++] = pixel_sample(camera, x, y, s, spp);
            return;
        }
        columns_.resize(static_cast<std::size_t>(w));
        for (int x = t.x0; x < t.x1; ++x)
            columns_[x - t.x0] = camera.across(static_cast<float>(x) + 0.5f);
        // By axis, padded to whole runs with the last column (real numbers in every lane).
        for (int a = 0; a < 3; ++a) {
            by_axis_[a].resize(padded(columns_.size()));
            for (std::size_t k = 0; k < by_axis_[a].size(); ++k)
                by_axis_[a][k] = columns_[std::min(k, columns_.size() - 1)][a];
        }
        rows_.resize(static_cast<std::size_t>(t.y1 - t.y0));
        set_row_start(columns_);
        for (int y = t.y0; y < t.y1; ++y) {
            const vec3 row = rows_[y - t.y0] = camera.upward(static_cast<float>(y) + 0.5f);
            write_row(row, &rays[i]);
            i += columns_.size();
        }
    }

    // The rays of pixels x .. x + n - 1 of row y as lanes (n <= kPacketWidth).
    RayLanes<kPacketWidth> lanes(int x, int y, int n) const {
        using Float = Lanes<kPacketWidth>::Float;
        const std::size_t column = static_cast<std::size_t>(x - t_.x0);
        if (!centres_) {
            const std::size_t i = static_cast<std::size_t>(y - t_.y0) * (t_.x1 - t_.x0) + column;
            return RayLanes<kPacketWidth>::gather(&rays[i], (1u << n) - 1u);
        }
        const vec3& row = rows_[static_cast<std::size_t>(y - t_.y0)];
        RayLanes<kPacketWidth> out;
        for (int a = 0; a < 3; ++a) {
            Float c;
            std::memcpy(&c, &by_axis_[a][column], sizeof c);
            out.origin[a] = splat<Float>(eye_[a]);
            out.dir[a] = c + row[a];  // column + row, as the Ray's
        }
        return out;
    }

  private:
    // A row's Rays are {eye, column + row}: the row's floats are the floats of {eye, column}
    // plus {-0, -0, -0, row} over and over (x + -0 is x, for -0 too). Kept as floats, a
    // row is then whole vectors of additions, kBlock floats (four Rays) at a time, not six
    // scalar loads, additions and stores a pixel: the item buffer's primary step spent a
    // quarter of its time making rays so (whitted, perf).
    static constexpr std::size_t kBlock = 24;  // four Rays of six floats, three AVX vectors
    static_assert(sizeof(Ray) == 6 * sizeof(float), "a Ray is its six floats");

    void set_row_start(const std::vector<vec3>& columns) {
        row_start_.resize(columns.size() * 6);
        for (std::size_t k = 0; k < columns.size(); ++k)
            for (int a = 0; a < 3; ++a) {
                row_start_[6 * k + a] = eye_[a];
                row_start_[6 * k + 3 + a] = columns[k][a];
            }
    }
    void write_row(const vec3& row, Ray* out) const {
        // Eight floats, read and written where a Ray's floats are.
        using Chunk = float __attribute__((vector_size(32), aligned(4), may_alias));
        constexpr std::size_t kChunks = kBlock / 8;
        // {-0, -0, -0, row} four times over, as three chunks: shuffles of one vector (each
        // float written alone and read back as a vector waited on the store each time).
        const Chunk v{row.x, row.y, row.z, -0.0f, -0.0f, -0.0f, -0.0f, -0.0f};
        const Chunk add[kChunks] = {__builtin_shufflevector(v, v, 3, 3, 3, 0, 1, 2, 3, 3),
                                    __builtin_shufflevector(v, v, 3, 0, 1, 2, 3, 3, 3, 0),
                                    __builtin_shufflevector(v, v, 1, 2, 3, 3, 3, 0, 1, 2)};
        const auto* from = reinterpret_cast<const Chunk*>(row_start_.data());
        auto* to = reinterpret_cast<Chunk*>(out);
        const std::size_t whole = columns_.size() / 4;  // blocks of four Rays
        for (std::size_t b = 0; b < whole; ++b)
            for (std::size_t c = 0; c < kChunks; ++c)
                to[kChunks * b + c] = from[kChunks * b + c] + add[c];
        for (std::size_t k = 4 * whole; k < columns_.size(); ++k)
            out[k] = Ray{eye_, columns_[k] + row};
    }

    static std::size_t padded(std::size_t n) {
        return (n + kPacketWidth - 1) / kPacketWidth * kPacketWidth;
    }

    Tile t_{};
    vec3 eye_{0.0f};
    bool centres_ = true;
    std::vector<vec3> columns_, rows_;
    std::vector<float> row_start_;  // {eye, column} of each column, as floats
    std::array<std::vector<float>, 3> by_axis_;
};

}  // namespace rt::detail
