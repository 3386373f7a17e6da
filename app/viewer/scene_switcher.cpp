#include "app/viewer/scene_switcher.h"

#include "app/common/data_dir.h"

#include <algorithm>
#include <cstdlib>
#include <system_error>

namespace rt::viewer {

SceneSwitcher::SceneSwitcher(std::filesystem::path scenes_dir) : dir_(std::move(scenes_dir)) {}

std::vector<std::filesystem::path> SceneSwitcher::scenes() const {
    std::vector<std::filesystem::path> out;
    std::error_code ec;  // a missing or unreadable folder lists nothing
    for (const auto& e : std::filesystem::directory_iterator(dir_, ec))
        if (e.path().extension() == ".json") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

void SceneSwitcher::step(int step) {
    const auto list = scenes();
    if (list.empty()) return;
    const std::filesystem::path from = asked_.empty() ? current_ : asked_;
    const auto at = std::find(list.begin(), list.end(), from);
    const auto n = static_cast<long>(list.size());
    // From a scene outside the folder, PageDown starts at its first and PageUp at its last.
    long index = step > 0 ? 0 : n - 1;
    if (at != list.end()) index = (((at - list.begin()) + step) % n + n) % n;
    pick(list[static_cast<std::size_t>(index)]);
}

void SceneSwitcher::pick(const std::filesystem::path& path) {
    asked_ = path.string();
    pending_ = asked_;
}

void SceneSwitcher::reload() {
    if (!current_.empty()) pending_ = current_;
}

std::optional<std::string> SceneSwitcher::take() {
    std::optional<std::string> out = std::move(pending_);
    pending_.reset();
    return out;
}

void SceneSwitcher::shown(const std::string& path) {
    current_ = path;
    if (asked_ == path) asked_.clear();
}

std::filesystem::path scenes_dir() { return rt::app::asset_dir() / "scenes"; }

}  // namespace rt::viewer
