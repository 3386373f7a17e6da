// The viewer's GL-free parts: the camera controller, the progressive trace job, the
// scene switcher and the table of controls.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "app/viewer/camera_controller.h"
#include "app/viewer/frame_history.h"
#include "app/viewer/keys.h"
#include "app/viewer/refinement.h"
#include "app/viewer/scene_switcher.h"
#include "app/viewer/trace_job.h"
#include "core/scene_loader.h"
#include "test_util.h"

namespace rt::viewer {
namespace {

using rt::vec3;

void expect_vec(const vec3& a, const vec3& b, float tol = 1e-4f) {
    EXPECT_NEAR(a.x, b.x, tol);
    EXPECT_NEAR(a.y, b.y, tol);
    EXPECT_NEAR(a.z, b.z, tol);
}

rt::Camera home() { return rt::Camera::look_at({0, 2, 8}, {0, 1, 0}, {0, 1, 0}, 40.0f, 640, 480); }
rt::Aabb unit_box() { return {vec3(-1.0f), vec3(1.0f)}; }

TEST(CameraController, StartsAtTheScenesCamera) {
    const CameraController c(home(), unit_box());
    const rt::Camera cam = c.camera(640, 480);
    expect_vec(cam.eye, home().eye);
    expect_vec(cam.n, home().n);
    expect_vec(cam.u, home().u);
    EXPECT_FLOAT_EQ(cam.H, home().H);
}

TEST(CameraController, OrbitKeepsTheDistanceAndComesBack) {
    CameraController c(home(), unit_box());
    const float d0 = glm::length(c.eye() - c.target());
    c.orbit(120.0f, -40.0f);
    EXPECT_NEAR(glm::length(c.eye() - c.target()), d0, 1e-4f);
    EXPECT_GT(glm::length(c.eye() - home().eye), 0.5f);
    c.orbit(-120.0f, 40.0f);
    expect_vec(c.eye(), home().eye);
}

TEST(CameraController, PitchStopsShortOfThePoles) {
    CameraController c(home(), unit_box());
    c.orbit(0.0f, 100000.0f);
    const rt::Camera cam = c.camera(64, 64);
    EXPECT_TRUE(std::isfinite(cam.u.x) && std::isfinite(cam.v.y) && std::isfinite(cam.n.z));
    EXPECT_LT(std::fabs(glm::dot(cam.n, vec3(0, 1, 0))), 1.0f);
}

// The pitch stops 86 degrees above or below the horizon, however far the drag goes.
TEST(CameraController, PitchStopsAtItsLimitBothWays) {
    for (const float drag : {100000.0f, -100000.0f}) {
        CameraController c(home(), unit_box());
        c.orbit(0.0f, drag);
        const rt::Camera cam = c.camera(64, 64);
        EXPECT_NEAR(std::fabs(glm::dot(cam.n, vec3(0, 1, 0))),
                    std::sin(CameraController::kMaxPitch), 1e-4f);
    }
}

// Orbit is a turntable about the scene's up: from a camera looking down at 30 degrees, a
// purely horizontal drag keeps the horizon level (u stays horizontal) and the elevation
// as it was; the old orbit about the home camera's tilted v rolled it by about 3 degrees
// per 50 pixels.
TEST(CameraController, HorizontalOrbitNeverRollsTheHorizon) {
    const rt::Camera tilted =
        rt::Camera::look_at({0, 4, 6.93f}, {0, 0, 0}, {0, 1, 0}, 40.0f, 640, 480);
    CameraController c(tilted, unit_box());
    const float elevation = glm::dot(c.camera(640, 480).n, vec3(0, 1, 0));
    for (int step = 0; step < 40; ++step) {
        c.orbit(50.0f, 0.0f);
        const rt::Camera cam = c.camera(640, 480);
        ASSERT_NEAR(glm::dot(cam.u, vec3(0, 1, 0)), 0.0f, 1e-5f)
            << "after " << step + 1 << " drags";
        EXPECT_GT(glm::dot(cam.v, vec3(0, 1, 0)), 0.0f);
        EXPECT_NEAR(glm::dot(cam.n, vec3(0, 1, 0)), elevation, 1e-5f);
    }
    // A z-up scene turns about z.
    const rt::Camera z_up = rt::Camera::look_at({6, -6, 4}, {0, 0, 0}, {0, 0, 1}, 40.0f, 64, 48);
    CameraController cz(z_up, unit_box());
    cz.orbit(120.0f, 30.0f);
    EXPECT_NEAR(glm::dot(cz.camera(64, 48).u, vec3(0, 0, 1)), 0.0f, 1e-5f);
}

// A home camera with a roll of its own (a u, v, n frame) starts as it is and keeps that
// roll while orbiting.
TEST(CameraController, AHomeRollIsKept) {
    const float roll = glm::radians(20.0f);
    rt::Camera rolled = home();
    const vec3 u = rolled.u, v = rolled.v;
    rolled.u = std::cos(roll) * u + std::sin(roll) * v;
    rolled.v = glm::cross(rolled.n, rolled.u);
    CameraController c(rolled, unit_box());
    expect_vec(c.camera(640, 480).u, rolled.u);
    expect_vec(c.camera(640, 480).v, rolled.v);
    c.orbit(200.0f, -40.0f);
    const rt::Camera cam = c.camera(640, 480);
    const vec3 level = glm::normalize(glm::cross(vec3(0, 1, 0), cam.n));
    EXPECT_NEAR(std::acos(std::clamp(glm::dot(cam.u, level), -1.0f, 1.0f)), roll, 1e-4f);
}

TEST(CameraController, ZoomPanFlyAndReset) {
    CameraController c(home(), unit_box());
    const std::uint64_t v0 = c.version();
    const float d0 = glm::length(c.eye() - c.target());
    c.zoom(2.0f);
    EXPECT_NEAR(glm::length(c.eye() - c.target()), d0 * 0.85f * 0.85f, 1e-4f);
    const vec3 t0 = c.target();
    c.pan(100.0f, 0.0f, 480);  // dragging right moves the scene right: the target goes left
    EXPECT_LT(glm::dot(c.target() - t0, home().u), 0.0f);
    const vec3 e0 = c.eye();
    c.fly({0, 0, 1}, 0.5f, false);  // forward is -n
    EXPECT_GT(glm::dot(c.eye() - e0, -home().n), 0.0f);
    EXPECT_GT(c.version(), v0);
    c.reset();
    expect_vec(c.eye(), home().eye);
}

std::shared_ptr<const rt::Scene> tutorial() {
    rt::LoadedScene loaded = rt::load_scene(rt::test::scene_path("tutorial.json"));
    return std::make_shared<const rt::Scene>(std::move(loaded.scene));
}

std::optional<TraceResult> wait_for_level(TraceJob& job, int level) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (std::chrono::steady_clock::now() < deadline) {
        if (auto r = job.take(); r && r->level == level) return r;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return std::nullopt;
}

TEST(TraceJob, RefinesToFullResolution) {
    std::atomic<int> published{0};  // the viewer wakes its event loop on each
    TraceJob job([&] { ++published; });
    TraceRequest request;
    request.scene = tutorial();
    request.camera = request.scene->camera.resized(160, 120);
    request.levels = {8, 2, 1};
    request.id = 7;
    job.submit(request);
    const auto full = wait_for_level(job, 1);
    ASSERT_TRUE(full);
    EXPECT_EQ(full->id, 7u);
    EXPECT_EQ(full->image.width, 160);
    EXPECT_EQ(full->image.height, 120);
    EXPECT_EQ(full->stats.rays.primary, 160u * 120u);
    job.cancel();  // the worker is done: every level has said so
    EXPECT_EQ(published.load(), 3);
}

// Every level arrives, coarse to fine: taken as soon as published (in the publish
// callback, on the worker, before it goes on to the next level), the levels of one
// request come in the order asked for (a job that skipped to the last would show only 1).
// Taken by polling instead, a poller held up for a few milliseconds (a loaded machine)
// saw a level replaced by the next before it looked.
TEST(TraceJob, EachLevelArrivesInOrder) {
    std::mutex mutex;
    std::vector<int> seen;
    TraceJob* self = nullptr;
    TraceJob job([&] {
        const auto r = self->take();
        if (!r) return;
        EXPECT_EQ(r->id, 3u);
        EXPECT_EQ(r->image.width, 960 / r->level);
        const std::lock_guard lock(mutex);
        seen.push_back(r->level);
    });
    self = &job;
    TraceRequest request;
    request.scene = tutorial();
    request.camera = request.scene->camera.resized(960, 720);
    request.options.threads = 1;
    request.levels = {8, 4, 2, 1};
    request.id = 3;
    job.submit(request);
    const auto done = [&] {
        const std::lock_guard lock(mutex);
        return !seen.empty() && seen.back() == 1;
    };
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!done() && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    job.cancel();
    const std::lock_guard lock(mutex);
    EXPECT_EQ(seen, (std::vector<int>{8, 4, 2, 1}));
}

// A result of an older request is never taken once a newer request is in: not one
// already published and waiting, not one that finishes after the new submit.
TEST(TraceJob, ASupersededResultIsNeverTaken) {
    TraceJob job;
    TraceRequest quick;
    quick.scene = tutorial();
    quick.camera = quick.scene->camera.resized(40, 30);
    quick.levels = {1};
    quick.id = 1;
    job.submit(quick);
    // 1,200 rays take well under a millisecond, under the sanitizers too: published, not taken.
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    TraceRequest slow = quick;
    slow.camera = quick.scene->camera.resized(1600, 1200);
    slow.options.threads = 1;
    slow.id = 2;
    job.submit(slow);
    const auto r = job.take();
    EXPECT_FALSE(r.has_value()) << "took the result of request " << r->id;
    job.cancel();
}

TEST(TraceJob, CancelReturnsPromptlyAndLetsGoOfTheScene) {
    TraceJob job;
    std::shared_ptr<const rt::Scene> scene = tutorial();
    TraceRequest request;
    request.scene = scene;
    request.camera = scene->camera.resized(2000, 1500);  // on one thread: long enough to be running
    request.options.threads = 1;
    request.levels = {1};
    job.submit(request);
    request.scene.reset();
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    const auto start = std::chrono::steady_clock::now();
    job.cancel();
    // A tile takes microseconds; a second allows for sanitizers slowing everything 10x.
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 3.0);
    EXPECT_FALSE(job.busy());
    EXPECT_EQ(scene.use_count(), 1) << "the worker still holds the scene";
    EXPECT_FALSE(job.take().has_value());
}

TEST(TraceJob, ANewRequestReplacesTheRunningOne) {
    TraceJob job;
    TraceRequest slow;
    slow.scene = tutorial();
    slow.camera = slow.scene->camera.resized(4000, 3000);
    slow.levels = {1};
    slow.id = 1;
    job.submit(slow);
    TraceRequest quick = slow;
    quick.camera = slow.scene->camera.resized(64, 48);
    quick.id = 2;
    job.submit(quick);
    const auto r = wait_for_level(job, 1);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->id, 2u);
    EXPECT_EQ(r->image.width, 64);
}

