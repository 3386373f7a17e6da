#pragma once
// Which scene the viewer shows next: PageDown/PageUp through the scenes folder, a pick
// from the panel, a file dropped on the window, F5 (the same file again, read afresh).
// It knows no GL and loads nothing: the viewer takes() the path once per frame, tries
// it, and says whether it was shown(). Stepping goes on from the last scene asked for,
// loaded or not, so one broken file in the folder is stepped over, not a wall.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rt::viewer {

class SceneSwitcher {
  public:
    // `scenes_dir`: where PageDown/PageUp and the panel's list look (its .json files).
    explicit SceneSwitcher(std::filesystem::path scenes_dir);

    // The folder's scenes, sorted by name, read now (files may come and go).
    std::vector<std::filesystem::path> scenes() const;
    const std::filesystem::path& scenes_dir() const { return dir_; }

    void step(int step);  // +1: the next scene in the folder, -1: the previous (wrapping)
    void pick(const std::filesystem::path& path);  // from the panel, or a dropped file
    void reload();                                 // the scene shown, read again

    // The scene to load before the next frame, once; nothing when none was asked for.
    std::optional<std::string> take();
    // The viewer's answer: `path` is on screen now (at start, or after a take()).
    void shown(const std::string& path);
    const std::string& current() const { return current_; }

  private:
    std::filesystem::path dir_;
    std::string current_;                 // on screen
    std::string asked_;                   // the last scene asked for, loaded or not
    std::optional<std::string> pending_;  // asked for, not yet taken
};

// The shipped scenes' folder: scenes/ in the assets (app/common/data_dir.h).
std::filesystem::path scenes_dir();

}  // namespace rt::viewer
