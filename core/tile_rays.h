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

// A tile's camera rays for sample s, row by row. Through the pixel centres (one sample a
// pixel) a ray is two terms added, one per column and one per row of the direction
// (Camera::across, Camera::upward), each computed once: the same rays as Camera::ray
// without two divisions a pixel. They are not stored: each step makes the rays it reads
// where it reads them (a packet's eight, a run's lanes, the found pixels' for shading),
// so the item buffer's primary step, which tests its pixels through lanes, makes no Ray
// at all (writing a Ray a pixel was a fifth of that step: whitted, perf). Other samples
// (jittered, pixel_sample) are made and kept per pixel.
class TileRays {
  public:
    // Empty: make() sizes its arrays, allocating only for a tile larger than any before.
    TileRays() = default;
    // Its arrays sized for tile t up front: make() then allocates nothing, so the time of
    // the primary step is the rays' own.
    explicit TileRays(const Tile& t)
        : columns_(static_cast<std::size_t>(t.x1 - t.x0)),
          rows_(static_cast<std::size_t>(t.y1 - t.y0)),
          row_start_(6 * columns_.size()) {
        for (auto& axis : by_axis_) axis.resize(padded(columns_.size()));
    }

    void make(const Camera& camera, const Tile& t, int s, int spp) {
        t_ = t;
        eye_ = camera.eye;
        const int w = t.x1 - t.x0;
        centres_ = spp <= 1;
        if (!centres_) {
            samples_.resize(static_cast<std::size_t>(w) * (t.y1 - t.y0));
            std::size_t i = 0;
            for (int y = t.y0; y < t.y1; ++y)
                for (int x = t.x0; x < t.x1; ++x)
                    samples_[i++] = pixel_sample(camera, x, y, s, spp);
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
        for (int y = t.y0; y < t.y1; ++y)
            rows_[y - t.y0] = camera.upward(static_cast<float>(y) + 0.5f);
        set_row_start(columns_);
    }

    // The index of pixel (x, y) in the tile, row by row.
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y - t_.y0) * static_cast<std::size_t>(t_.x1 - t_.x0) +
               static_cast<std::size_t>(x - t_.x0);
    }

    // The ray of pixel (x, y).
    Ray ray(int x, int y) const {
        if (!centres_) return samples_[index(x, y)];
        return Ray{eye_, columns_[static_cast<std::size_t>(x - t_.x0)] +
                             rows_[static_cast<std::size_t>(y - t_.y0)]};
    }

    // The rays of the tile's pixels i .. i + n - 1 (row by row, running on into the next
    // row where a row ends) into out.
    void span(std::size_t i, std::size_t n, Ray* out) const {
        if (!centres_) {
            std::copy_n(&samples_[i], n, out);
            return;
        }
        const std::size_t w = columns_.size();
        std::size_t row = i / w, column = i % w;
        while (n > 0) {
            const std::size_t m = std::min(n, w - column);
            write_run(rows_[row], column, m, out);
            out += m;
            n -= m;
            column = 0;
            ++row;
        }
    }

    // The rays of pixels x .. x + n - 1 of row y as lanes (n <= kPacketWidth).
    RayLanes<kPacketWidth> lanes(int x, int y, int n) const {
        using Float = Lanes<kPacketWidth>::Float;
        if (!centres_)
            return RayLanes<kPacketWidth>::gather(&samples_[index(x, y)], (1u << n) - 1u);
        const std::size_t column = static_cast<std::size_t>(x - t_.x0);
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
    // run of a row is then whole vectors of additions, kBlock floats (four Rays) at a time,
    // not six scalar loads, additions and stores a pixel (a third as many samples, perf).
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
    // The rays of columns column .. column + n - 1 for a row's term `row`.
    void write_run(const vec3& row, std::size_t column, std::size_t n, Ray* out) const {
        // Eight floats, read and written where a Ray's floats are.
        using Chunk = float __attribute__((vector_size(32), aligned(4), may_alias));
        constexpr std::size_t kChunks = kBlock / 8;
        // {-0, -0, -0, row} four times over, as three chunks: shuffles of one vector (each
        // float written alone and read back as a vector waited on the store each time).
        const Chunk v{row.x, row.y, row.z, -0.0f, -0.0f, -0.0f, -0.0f, -0.0f};
        const Chunk add[kChunks] = {__builtin_shufflevector(v, v, 3, 3, 3, 0, 1, 2, 3, 3),
                                    __builtin_shufflevector(v, v, 3, 0, 1, 2, 3, 3, 3, 0),
                                    __builtin_shufflevector(v, v, 1, 2, 3, 3, 3, 0, 1, 2)};
        const auto* from = reinterpret_cast<const Chunk*>(&row_start_[6 * column]);
        auto* to = reinterpret_cast<Chunk*>(out);
        const std::size_t whole = n / 4;  // blocks of four Rays
        for (std::size_t b = 0; b < whole; ++b)
            for (std::size_t c = 0; c < kChunks; ++c)
                to[kChunks * b + c] = from[kChunks * b + c] + add[c];
        for (std::size_t k = 4 * whole; k < n; ++k) out[k] = Ray{eye_, columns_[column + k] + row};
    }

    static std::size_t padded(std::size_t n) {
        return (n + kPacketWidth - 1) / kPacketWidth * kPacketWidth;
    }

    Tile t_{};
    vec3 eye_{0.0f};
    bool centres_ = true;
    std::vector<Ray> samples_;  // jittered samples' rays, made per pixel
    std::vector<vec3> columns_, rows_;
    std::vector<float> row_start_;  // {eye, column} of each column, as floats
    std::array<std::vector<float>, 3> by_axis_;
};

}  // namespace rt::detail
