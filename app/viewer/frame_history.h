#pragma once
// The last frames' times, for the panel's graph and the viewer's benchmark: a ring of
// the newest kSize values, oldest first when read.

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace rt::viewer {

class FrameHistory {
  public:
    static constexpr std::size_t kSize = 120;

    void add(float ms) {
        values_[next_] = ms;
        next_ = (next_ + 1) % kSize;
        count_ = std::min(count_ + 1, kSize);
    }
    std::size_t size() const { return count_; }
    // Oldest first.
    std::vector<float> values() const {
        std::vector<float> out;
        out.reserve(count_);
        for (std::size_t i = 0; i < count_; ++i)
            out.push_back(values_[(next_ + kSize - count_ + i) % kSize]);
        return out;
    }
    float median() const {
        std::vector<float> v = values();
        if (v.empty()) return 0.0f;
        std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
        return v[v.size() / 2];
    }
    float max() const {
        const std::vector<float> v = values();
        return v.empty() ? 0.0f : *std::max_element(v.begin(), v.end());
    }

  private:
    std::array<float, kSize> values_{};
    std::size_t next_ = 0, count_ = 0;
};

}  // namespace rt::viewer