// The refinement schedule: the first image goes through every level; a change follows at
// the coarsest level at once and again at each further change; full resolution waits
// until nothing changed for the rest time; display-only settings are not in the key.
TEST(RefinementSchedule, CoarseWhileChangingFullOnceAtRest) {
    using V = std::vector<int>;
    RefinementSchedule s;
    TraceKey key;
    key.width = 640;
    key.height = 480;
    EXPECT_EQ(s.update(key, 0.0), (V{8, 4, 2, 1}));
    EXPECT_EQ(s.update(key, 0.05), V{});  // nothing changed: nothing to trace
    key.camera_version = 1;               // an orbit step
    EXPECT_EQ(s.update(key, 1.0), V{8});
    key.camera_version = 2;
    EXPECT_EQ(s.update(key, 1.1), V{8});
    EXPECT_EQ(s.update(key, 1.1 + 0.5 * RefinementSchedule::kRestSeconds), V{});  // not rested
    EXPECT_EQ(s.update(key, 1.11 + RefinementSchedule::kRestSeconds), (V{4, 2, 1}));
    EXPECT_EQ(s.update(key, 5.0), V{});  // refined once, not again
    key.max_depth = 2;                   // a trace setting
    EXPECT_EQ(s.update(key, 6.0), V{8});
    key.width = 320;  // the window (or the resolution scale)
    EXPECT_EQ(s.update(key, 6.1), V{8});
    EXPECT_EQ(s.update(key, 7.0), (V{4, 2, 1}));
    s.reset();  // a new scene
    EXPECT_EQ(s.update(key, 7.1), (V{8, 4, 2, 1}));
}

