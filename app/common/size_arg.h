#pragma once
// "WxH" on the command lines of rtrender, rtview and rtbench.

#include <charconv>
#include <optional>
#include <string>
#include <utility>

namespace rt::app {

// Width and height from "WxH" (or "WXH"), each in [lo, hi]; nothing if malformed.
inline std::optional<std::pair<int, int>> parse_size(const std::string& text, int lo = 1,
                                                     int hi = 16384) {
    int w = 0, h = 0;
    const char* end = text.data() + text.size();
    const auto [x_at, ec1] = std::from_chars(text.data(), end, w);
    if (ec1 != std::errc{} || x_at == end || (*x_at != 'x' && *x_at != 'X')) return std::nullopt;
    const auto [h_end, ec2] = std::from_chars(x_at + 1, end, h);
    if (ec2 != std::errc{} || h_end != end) return std::nullopt;
    if (w < lo || h < lo || w > hi || h > hi) return std::nullopt;
    return std::make_pair(w, h);
}

}  // namespace rt::app
