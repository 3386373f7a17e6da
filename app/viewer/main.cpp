// rtview: the interactive viewer.
//   rtview [SCENE] [--size WxH] [--view raster|trace|split|diff|itembuffer] [--save-dir DIR]
//          [--accel bvh|bvh2|grid|brute]

#include <charconv>
#include <iostream>
#include <map>

#include <CLI/CLI.hpp>

#include "app/common/size_arg.h"
#include "app/viewer/viewer.h"
#include "core/error.h"
#include "core/scene_loader.h"

int main(int argc, char** argv) {
    rtview::ViewerOptions options;
    options.scene = std::string(RTVIEW_ASSET_DIR) + "/scenes/whitted.json";
    std::string size, view = "split", save_dir = ".", accel = "bvh";
    CLI::App app{"rtview: one scene, rasterised by OpenGL and ray traced, side by side"};
    app.add_option("scene", options.scene,
                   "Scene file (.json or .obj); default: the Whitted scene");
    app.add_option("--size", size, "Window size WxH (default 1280x720)");
    app.add_option("--view", view, "First view")
        ->check(CLI::IsMember({"raster", "trace", "split", "diff", "itembuffer"}));
    app.add_option("--save-dir", save_dir, "Where F12 saves images (default: here)");
    app.add_option("--up", options.up, "A bare mesh's up axis: y (default), z, x, -y, -z or -x")
        ->check(CLI::IsMember(std::vector<std::string>(std::begin(rt::kUpAxes), std::end(rt::kUpAxes))));
    app.add_option("--accel", accel,
                   "Acceleration structure: bvh (wide, default), bvh2 (binary), grid or brute")
        ->check(CLI::IsMember({"bvh", "bvh2", "grid", "brute"}));
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "rtview: command line: " << e.what() << " (see rtview --help)\n";
        return 1;
    }
    const auto parsed = rtapp::parse_size(size, 64);
    if (parsed) std::tie(options.width, options.height) = *parsed;
    if (!size.empty() && !parsed) {
        std::cerr << "rtview: --size: expected WxH between 64x64 and 16384x16384, got \"" << size
                  << "\"\n";
        return 1;
    }
    const std::map<std::string, rt::gl::View> views = {{"raster", rt::gl::View::kRaster},
                                                       {"trace", rt::gl::View::kTrace},
                                                       {"split", rt::gl::View::kSplit},
                                                       {"diff", rt::gl::View::kDiff},
                                                       {"itembuffer", rt::gl::View::kItemBuffer}};
    options.view = views.at(view);
    options.save_dir = save_dir;
    options.accel = *rt::parse_accel(accel);
    try {
        rtview::Viewer viewer(options);
        return viewer.run();
    } catch (const rt::Error& e) {
        std::cerr << e.what() << '\n';
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "rtview: error: " << e.what() << '\n';
        return 1;
    }
}
