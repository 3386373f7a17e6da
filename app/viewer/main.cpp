// rtview: the interactive viewer.
//   rtview [SCENE] [--size WxH] [--view raster|trace|split|diff|itembuffer|why] [--spp N]
//          [--msaa N] [--raster-shadows none|map] [--raster-reflections none|envmap]
//          [--save-dir DIR]
//          [--accel bvh|bvh2|grid|brute] [--benchmark]

#include <charconv>
#include <iostream>

#include <CLI/CLI.hpp>

#include "app/common/cli_names.h"
#include "app/common/size_arg.h"
#include "app/viewer/viewer.h"
#include "app/viewer/views.h"
#include "core/error.h"
#include "core/scene_loader.h"

int main(int argc, char** argv) {
    rt::viewer::ViewerOptions options;
    options.scene = (rt::viewer::scenes_dir() / "whitted.json").string();
    std::string size, save_dir = ".";
    options.view = rt::gl::View::kSplit;
    CLI::App app{"rtview: one scene, rasterised by OpenGL and ray traced, side by side"};
    app.add_option(
        "scene", options.scene,
        "Scene or model file (.json, .obj, .gltf, .glb, .ply, .stl); default: the Whitted scene");
    app.add_option("--size", size, "Window size WxH (default 1280x720)");
    app.add_option("--view", options.view, "First view")
        ->transform(rt::app::cli_names(rt::viewer::kViews));
    app.add_option("--save-dir", save_dir, "Where F12 saves images (default: here)");
    app.add_option("--spp", options.spp,
                   "Samples per pixel the traced view refines to once at full resolution: "
                   "1 (no anti-aliasing), 4, 16 (default) or 64")
        ->check(CLI::IsMember({1, 4, 16, 64}));
    app.add_option("--msaa", options.msaa,
                   "Raster multisample anti-aliasing at the start: 1 (none, default), 2, 4 or 8")
        ->check(CLI::IsMember({1, 2, 4, 8}));
    std::string raster_shadows = "none", raster_reflections = "none";
    app.add_option("--raster-shadows", raster_shadows,
                   "Raster shadows at the start: none (default) or map (shadow maps)")
        ->check(CLI::IsMember({"none", "map"}));
    app.add_option("--raster-reflections", raster_reflections,
                   "Raster mirrors and glass at the start: none (default) or envmap "
                   "(environment maps)")
        ->check(CLI::IsMember({"none", "envmap"}));
    app.add_option("--camera", options.camera,
                   "Which of a glTF file's perspective cameras to look through (the first "
                   "scene's): 0 (default), 1, ...")
        ->check(CLI::Range(0, 1 << 20));
    app.add_option("--up", options.up, "A bare mesh's up axis: y (default), z, x, -y, -z or -x")
        ->check(CLI::IsMember(
            std::vector<std::string>(std::begin(rt::kUpAxes), std::end(rt::kUpAxes))));
    app.add_option("--accel", options.accel,
                   "Acceleration structure: bvh (wide, default), bvh2 (binary), grid or brute")
        ->transform(rt::app::cli_names(rt::kAccelNames));
    bool benchmark = false;
    app.add_flag("--benchmark", benchmark,
                 "Measure frame times while tracing, at rest and orbiting, and the delay to "
                 "the full trace, on the scene given or else every scene of the scenes "
                 "folder; print a table and exit");
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::cerr << "rtview: command line: " << e.what() << " (see rtview --help)\n";
        return 1;
    }
    const auto parsed = rt::app::parse_size(size, 64);
    if (parsed) std::tie(options.width, options.height) = *parsed;
    if (!size.empty() && !parsed) {
        std::cerr << "rtview: --size: expected WxH between 64x64 and 16384x16384, got \"" << size
                  << "\"\n";
        return 1;
    }
    options.save_dir = save_dir;
    options.shadow_maps = raster_shadows == "map";
    options.environment_maps = raster_reflections == "envmap";
    try {
        rt::viewer::Viewer viewer(options);
        if (!benchmark) return viewer.run();
        std::vector<std::string> scenes;
        if (app.count("scene") > 0) {
            scenes.push_back(options.scene);
        } else {
            for (const auto& p : rt::viewer::SceneSwitcher(rt::viewer::scenes_dir()).scenes())
                scenes.push_back(p.string());
        }
        return viewer.benchmark(scenes);
    } catch (const rt::Error& e) {
        std::cerr << e.what() << '\n';
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "rtview: error: " << e.what() << '\n';
        return 1;
    }
}
