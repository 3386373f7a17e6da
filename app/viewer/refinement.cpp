#include "app/viewer/refinement.h"

namespace rt::viewer {

std::vector<int> RefinementSchedule::update(const TraceKey& key, double now, bool on_screen) {
    if (!submitted_) {
        submitted_ = key;
        refine_pending_ = false;
        return {kCoarsest, 4, 2, 1};
    }
    if (!(key == *submitted_)) {
        submitted_ = key;
        last_change_ = now;
        refine_pending_ = true;
        followed_ = false;
    }
    if (refine_pending_ && !followed_ && on_screen) {
        followed_ = true;
        return {kCoarsest};  // follow the change at once, coarsely
    }
    if (!refine_pending_ || now - last_change_ < kRestSeconds) return {};
    refine_pending_ = false;
    if (followed_) return {4, 2, 1};
    return {kCoarsest, 4, 2, 1};
}

}  // namespace rt::viewer
