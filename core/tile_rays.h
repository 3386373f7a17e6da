#pragma once
// A tile's camera rays (core/renderer.cpp's primary step): one Ray per pixel, and for the
// pixel centres the terms they are made of (per frame), from which a run of pixels gets
// its rays as SIMD lanes.

#include <algorithm>
#include <array>
#include <cstring>
#include <vector>

#include "core/camera.h"
#include "core/ray_lanes.h"
#include "core/renderer.h"
#include "core/tile_runner.h"

namespace rt::detail {

// The terms a frame's rays through the pixel centres are made of (Camera::across per
// column, Camera::upward per row), computed once a frame: every tile's rays add them
// (made per tile, they were a tenth of the item buffer's primary step: whitted, probe).
class CameraTerms {
  public:
    explicit CameraTerms(const Camera& camera) : camera_(camera) {
        columns_.resize(static_cast<std::size_t>(camera.cols));
        for (int x = 0; x < camera.cols; ++x)
            columns_[static_cast<std::size_t>(x)] = camera.across(static_cast<float>(x) + 0.5f);
        rows_.resize(static_cast<std::size_t>(camera.rows));
        for (int y = 0; y < camera.rows; ++y)
            rows_[static_cast<std::size_t>(y)] = camera.upward(static_cast<float>(y) + 0.5f);
        // By axis, padded past the last column with it, so that a run of kPacketWidth
        // columns from any column is real numbers in every lane.
        for (int a = 0; a < 3; ++a) {
            by_axis_[a].resize(columns_.size() + kPacketWidth);
            for (std::size_t k = 0; k < by_axis_[a].size(); ++k)
                by_axis_[a][k] = columns_[std::min(k, columns_.size() - 1)][a];
        }
        row_start_.resize(columns_.size() * 6);
        for (std::size_t k = 0; k < columns_.size(); ++k)
            for (int a = 0; a < 3; ++a) {
                row_start_[6 * k + a] = camera.eye[a];
                row_start_[6 * k + 3 + a] = columns_[k][a];
            }
    }

    const Camera& camera() const { return camera_; }
    const vec3& eye() const { return camera_.eye; }
    const vec3& column(int x) const { return columns_[static_cast<std::size_t>(x)]; }
    const vec3& row(int y) const { return rows_[static_cast<std::size_t>(y)]; }
    // kPacketWidth columns' terms along axis a from column x.
    const float* columns_along(int a, int x) const {
        return &by_axis_[a][static_cast<std::size_t>(x)];
    }
    // {eye, column} of columns x on, as floats (a Ray's six).
    const float* row_start(int x) const { return &row_start_[6 * static_cast<std::size_t>(x)]; }

  private:
    const Camera& camera_;
    std::vector<vec3> columns_, rows_;
    std::array<std::vector<float>, 3> by_axis_;
    std::vector<float> row_start_;  // {eye, column} of each column, as floats
};

// A tile's camera rays for sample s, row by row. Through the pixel centres (one sample a
// pixel) a ray is two terms added, one per column and one per row of the direction
// (CameraTerms): the same rays as Camera::ray without two divisions a pixel. They are not
// stored: each step makes the rays it reads where it reads them (a packet's eight, a
// run's lanes, the found pixels' for shading), so the item buffer's primary step, which
// tests its pixels through lanes, makes no Ray at all (writing a Ray a pixel was a fifth
// of that step: whitted, perf). Other samples (jittered, pixel_sample) are made and kept
// per pixel.
class TileRays {
  public:
    void make(const CameraTerms& terms, const Tile& t, int s, int spp) {
        t_ = t;
        terms_ = &terms;
        centres_ = spp <= 1;
        if (centres_) return;
        samples_.resize(static_cast<std::size_t>(t.x1 - t.x0) * (t.y1 - t.y0));
        std::size_t i = 0;
        for (int y = t.y0; y < t.y1; ++y)
            for (int x = t.x0; x < t.x1; ++x)
                samples_[i++] = pixel_sample(terms.camera(), x, y, s, spp);
    }

    // The index of pixel (x, y) in the tile, row by row.
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y - t_.y0) * static_cast<std::size_t>(t_.x1 - t_.x0) +
               static_cast<std::size_t>(x - t_.x0);
    }

    // The ray of pixel (x, y).
    Ray ray(int x, int y) const {
        if (!centres_) return samples_[index(x, y)];
        return Ray{terms_->eye(), terms_->column(x) + terms_->row(y)};
    }

    // The rays of the tile's pixels i .. i + n - 1 (row by row, running on into the next
    // row where a row ends) into out.
    void span(std::size_t i, std::size_t n, Ray* out) const {
        if (!centres_) {
            std::copy_n(&samples_[i], n, out);
            return;
        }
        const auto w = static_cast<std::size_t>(t_.x1 - t_.x0);
        std::size_t row = i / w, column = i % w;
        while (n > 0) {
            const std::size_t m = std::min(n, w - column);
            write_run(terms_->row(t_.y0 + static_cast<int>(row)), t_.x0 + static_cast<int>(column),
                      m, out);
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
        const vec3& row = terms_->row(y);
        const vec3& eye = terms_->eye();
        RayLanes<kPacketWidth> out;
        for (int a = 0; a < 3; ++a) {
            Float c;
            std::memcpy(&c, terms_->columns_along(a, x), sizeof c);
            out.origin[a] = splat<Float>(eye[a]);
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

    // The rays of image columns x .. x + n - 1 for a row's term `row`.
    void write_run(const vec3& row, int x, std::size_t n, Ray* out) const {
        // Eight floats, read and written where a Ray's floats are.
        using Chunk = float __attribute__((vector_size(32), aligned(4), may_alias));
        constexpr std::size_t kChunks = kBlock / 8;
        // {-0, -0, -0, row} four times over, as three chunks: shuffles of one vector (each
        // float written alone and read back as a vector waited on the store each time).
        const Chunk v{row.x, row.y, row.z, -0.0f, -0.0f, -0.0f, -0.0f, -0.0f};
        const Chunk add[kChunks] = {__builtin_shufflevector(v, v, 3, 3, 3, 0, 1, 2, 3, 3),
                                    __builtin_shufflevector(v, v, 3, 0, 1, 2, 3, 3, 3, 0),
                                    __builtin_shufflevector(v, v, 1, 2, 3, 3, 3, 0, 1, 2)};
        const auto* from = reinterpret_cast<const Chunk*>(terms_->row_start(x));
        auto* to = reinterpret_cast<Chunk*>(out);
        const std::size_t whole = n / 4;  // blocks of four Rays
        for (std::size_t b = 0; b < whole; ++b)
            for (std::size_t c = 0; c < kChunks; ++c)
                to[kChunks * b + c] = from[kChunks * b + c] + add[c];
        for (std::size_t k = 4 * whole; k < n; ++k)
            out[k] = Ray{terms_->eye(), terms_->column(x + static_cast<int>(k)) + row};
    }

    Tile t_{};
    const CameraTerms* terms_ = nullptr;
    bool centres_ = true;
    std::vector<Ray> samples_;  // jittered samples' rays, made per pixel
};

}  // namespace rt::detail