// With no traced image on screen (the raster view) changes are not followed coarsely,
// and the whole chain comes once the camera rests; a traced view shown again during the
// rest follows at once.
TEST(RefinementSchedule, OffScreenWaitsForRest) {
    using V = std::vector<int>;
    RefinementSchedule s;
    TraceKey key;
    EXPECT_EQ(s.update(key, 0.0, false), (V{8, 4, 2, 1}));  // the first image
    key.camera_version = 1;
    EXPECT_EQ(s.update(key, 1.0, false), V{});
    key.camera_version = 2;
    EXPECT_EQ(s.update(key, 1.1, false), V{});
    EXPECT_EQ(s.update(key, 1.11 + RefinementSchedule::kRestSeconds, false), (V{8, 4, 2, 1}));
    EXPECT_EQ(s.update(key, 5.0, false), V{});
    key.camera_version = 3;
    EXPECT_EQ(s.update(key, 6.0, false), V{});
    EXPECT_EQ(s.update(key, 6.05, true), V{8});  // the traced view again, before the rest
    EXPECT_EQ(s.update(key, 6.1, true), V{});
    EXPECT_EQ(s.update(key, 6.01 + RefinementSchedule::kRestSeconds, true), (V{4, 2, 1}));
}

// A folder of three scenes (and a file that is not one), made for the test.
std::filesystem::path scene_folder(const char* name) {
    const auto dir = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    for (const char* f : {"b.json", "a.json", "c.json", "notes.txt"})
        std::ofstream(dir / f) << "{}";
    return dir;
}

