// rtbench SCENE_OR_MESH: every structure, the same triangles, the same rays.
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "app/bench/modes.h"
#include "core/error.h"
#include "core/scene_loader.h"
#include "core/simd.h"
#include "core/stopwatch.h"
#include "core/tessellate.h"

namespace rt::bench {
namespace {

struct Entry {
    explicit Entry(std::unique_ptr<Structure> s) : structure(std::move(s)) {}
    std::unique_ptr<Structure> structure;
    double build_seconds = 0.0;
    std::vector<SetTiming> timing;             // per ray set
    std::vector<std::vector<Result>> answers;  // per ray set
    bool brute() const { return structure->name() == "brute"; }
};

// Each structure's build time, the median of `repeats` builds; the builds take turns
// (ours, Embree, ours, ...), as the traced passes do, so that none gets the machine's
// cold start or a quiet spell alone. Brute force is built once.
void time_builds(std::vector<Entry>& entries, const rt::TriangleMesh& mesh, int repeats) {
    std::vector<std::vector<double>> seconds(entries.size());
    for (int k = 0; k < repeats; ++k)
        for (std::size_t i = 0; i < entries.size(); ++i) {
            if (k > 0 && entries[i].brute()) continue;
            entries[i].structure->prepare(mesh);
            const rt::Stopwatch watch;
            entries[i].structure->build();
            seconds[i].push_back(watch.seconds());
        }
    for (std::size_t i = 0; i < entries.size(); ++i) entries[i].build_seconds = median(seconds[i]);
}

// Each structure against the reference: Embree on every ray if there is one, and brute
// force on the rays brute force traced. A mismatch of ours beyond the exact test's
// ambiguous rays fails; one of Embree's against brute force is reported.
struct Verdict {
    bool ok = true;             // every structure of ours right where it differs
    bool embree_wrong = false;  // Embree's wrong somewhere by brute force and the exact test
    const char* line() const {
        if (!ok) return "WRONG ANSWERS (see above)";
        return embree_wrong ? "every structure agrees with the references (Embree's own are wrong "
                              "on some rays, above)"
                            : "every structure agrees with the references";
    }
};

Verdict check(const std::vector<Entry>& entries, const std::vector<RaySet>& sets,
              const rt::TriangleMesh& mesh, nlohmann::json& report) {
    Verdict verdict;
    const ExactTracer exact(mesh);
    const Entry* brute = nullptr;
    const Entry* embree = nullptr;
    for (const Entry& e : entries) {
        if (e.brute()) brute = &e;
        if (e.structure->name() == "embree") embree = &e;
    }
    for (const Entry& e : entries) {
        for (std::size_t s = 0; s < sets.size(); ++s) {
            const std::string name = e.structure->name() + "." + sets[s].name;
            const auto against = [&](const Entry& ref, const char* label) {
                if (&ref == &e) return;
                const Mismatches m = compare(sets[s], e.answers[s], e.timing[s].stride,
                                             ref.answers[s], ref.timing[s].stride, exact);
                report["checks"][name][label] = to_json(m);
                // "of the N arbitrated" where not every disagreement was.
                char sample[96] = "";
                if (m.arbitrated < m.disagreements)
                    std::snprintf(sample, sizeof sample,
                                  " (of %zu of its %zu disagreements, spread evenly)", m.arbitrated,
                                  m.disagreements);
                if (m.ambiguous + m.reference_wrong > 0)
                    std::printf(
                        "%s against %s: %zu rays graze an edge (either answer is right), %s is "
                        "wrong on %zu (exact double-precision test)%s\n",
                        name.c_str(), label, m.ambiguous, label, m.reference_wrong, sample);
                if (!m.ok()) {
                    // Embree's own answers are the reference's, not ours: its default triangle
                    // test is not watertight (a tube of slivers leaks), so where brute force
                    // catches it out that is said, and the run does not fail for it.
                    const bool reference = e.structure->name().starts_with("embree");
                    if (reference)
                        verdict.embree_wrong = true;
                    else
                        verdict.ok = false;
                    std::printf(
                        "%s: %s is wrong where it differs from %s on %zu of %zu rays (%zu "
                        "hit/miss, %zu other hit)%s%s\n",
                        reference ? "Embree" : "WRONG", name.c_str(), label,
                        m.hit_miss + m.wrong_hit, m.checked, m.hit_miss, m.wrong_hit, sample,
                        reference ? " (Intel's library, the reference: not a failure of ours)"
                                  : "");
                }
            };
            if (brute) against(*brute, "brute");
            if (embree) against(*embree, "embree");
        }
    }
    return verdict;
}

// Our wide BVH against Embree with the guarantees ours give (RTC_SCENE_FLAG_ROBUST: a
// watertight triangle test, a conservative box test), where both ran.
void print_against_robust(const std::vector<Entry>& entries, const std::vector<RaySet>& sets,
                          nlohmann::json& report) {
    const Entry *bvh = nullptr, *robust = nullptr;
    for (const Entry& e : entries) {
        if (e.structure->name() == "bvh") bvh = &e;
        if (e.structure->name() == "embree-robust") robust = &e;
    }
    if (!bvh || !robust) return;
    std::printf("bvh against embree-robust (time per ray, the same guarantees):");
    for (std::size_t s = 0; s < sets.size(); ++s) {
        const double ratio = robust->timing[s].mrays_per_s / bvh->timing[s].mrays_per_s;
        std::printf(" %s %.2fx", sets[s].name.c_str(), ratio);
        report["structures"]["bvh"]["rays"][sets[s].name]["embree_robust_time_ratio"] = ratio;
    }
    std::printf("\n");
}

void print_table(const std::vector<Entry>& entries, const std::vector<RaySet>& sets,
                 std::size_t triangles, nlohmann::json& report) {
    const Entry *embree = nullptr, *embree_packets = nullptr;
    for (const Entry& e : entries) {
        if (e.structure->name() == "embree") embree = &e;
        if (e.structure->name() == "embree-packets") embree_packets = &e;
    }
    std::printf("%-14s %10s %12s %11s", "", "build s", "Mtri/s", "memory MB");
    for (const RaySet& set : sets) std::printf(" %10s Mrays/s", set.name.c_str());
    std::printf("\n");
    for (const Entry& e : entries) {
        // Packets against Embree's packets, single rays against its single rays.
        const Entry* ref = e.structure->packets() && embree_packets ? embree_packets : embree;
        nlohmann::json j = {
            {"build_seconds", e.build_seconds},
            {"build_mtris_per_s", static_cast<double>(triangles) / e.build_seconds * 1e-6},
            {"memory_bytes", e.structure->memory_bytes()}};
        std::printf("%-14s %10.4f %12.2f %11.2f", e.structure->name().c_str(), e.build_seconds,
                    static_cast<double>(triangles) / e.build_seconds * 1e-6,
                    static_cast<double>(e.structure->memory_bytes()) / 1e6);
        for (std::size_t s = 0; s < sets.size(); ++s) {
            j["rays"][sets[s].name] = to_json(e.timing[s]);
            const double ratio = ref ? ref->timing[s].mrays_per_s / e.timing[s].mrays_per_s : 0.0;
            if (ref) j["rays"][sets[s].name]["embree_time_ratio"] = ratio;
            std::printf(" %18.2f", e.timing[s].mrays_per_s);
            if (ref && &e != ref) std::printf(" (%4.2fx)", ratio);
        }
        if (e.brute()) std::printf("  [every %zu-th ray]", e.timing[0].stride);
        std::printf("\n");
        report["structures"][e.structure->name()] = j;
    }
    if (embree)
        std::printf(
            "(N.NNx): time per ray relative to Embree's (rtcIntersect1/rtcOccluded1; for -packets, "
            "Embree's %d-ray packets), on the same rays and threads\n",
            rt::kPacketWidth);
    print_against_robust(entries, sets, report);
}

// "sphere:N": a unit sphere tessellated into about N triangles, seen from the front and
// lit from above; anything else is a scene or mesh file.
rt::LoadedScene load(const std::string& name) {
    if (name.rfind("sphere:", 0) != 0) return rt::load_scene(name);
    long long wanted = 0;
    const char* digits = name.c_str() + 7;
    const auto [end, ec] = std::from_chars(digits, name.c_str() + name.size(), wanted);
    if (ec != std::errc{} || *end != '\0' || wanted < 8 || wanted > 50000000)
        throw rt::Error(name, "sphere", "expected sphere:N with N from 8 to 50000000 triangles");
    rt::LoadedScene out;
    const int slices =
        static_cast<int>(std::lround(1.0 + std::sqrt(1.0 + static_cast<double>(wanted))));
    out.scene.meshes.push_back(rt::tessellate_unit_sphere(slices));
    out.scene.objects.push_back(rt::Object{"sphere", rt::MeshRef{0, true}, 0, std::nullopt});
    out.scene.camera =
        rt::Camera::look_at({0.3f, 0.4f, 3.0f}, {0, 0, 0}, {0, 1, 0}, 45.0f, 1280, 720);
    out.scene.lights.push_back(rt::Light{rt::Light::Type::kPoint, {3, 5, 4}, {}, rt::vec3(1.0f)});
    return out;
}

// Every ray set through every entry, brute force on a subset of its rays. Per set, each
// entry's warm-up pass, then its timed passes in turns (ours, Embree, ours, ...; each
// round begins one further along), so that a slow or quiet spell of the machine falls on
// all alike: a structure's passes all run together let such a spell fall on one
// structure alone, and its ratio to Embree moved by 0.1-0.2 between runs.
void trace_sets(std::vector<Entry>& entries, const std::vector<RaySet>& sets,
                const rt::TriangleMesh& mesh, const MeasureOptions& measure) {
    for (Entry& e : entries) {
        e.answers.assign(sets.size(), {});
        e.timing.assign(sets.size(), {});
    }
    for (std::size_t s = 0; s < sets.size(); ++s) {
        std::vector<std::size_t> strides;
        for (Entry& e : entries) {
            strides.push_back(
                stride_for(*e.structure, sets[s].rays.size(), mesh.triangles.size(), measure));
            trace_pass(*e.structure, sets[s], strides.back(), measure.threads, e.answers[s]);
        }
        std::vector<std::vector<double>> seconds(entries.size());
        const std::size_t n = entries.size();
        for (int round = 0; round < measure.repeats; ++round)
            for (std::size_t k = 0; k < n; ++k) {
                const std::size_t i = (k + static_cast<std::size_t>(round)) % n;
                if (round >= repeats_for(strides[i], measure.repeats)) continue;
                seconds[i].push_back(trace_pass(*entries[i].structure, sets[s], strides[i],
                                                measure.threads, entries[i].answers[s]));
            }
        for (std::size_t i = 0; i < n; ++i)
            entries[i].timing[s] = summarise(*entries[i].structure, std::move(seconds[i]),
                                             strides[i], entries[i].answers[s]);
    }
}

// The ray sets, from our BVH's primary hits.
std::vector<RaySet> ray_sets(const Structure& bvh, const rt::Camera& camera,
                             const rt::TriangleMesh& mesh, const std::vector<rt::Light>& lights,
                             const MeasureOptions& measure) {
    std::vector<Result> primary_hits;
    MeasureOptions once = measure;
    once.repeats = 0;
    time_set(bvh, primary_rays(camera), 1, once, primary_hits);
    return make_ray_sets(camera, mesh, lights, primary_hits);
}

void write_json(const std::string& path, const nlohmann::json& report) {
    if (path.empty()) return;
    std::ofstream out(path);
    out << report.dump(2) << '\n';
    if (!out) throw rt::Error(path, "json", "cannot write the file");
}

// --threads-sweep: build and trace rates of our BVH and Embree per thread count.
int run_threads_sweep(const SceneBenchOptions& o, const rt::LoadedScene& loaded,
                      const rt::TriangleMesh& mesh, const rt::Camera& camera) {
    std::printf(
        "%s: %zu triangles, %dx%d camera, median of %d passes (builds: of %d) per "
        "thread count; (N.NNx): time relative to Embree's\n",
        o.scene.c_str(), mesh.triangles.size(), o.width, o.height, o.measure.repeats,
        o.measure.build_repeats);
    std::printf("%7s %22s %14s", "threads", "bvh build Mtri/s", "embree Mtri/s");
    nlohmann::json report = {{"scene", o.scene}, {"triangles", mesh.triangles.size()}};
    std::vector<RaySet> sets;
    bool ok = true, embree_wrong = false;
    for (int threads : o.threads_sweep) {
        MeasureOptions measure = o.measure;
        measure.threads = threads;
        std::vector<Entry> entries;
        entries.emplace_back(make_ours(rt::AccelKind::kBvh, threads));
        if (auto embree = make_embree(threads)) entries.emplace_back(std::move(embree));
        time_builds(entries, mesh, measure.build_repeats);
        if (sets.empty()) {
            sets = ray_sets(*entries[0].structure, camera, mesh, loaded.scene.lights, measure);
            for (const RaySet& set : sets)
                std::printf(" %28s", (set.name + " Mrays/s bvh, embree").c_str());
            std::printf("\n");
        }
        trace_sets(entries, sets, mesh, measure);
        const Entry& bvh = entries[0];
        const Entry* embree = entries.size() > 1 ? &entries[1] : nullptr;
        const auto rate = [&](const Entry& e) {
            return static_cast<double>(mesh.triangles.size()) / e.build_seconds * 1e-6;
        };
        nlohmann::json row = {{"threads", threads}, {"bvh_build_mtris_per_s", rate(bvh)}};
        std::printf("%7d %13.2f", threads, rate(bvh));
        if (embree) {
            std::printf(" (%4.2fx) %14.2f", bvh.build_seconds / embree->build_seconds,
                        rate(*embree));
            row["embree_build_mtris_per_s"] = rate(*embree);
        } else {
            std::printf(" %22s", "-");
        }
        for (std::size_t s = 0; s < sets.size(); ++s) {
            row[sets[s].name]["bvh"] = bvh.timing[s].mrays_per_s;
            if (!embree) {
                std::printf(" %19.2f, -", bvh.timing[s].mrays_per_s);
                continue;
            }
            const double ratio = embree->timing[s].mrays_per_s / bvh.timing[s].mrays_per_s;
            row[sets[s].name]["embree"] = embree->timing[s].mrays_per_s;
            row[sets[s].name]["embree_time_ratio"] = ratio;
            std::printf(" %11.2f (%4.2fx), %8.2f", bvh.timing[s].mrays_per_s, ratio,
                        embree->timing[s].mrays_per_s);
        }
        std::printf("\n");
        nlohmann::json checks;
        const Verdict verdict = check(entries, sets, mesh, checks);
        ok = verdict.ok && ok;
        embree_wrong = embree_wrong || verdict.embree_wrong;
        row["checks"] = checks["checks"];
        report["rows"].push_back(row);
    }
    std::printf("answers: %s\n", Verdict{ok, embree_wrong}.line());
    write_json(o.json, report);
    return ok ? 0 : 1;
}

}  // namespace

int run_scene(const SceneBenchOptions& o) {
    rt::LoadedScene loaded = load(o.scene);
    const rt::TriangleMesh mesh = flatten(loaded.scene);
    if (mesh.triangles.empty())
        throw rt::Error(o.scene, "triangles", "the scene has no triangles to benchmark");
    const rt::Camera camera = loaded.scene.camera.resized(o.width, o.height);
    if (!o.threads_sweep.empty()) return run_threads_sweep(o, loaded, mesh, camera);
    std::printf(
        "%s: %zu triangles, %dx%d camera, %zu lights, %d threads, median of %d passes after a "
        "warm-up; bvh %d-wide, bvh2 binary%s\n",
        o.scene.c_str(), mesh.triangles.size(), o.width, o.height, loaded.scene.lights.size(),
        o.measure.threads, o.measure.repeats, rt::kBvhWidth,
        have_embree() ? "" : " (built without Embree)");

    std::vector<Entry> entries;
    for (rt::AccelKind k :
         {rt::AccelKind::kBrute, rt::AccelKind::kGrid, rt::AccelKind::kBvh2, rt::AccelKind::kBvh})
        entries.emplace_back(make_ours(k, o.measure.threads));
    if (auto embree = make_embree(o.measure.threads)) entries.emplace_back(std::move(embree));
    if (auto robust = make_embree_robust(o.measure.threads))
        entries.emplace_back(std::move(robust));
    entries.emplace_back(make_ours(rt::AccelKind::kBvh, o.measure.threads, true));
    if (auto embree = make_embree(o.measure.threads, true)) entries.emplace_back(std::move(embree));
    if (o.gpu) entries.emplace_back(make_gpu(o.gl));
    // The BVH makes the ray sets; a reference checks every answer, so both always run.
    const std::string reference = have_embree() ? "embree" : "brute";
    const auto wanted = [&](const Entry& e) {
        const std::string name = e.structure->name();
        return o.only.empty() || name == "bvh" || name == reference || name == "gpu" ||
               std::find(o.only.begin(), o.only.end(), name) != o.only.end();
    };
    std::erase_if(entries, [&](const Entry& e) { return !wanted(e); });
    time_builds(entries, mesh, o.measure.build_repeats);

    const auto bvh = std::find_if(entries.begin(), entries.end(),
                                  [](const Entry& e) { return e.structure->name() == "bvh"; });
    const std::vector<RaySet> sets =
        ray_sets(*bvh->structure, camera, mesh, loaded.scene.lights, o.measure);
    trace_sets(entries, sets, mesh, o.measure);
    nlohmann::json report = {{"scene", o.scene},
                             {"triangles", mesh.triangles.size()},
                             {"threads", o.measure.threads},
                             {"width", o.width},
                             {"height", o.height},
                             {"repeats", o.measure.repeats},
                             {"embree", have_embree()}};
    for (const RaySet& set : sets) report["ray_counts"][set.name] = set.rays.size();
    print_table(entries, sets, mesh.triangles.size(), report);
    const Verdict verdict = check(entries, sets, mesh, report);
    if (o.gpu)  // the GPU entry's context is current
        report["gpu_frame"] =
            time_gpu_frame(loaded.scene, camera, o.gpu_frame, o.measure.repeats, o.measure.threads);
    std::printf("answers: %s\n", verdict.line());
    write_json(o.json, report);
    return verdict.ok ? 0 : 1;
}

}  // namespace rt::bench
