#include "core/explain.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/common.hpp>

#include "core/bitmap_font.h"
#include "core/tile_runner.h"

namespace rt {
namespace {

float largest(const vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

constexpr float kNoneThreshold = 2.0f / 255.0f;  // compare_images' default threshold

}  // namespace

const vec3& ExplainTerms::operator[](Cause c) const {
    switch (c) {
        case Cause::kGeometry:
            return geometry;
        case Cause::kShading:
            return shading;
        case Cause::kShadow:
            return shadow;
        case Cause::kReflection:
            return reflection;
        case Cause::kRefraction:
            return refraction;
        case Cause::kNone:
            break;
    }
    throw std::invalid_argument("ExplainTerms: none is not a term");
}

ExplainTerms explain_terms(const PrimaryParts& traced, const vec3& raster, std::uint32_t raster_id,
                           const RasterPixelTricks& tricks) {
    ExplainTerms t;
    const std::uint32_t traced_id =
        traced.object == PrimaryParts::kNoObject ? ItemBuffer::kEmpty : traced.object + 1;
    const vec3 colour = traced.colour();
    if (!finite(colour)) {
        t.shading = -raster;  // the renderer writes such a pixel black
    } else if (traced_id != raster_id) {
        t.geometry = colour - raster;
    } else {
        // The raster's local part: what is left of it without its tricks.
        const vec3 local = raster - tricks.shadow - tricks.reflection - tricks.refraction;
        t.shading = traced.unblocked - local;
        t.shadow = (traced.local - traced.unblocked) - tricks.shadow;
        t.reflection = traced.reflection - tricks.reflection;
        t.refraction = traced.refraction - tricks.refraction;
    }
    return t;
}

Cause cause_of(const ExplainTerms& terms, float displayed_difference) {
    if (!(displayed_difference > kNoneThreshold)) return Cause::kNone;
    Cause best = Cause::kNone;
    float best_size = -1.0f;
    for (const Named<Cause>& n : kCauseNames) {
        if (n.value == Cause::kNone) continue;
        const float size = largest(terms[n.value]);
        if (size > best_size) best = n.value, best_size = size;
    }
    return best;
}

ExplainMap explain(const Scene& scene, const Camera& camera, const RenderOptions& options,
                   const Image& raster, const ItemBuffer& raster_ids, std::stop_token stop,
                   const RasterTricks* tricks) {
    const int width = camera.cols, height = camera.rows;
    if (raster.width != width || raster.height != height || raster_ids.width != width ||
        raster_ids.height != height)
        throw std::invalid_argument("explain: the raster image's or item buffer's size differs");
    const auto fits = [&](const Image& im) {
        return im.pixels.empty() || (im.width == width && im.height == height);
    };
    if (tricks && !(fits(tricks->shadow) && fits(tricks->reflection) && fits(tricks->refraction)))
        throw std::invalid_argument("explain: a raster trick's image size differs");
    const auto at = [](const Image& im, std::size_t i) {
        return im.pixels.empty() ? vec3(0.0f) : im.pixels[i];
    };
    ExplainMap map;
    map.width = width;
    map.height = height;
    const std::size_t n = static_cast<std::size_t>(width) * height;
    map.terms.resize(n);
    map.cause.resize(n, Cause::kNone);
    map.difference.resize(n, 0.0f);
    map.error.resize(n, 0.0f);
    map.traced = Image(width, height);

    const Tracer tracer(scene, options.trace);
    const int tile_size = std::max(1, options.tile_size);
    const ProgressFn no_progress;  // the runner keeps a reference
    detail::TileRunner runner(width, height, tile_size, resolve_thread_count(options.threads),
                              no_progress, detail::tile_count(width, height, tile_size));
    const bool complete = runner.run(stop, map.rays, [&](const detail::Tile& t, RayCounts& local) {
        const Tracer mine = tracer;  // per worker, as in render()
        for (int y = t.y0; y < t.y1; ++y) {
            for (int x = t.x0; x < t.x1; ++x) {
                const std::size_t i = map.index(x, y);
                const PrimaryParts parts = mine.trace_parts(camera.ray(x, y), local);
                const vec3 colour = parts.colour();
                map.traced.pixels[i] = finite(colour) ? colour : vec3(0.0f);
                RasterPixelTricks added;
                if (tricks)
                    added = {at(tricks->shadow, i), at(tricks->reflection, i),
                             at(tricks->refraction, i)};
                map.terms[i] =
                    explain_terms(parts, raster.pixels[i], raster_ids.object_id(i), added);
                const vec3 shown = finite(raster.pixels[i])
                                       ? glm::abs(srgb_encode(map.traced.pixels[i]) -
                                                  srgb_encode(raster.pixels[i]))
                                       : vec3(1.0f);
                map.difference[i] = largest(shown);
                map.error[i] = shown.x + shown.y + shown.z;
                map.cause[i] = cause_of(map.terms[i], map.difference[i]);
            }
        }
    });
    map.cancelled = !complete;
    return map;
}

std::array<CauseShare, kCauseCount> cause_shares(const ExplainMap& map) {
    std::array<CauseShare, kCauseCount> shares{};
    const auto slot = [](Cause c) {
        for (std::size_t k = 0; k < kCauseCount; ++k)
            if (kCauseNames[k].value == c) return k;
        return kCauseCount - 1;
    };
    double total_error = 0.0;
    for (std::size_t i = 0; i < map.cause.size(); ++i) {
        CauseShare& s = shares[slot(map.cause[i])];
        s.pixels += 1.0;
        s.error += map.error[i];
        total_error += map.error[i];
    }
    const double pixels = std::max<double>(1.0, static_cast<double>(map.cause.size()));
    for (CauseShare& s : shares) {
        s.pixels /= pixels;
        s.error = total_error > 0.0 ? s.error / total_error : 0.0;
    }
    if (total_error == 0.0) shares[slot(Cause::kNone)].error = 1.0;  // nothing differs
    return shares;
}

vec3 cause_colour(Cause c) {
    switch (c) {  // Okabe & Ito (2008)
        case Cause::kGeometry:
            return from_srgb8(213, 94, 0);  // vermillion
        case Cause::kShading:
            return from_srgb8(86, 180, 233);  // sky blue
        case Cause::kShadow:
            return from_srgb8(204, 121, 167);  // reddish purple
        case Cause::kReflection:
            return from_srgb8(240, 228, 66);  // yellow
        case Cause::kRefraction:
            return from_srgb8(0, 158, 115);  // bluish green
        case Cause::kNone:
            break;
    }
    return from_srgb8(64, 64, 64);
}

Image explain_colours(const ExplainMap& map) {
    Image out(map.width, map.height);
    for (std::size_t i = 0; i < out.pixels.size(); ++i) {
        if (map.cause[i] == Cause::kNone) {
            const vec3& c = map.traced.pixels[i];
            const float grey = srgb_encode(0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z);
            out.pixels[i] = vec3(srgb_decode(0.25f * grey));
        } else {
            // From 40 % brightness at the threshold to full at a quarter of the range.
            const float size = std::min(1.0f, map.difference[i] / 0.25f);
            out.pixels[i] = cause_colour(map.cause[i]) * srgb_decode(0.4f + 0.6f * size);
        }
    }
    return out;
}

Image explain_image(const ExplainMap& map) {
    const Image colours = explain_colours(map);
    const int s = map.width >= 400 ? 2 : 1;  // font pixel size
    const int line = (kGlyphHeight + 4) * s, swatch = kGlyphHeight * s, gap = 3 * s;
    // Lay the legend out in lines that fit the width.
    struct Entry {
        Cause cause;
        int x, line;
    };
    std::vector<Entry> entries;
    int x = gap, lines = 1;
    for (const Named<Cause>& n : kCauseNames) {
        const int w = swatch + s + text_width(n.name, s) + gap;
        if (x + w > map.width && x > gap) x = gap, ++lines;
        entries.push_back({n.value, x, lines - 1});
        x += w;
    }
    const int strip = lines * line + 2 * s;
    Image out(map.width, map.height + strip);
    for (int y = 0; y < map.height; ++y)
        for (int xx = 0; xx < map.width; ++xx) out.at(xx, y + strip) = colours.at(xx, y);
    for (const Entry& e : entries) {
        const int top = strip - s - e.line * line - 2 * s;  // rows count from the bottom
        for (int dy = 0; dy < swatch; ++dy)
            for (int dx = 0; dx < swatch; ++dx)
                if (e.x + dx < out.width && top - dy >= 0)
                    out.at(e.x + dx, top - dy) = cause_colour(e.cause);
        draw_text(out, e.x + swatch + s, top, name_of(kCauseNames, e.cause), s, vec3(1.0f));
    }
    return out;
}

}  // namespace rt
