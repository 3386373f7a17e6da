// rtbench --item-buffer SCENE: a full Whitted frame with and without the item buffer.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <vector>

#include "app/bench/modes.h"
#include "app/gl/context.h"
#include "app/gl/raster_renderer.h"
#include "core/error.h"
#include "core/item_buffer_step.h"
#include "core/renderer.h"
#include "core/scene_loader.h"
#include "core/stopwatch.h"

namespace rt::bench {

namespace {

// Per frame: a trace without the item buffer, one with it from its own pass, and (where
// the raster can share its pass) a plain raster frame and one that draws the ids too.
constexpr int kRasterPairs = 3;   // raster frames with and without the ids, per round
constexpr int kAlonePasses = 15;  // of the primary step alone (primary_step_alone), each way

struct Samples {
    std::vector<double> plain_frame, plain_primary, ib_pass, ib_primary, ib_frame, trace_with,
        raster_plain, raster_shared, ids_cost, alone_packets, alone_step;
    rt::Image with, without;
    rt::RenderStats stats;  // the last trace with the item buffer
    bool can_share = false;
};

// The primary step alone: one pass over the frame's tiles on this thread, as the renderer
// makes them, with the item buffer (`ib`) or without it (null); no shading in between, and
// no second thread on the core. Returns the seconds.
double primary_step_alone(const rt::Scene& scene, const rt::ItemBuffer* ib,
                          const rt::SmallObjects& small) {
    const rt::Camera& camera = scene.camera;
    const int size = rt::RenderOptions{}.tile_size;
    const rt::detail::CameraTerms terms(camera);
    rt::detail::TileRays rays;
    std::vector<rt::Hit> hits;
    std::vector<rt::Ray> tile_rays;
    rt::Stopwatch watch;
    for (int y = 0; y < camera.rows; y += size) {
        for (int x = 0; x < camera.cols; x += size) {
            const rt::detail::Tile t{x, y, std::min(x + size, camera.cols),
                                     std::min(y + size, camera.rows)};
            hits.resize(static_cast<std::size_t>(t.x1 - t.x0) * (t.y1 - t.y0));
            rays.make(terms, t, 0, 1);
            if (ib)
                rt::detail::item_buffer_hits(scene, *ib, small, t, rays, hits);
            else
                rt::detail::primary_packets(scene, rays, tile_rays, hits);
        }
    }
    return watch.seconds();
}

Samples measure(const ItemBufferBenchOptions& o, const rt::Scene& scene,
                rt::gl::RasterRenderer& raster) {
    rt::RenderOptions options;
    options.threads = o.threads;
    Samples m;
    rt::ItemBuffer ib = raster.render_item_buffer(scene.camera);  // warm-up: buffers, sphere meshes
    m.can_share = raster.shares_item_buffer();
    // Each pass draws into the storage of its previous frame, as a viewer would: fresh
    // pages cost more than reading the ids (the kernel zeroes them on first touch).
    rt::Image plain;
    rt::gl::RasterRenderer::Frame frame;
    if (m.can_share) {
        raster.render(scene.camera, plain);
        raster.render_with_item_buffer(scene.camera, frame);
    }
    for (int k = 0; k < o.repeats + 1; ++k) {  // the first round is a warm-up
        m.without = rt::render(scene, options, &m.stats);
        if (k > 0)
            m.plain_frame.push_back(m.stats.seconds),
                m.plain_primary.push_back(m.stats.primary_seconds);
        rt::Stopwatch watch;
        raster.render_item_buffer(scene.camera, ib);
        const double pass = watch.seconds();
        m.with = rt::render(scene, options, &m.stats, {}, {}, &ib);
        if (k > 0) {
            m.ib_pass.push_back(pass);
            m.ib_primary.push_back(m.stats.primary_seconds);
            m.ib_frame.push_back(pass + m.stats.seconds);
        }
        if (!m.can_share) continue;
        // From the raster pass: what drawing and reading the ids adds to a raster frame
        // (drawn anyway, to be compared with the traced one). The two raster frames are
        // drawn in pairs, in turn first, and the cost is each pair's difference: a frame
        // is noisier (llvmpipe shares the cores) than the ids' part of it.
        for (int pair = 0; pair < kRasterPairs; ++pair) {
            const bool plain_first = (k + pair) % 2 == 0;
            double plain_raster = 0.0, with_ids = 0.0;
            for (int turn = 0; turn < 2; ++turn) {
                watch.restart();
                if ((turn == 0) == plain_first) {
                    raster.render(scene.camera, plain);
                    plain_raster = watch.seconds();
                } else {
                    raster.render_with_item_buffer(scene.camera, frame);
                    with_ids = watch.seconds();
                }
            }
            if (k > 0) {
                m.raster_plain.push_back(plain_raster);
                m.raster_shared.push_back(with_ids);
                m.ids_cost.push_back(with_ids - plain_raster);
            }
        }
        if (frame.ids.ids != ib.ids || frame.ids.prim != ib.prim)
            throw rt::Error(o.scene, "item buffer",
                            "the raster pass's item buffer differs from the dedicated pass's");
        if (k > 0) m.trace_with.push_back(m.stats.seconds);
    }
    // The primary step alone on one thread, in turns with and without (after the frames,
    // whose second thread has stopped).
    const rt::SmallObjects small(scene, scene.camera);
    for (int k = 0; k < kAlonePasses + 1; ++k) {  // the first pass a warm-up
        const double packets = primary_step_alone(scene, nullptr, small);
        const double step = primary_step_alone(scene, &ib, small);
        if (k > 0) m.alone_packets.push_back(packets), m.alone_step.push_back(step);
    }
    return m;
}

// Prints the medians (and writes them as JSON); 0 when the images agree but for 0.1 %.
int report(const ItemBufferBenchOptions& o, const std::string& gl, const Samples& m) {
    const std::uint64_t differing = rt::item_buffer_disagreements(m.with, m.without);
    const double frame0 = median(m.plain_frame), frame1 = median(m.ib_frame);
    const double primary0 = median(m.plain_primary), primary1 = median(m.ib_primary),
                 pass = median(m.ib_pass);
    std::printf("%s at %dx%d, %d threads, %s; medians of %d frames\n", o.scene.c_str(), o.width,
                o.height, o.threads, gl.c_str(), o.repeats);
    std::printf("without item buffer: frame %.1f ms, primary rays %.1f ms\n", 1e3 * frame0,
                1e3 * primary0);
    const auto net = [&](double frame) {
        std::printf("net on the frame: %.2fx (%s %.1f ms)\n", frame0 / frame,
                    frame < frame0 ? "saves" : "COSTS", 1e3 * std::abs(frame0 - frame));
    };
    std::printf(
        "with item buffer, its own pass:        frame %.1f ms = pass and read-back %.1f ms + "
        "trace %.1f ms (primary %.1f ms); ",
        1e3 * frame1, 1e3 * pass, 1e3 * (frame1 - pass), 1e3 * primary1);
    net(frame1);
    double frame2 = 0.0, shared = 0.0;
    if (m.can_share) {
        // What the ids add to the raster frame, the median of the pairs' differences (both
        // frames read their colours back, which waits for the drawing: llvmpipe draws only
        // when something is read).
        shared = std::max(0.0, median(m.ids_cost));
        frame2 = shared + median(m.trace_with);
        std::printf(
            "with item buffer, from the raster pass: frame %.1f ms = ids drawn and read back %.1f "
            "ms (the raster frame %.1f -> %.1f ms) + trace %.1f ms; ",
            1e3 * frame2, 1e3 * shared, 1e3 * median(m.raster_plain), 1e3 * median(m.raster_shared),
            1e3 * (frame2 - shared));
        net(frame2);
    }
    const std::uint64_t fell_back = m.stats.item_buffer_fallbacks;
    std::printf("primary rays: %.2fx faster; %llu on edges, %llu of %zu pixels differ\n",
                primary0 / primary1, static_cast<unsigned long long>(fell_back),
                static_cast<unsigned long long>(differing), m.with.pixels.size());
    const double alone0 = median(m.alone_packets), alone1 = median(m.alone_step);
    std::printf(
        "the primary step alone, one thread (medians of %d passes over the frame's tiles): "
        "packets %.2f ms, item buffer %.2f ms (%.2fx faster)\n",
        kAlonePasses, 1e3 * alone0, 1e3 * alone1, alone0 / alone1);
    if (!o.json.empty()) {
        nlohmann::json j = {{"scene", o.scene},
                            {"width", o.width},
                            {"height", o.height},
                            {"threads", o.threads},
                            {"gl", gl},
                            {"frame_seconds_without", frame0},
                            {"frame_seconds_with", frame1},
                            {"primary_seconds_without", primary0},
                            {"primary_seconds_with", primary1},
                            {"primary_speedup", primary0 / primary1},
                            {"raster_pass_seconds", pass},
                            {"net_speedup", frame0 / frame1},
                            {"fallback_pixels", fell_back},
                            {"primary_step_alone_seconds_without", alone0},
                            {"primary_step_alone_seconds_with", alone1},
                            {"differing_pixels", differing}};
        if (m.can_share) {
            j["shared_pass_seconds"] = shared;
            j["frame_seconds_with_shared"] = frame2;
            j["net_speedup_shared"] = frame0 / frame2;
        }
        std::ofstream(o.json) << j.dump(2) << '\n';
    }
    const auto pixels = static_cast<double>(m.with.pixels.size());
    return static_cast<double>(differing) <= 0.001 * pixels ? 0 : 1;
}

}  // namespace

int run_item_buffer(const ItemBufferBenchOptions& o) {
    rt::LoadedScene loaded = rt::load_scene(o.scene);
    loaded.scene.camera = loaded.scene.camera.resized(o.width, o.height);
    const rt::Scene scene(std::move(loaded.scene));
    const auto context = rt::gl::create_headless_context(o.gl, "rtbench");
    rt::gl::RasterRenderer raster(scene);
    const Samples samples = measure(o, scene, raster);
    return report(o, context->description(), samples);
}

}  // namespace rt::bench
