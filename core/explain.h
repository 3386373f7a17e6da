#pragma once
// Why the raster and traced images differ, pixel by pixel: the difference traced - raster
// split into terms that add up to it exactly (docs/explain.md has the maths).
//
//   geometry    the first hits differ (the item buffer names another object, or none):
//               the whole difference, and every other term 0;
//   shading     same first object: local Phong with every light unblocked - raster;
//   shadow      what the shadow feelers took away: local as traced - local unblocked;
//   reflection  the reflected ray's weighted colour;
//   refraction  the refracted ray's weighted colour.
//
// With the raster's classic tricks on (shadow maps, environment maps), each term compares
// like with like: the raster image is split into its local part and what each trick added
// (RasterTricks), and the shadow, reflection and refraction terms become the tracer's
// minus the raster's (the feelers against the shadow map, the rays against the
// environment map); shading compares the local parts. The terms still sum to traced -
// raster exactly.
//
// A pixel's cause is its largest term (largest channel, by magnitude), or none where the
// displayed images differ by at most 2/255 in every channel (compare_images' threshold).

#include <array>
#include <cstdint>
#include <stop_token>
#include <vector>

#include "core/image.h"
#include "core/item_buffer.h"
#include "core/names.h"
#include "core/renderer.h"

namespace rt {

enum class Cause : std::uint8_t { kNone, kGeometry, kShading, kShadow, kReflection, kRefraction };
inline constexpr Named<Cause> kCauseNames[] = {
    {"geometry", Cause::kGeometry},     {"shading", Cause::kShading},
    {"shadow", Cause::kShadow},         {"reflection", Cause::kReflection},
    {"refraction", Cause::kRefraction}, {"none", Cause::kNone}};
inline constexpr std::size_t kCauseCount = std::size(kCauseNames);

// One pixel's terms, linear RGB.
struct ExplainTerms {
    vec3 geometry{0.0f}, shading{0.0f}, shadow{0.0f}, reflection{0.0f}, refraction{0.0f};

    vec3 sum() const { return geometry + shading + shadow + reflection + refraction; }
    const vec3& operator[](Cause c) const;  // not for kNone
};

// What the raster's tricks added to each pixel (linear RGB, images of the camera's size,
// empty where a trick is off): the shadow maps' darkening (<= 0), the environment maps'
// reflection and refraction terms.
struct RasterTricks {
    Image shadow, reflection, refraction;
};

struct ExplainMap {
    int width = 0, height = 0;  // rows bottom first, as Image
    std::vector<ExplainTerms> terms;
    std::vector<Cause> cause;
    std::vector<float> difference;  // the displayed difference: its largest channel
    std::vector<float> error;       // and its three channels summed (what "error" shares)
    Image traced;                   // the tracer's colours (its parts summed)
    RayCounts rays;
    bool cancelled = false;

    std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }
};

// Traces every pixel of `camera` in parts and sets them against the raster image and its
// item buffer (both of the camera's size, or std::invalid_argument). `stop` cancels
// between tiles (the map is then incomplete and says so).
ExplainMap explain(const Scene& scene, const Camera& camera, const RenderOptions& options,
                   const Image& raster, const ItemBuffer& raster_ids, std::stop_token stop = {},
                   const RasterTricks* tricks = nullptr);

// Splits one pixel (exposed for the tests): the tracer's parts against the raster's.
struct RasterPixelTricks {
    vec3 shadow{0.0f}, reflection{0.0f}, refraction{0.0f};
};
ExplainTerms explain_terms(const PrimaryParts& traced, const vec3& raster, std::uint32_t raster_id,
                           const RasterPixelTricks& tricks = {});
Cause cause_of(const ExplainTerms& terms, float displayed_difference);

// Per cause (kCauseNames' order): the share of the pixels whose cause it is, and the
// share of the summed absolute displayed difference they carry. Each sums to 1.
struct CauseShare {
    double pixels = 0.0, error = 0.0;
};
std::array<CauseShare, kCauseCount> cause_shares(const ExplainMap& map);

// The map in colour: each pixel its cause's colour (Okabe and Ito's colour-blind-safe
// palette), brighter the larger its difference; none-pixels a dim grey of the traced
// image, for orientation. explain_image adds the legend strip below.
vec3 cause_colour(Cause c);
Image explain_colours(const ExplainMap& map);
Image explain_image(const ExplainMap& map);

}  // namespace rt
