#pragma once
// The viewer's views, once: their order is that of the keys 1 to 7; `name` is what
// --view takes, `label` what the panel, the help, the title bar and the log show.

#include <cstddef>
#include <string>

#include "app/gl/compositor.h"

namespace rt::viewer {

struct ViewInfo {
    const char* name;
    rt::gl::View value;
    const char* label;
};

inline constexpr ViewInfo kViews[] = {{"raster", rt::gl::View::kRaster, "raster"},
                                      {"trace", rt::gl::View::kTrace, "traced"},
                                      {"split", rt::gl::View::kSplit, "split"},
                                      {"diff", rt::gl::View::kDiff, "difference"},
                                      {"itembuffer", rt::gl::View::kItemBuffer, "item buffer"},
                                      {"why", rt::gl::View::kWhy, "why"},
                                      {"gputrace", rt::gl::View::kGpuTrace, "GPU traced"}};
inline constexpr std::size_t kViewCount = std::size(kViews);

constexpr bool views_in_key_order() {
    for (std::size_t i = 0; i < kViewCount; ++i)
        if (static_cast<std::size_t>(kViews[i].value) != i) return false;
    return true;
}
static_assert(views_in_key_order(), "kViews[i] is the view of key i + 1");

inline const char* view_label(rt::gl::View v) { return kViews[static_cast<std::size_t>(v)].label; }

}  // namespace rt::viewer