TEST(SceneSwitcher, StepsThroughTheFolderInOrderAndWraps) {
    const auto dir = scene_folder("rtview_switcher_steps");
    SceneSwitcher s(dir);
    ASSERT_EQ(s.scenes().size(), 3u);  // the .json files only
    s.shown((dir / "b.json").string());
    EXPECT_FALSE(s.take());  // nothing asked for
    s.step(1);
    EXPECT_EQ(s.take(), (dir / "c.json").string());
    EXPECT_FALSE(s.take());  // once
    s.shown((dir / "c.json").string());
    s.step(1);
    EXPECT_EQ(s.take(), (dir / "a.json").string());  // wraps
    s.shown((dir / "a.json").string());
    s.step(-1);
    EXPECT_EQ(s.take(), (dir / "c.json").string());  // and back
}

// When a scene fails to load, the one before stays on screen, but the next step goes on from
// the broken one, not from the scene still shown, so one bad file is not a wall.
TEST(SceneSwitcher, StepsOverASceneThatFailedToLoad) {
    const auto dir = scene_folder("rtview_switcher_broken");
    SceneSwitcher s(dir);
    s.shown((dir / "a.json").string());
    s.step(1);
    EXPECT_EQ(s.take(), (dir / "b.json").string());  // b fails: a is still shown
    s.step(1);
    EXPECT_EQ(s.take(), (dir / "c.json").string());
    EXPECT_EQ(s.current(), (dir / "a.json").string());
}

TEST(SceneSwitcher, DropsPicksAndReloads) {
    const auto dir = scene_folder("rtview_switcher_drop");
    SceneSwitcher s(dir);
    s.shown("/elsewhere/model.obj");  // started on a file outside the folder
    s.reload();
    EXPECT_EQ(s.take(), "/elsewhere/model.obj");
    s.step(1);
    EXPECT_EQ(s.take(), (dir / "a.json").string());  // from outside: the first
    s.step(-1);
    EXPECT_EQ(s.take(), (dir / "c.json").string());  // or the last
    s.pick("/dropped/scene.json");
    s.step(1);  // the later request wins
    EXPECT_EQ(s.take(), (dir / "a.json").string());
    EXPECT_TRUE(SceneSwitcher(dir / "missing").scenes().empty());
}

TEST(Controls, KeysFindTheirActionWithExactlyTheirModifiers) {
    EXPECT_EQ(action_of(GLFW_KEY_R, 0), Action::kResetCamera);
    EXPECT_EQ(action_of(GLFW_KEY_P, 0), Action::kSave);
    EXPECT_EQ(action_of(GLFW_KEY_F12, 0), Action::kSave);
    EXPECT_EQ(action_of(GLFW_KEY_SLASH, GLFW_MOD_SHIFT), Action::kHelp);  // '?'
    EXPECT_EQ(action_of(GLFW_KEY_SLASH, 0), Action::kNone);
    EXPECT_EQ(action_of(GLFW_KEY_Q, GLFW_MOD_CONTROL), Action::kQuit);
    EXPECT_EQ(action_of(GLFW_KEY_Q, GLFW_MOD_CONTROL | GLFW_MOD_NUM_LOCK), Action::kQuit);
    EXPECT_EQ(action_of(GLFW_KEY_Q, 0), Action::kNone);  // flying down, not quitting
    EXPECT_EQ(with_keys(Action::kResetCamera), "reset camera (R)");
    // Every action has a row in the help, and every key-bound row a key.
    for (const Control& c : kControls) {
        EXPECT_NE(std::string(c.keys), "");
        EXPECT_NE(std::string(c.what), "");
        if (c.action == Action::kNone) continue;
        EXPECT_EQ(action_of(c.chords[0].key, c.chords[0].mods), c.action) << c.name;
    }
}

TEST(FrameHistory, KeepsTheNewestOldestFirst) {
    FrameHistory h;
    EXPECT_EQ(h.median(), 0.0f);
    for (int i = 1; i <= 5; ++i) h.add(static_cast<float>(i));
    EXPECT_EQ(h.values(), (std::vector<float>{1, 2, 3, 4, 5}));
    EXPECT_EQ(h.median(), 3.0f);
    EXPECT_EQ(h.max(), 5.0f);
    for (std::size_t i = 0; i < FrameHistory::kSize; ++i) h.add(100.0f + static_cast<float>(i));
    ASSERT_EQ(h.size(), FrameHistory::kSize);
    EXPECT_EQ(h.values().front(), 100.0f);  // the first five are gone
    EXPECT_EQ(h.values().back(), 100.0f + static_cast<float>(FrameHistory::kSize - 1));
}

// The image on screen is stale from the moment the camera moves until a level of the
// new request arrives; a late level of an older request never makes it current.
TEST(ShownTrace, StaleFromTheChangeUntilTheNewRequestArrives) {
    ShownTrace shown;
    TraceKey a;
    a.width = 640;
    EXPECT_TRUE(shown.stale(a));  // nothing traced yet
    shown.submitted(1, a);
    shown.arrived(1, 8);
    EXPECT_FALSE(shown.stale(a));
    EXPECT_FALSE(shown.complete(a));  // coarse
    shown.arrived(1, 1);
    EXPECT_TRUE(shown.complete(a));
    TraceKey b = a;
    b.camera_version = 1;  // the camera moved: the image on screen is a's
    EXPECT_TRUE(shown.stale(b));
    shown.submitted(2, b);
    EXPECT_TRUE(shown.stale(b));
    EXPECT_EQ(shown.level(), 1);  // a's full image, still shown
    shown.arrived(1, 1);          // a late result of the old request
    EXPECT_TRUE(shown.stale(b));
    shown.arrived(2, 8);
    EXPECT_FALSE(shown.stale(b));
    EXPECT_EQ(shown.level(), 8);
    shown.reset();
    EXPECT_TRUE(shown.stale(b));
}

}  // namespace
}  // namespace rt::viewer
