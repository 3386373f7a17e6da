// rtbench --sweep: time per ray against triangle count, on a tessellated sphere.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <glm/geometric.hpp>

#include "app/bench/modes.h"
#include "core/error.h"
#include "core/stopwatch.h"
#include "core/tessellate.h"

namespace rt::bench {
namespace {

// slices s, stacks s/2: s * s - 2 s triangles.
int slices_for(int triangles) {
    return static_cast<int>(std::lround(1.0 + std::sqrt(1.0 + triangles)));
}

struct Row {
    std::size_t triangles;
    std::string structure;
    double ns_per_ray;
};

// `text` as one word for the shell, and as a string in gnuplot's single quotes: paths
// with spaces or quotes in them are the user's to choose.
std::string shell_quoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}
std::string gnuplot_quoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}

void write_plot(const SweepOptions& o, const std::vector<Row>& rows) {
    // gnuplot wants one block per line: the rows grouped by structure. Its data and
    // script go beside the plot and are removed after it.
    const std::string data = o.png + ".dat", script = o.png + ".gnuplot";
    std::vector<std::string> names;
    for (const Row& r : rows)
        if (std::find(names.begin(), names.end(), r.structure) == names.end())
            names.push_back(r.structure);
    std::ofstream dat(data);
    for (const std::string& name : names) {
        dat << "\"" << name << "\"\n";
        for (const Row& r : rows)
            if (r.structure == name) dat << r.triangles << ' ' << r.ns_per_ray << '\n';
        dat << "\n\n";
    }
    dat.close();
    std::ofstream gp(script);
    gp << "set terminal pngcairo size 900,600 font ',11'\n"
       << "set output " << gnuplot_quoted(o.png) << "\n"
       << "set title 'rtbench --sweep: primary rays on a tessellated sphere'\n"
       << "set logscale xy\nset xlabel 'triangles'\nset ylabel 'nanoseconds per ray (2 "
          "threads)'\nset grid\n"
       << "set key left top\n"
       << "plot for [i=0:" << names.size() - 1 << "] " << gnuplot_quoted(data)
       << " index i using 1:2 with linespoints lw 2 title columnheader(1)\n";
    gp.close();
    const bool plotted =
        std::system(("gnuplot " + shell_quoted(script) + " 2>/dev/null").c_str()) == 0;
    std::error_code ignored;
    std::filesystem::remove(data, ignored);
    std::filesystem::remove(script, ignored);
    if (plotted)
        std::printf("plot: %s\n", o.png.c_str());
    else
        std::printf("no plot: gnuplot is missing or failed (the CSV is there)\n");
}

// Each structure's passes alternate with the others': round k times one pass of each
// (after its warm-up), and each reports its median over the rounds. This machine's load
// changes within seconds; timing one structure's passes and then the next's put that
// change into their ratio (the 1M-triangle row gave bvh/embree 1.05x to 1.45x in three
// runs so). The ratio to Embree is printed beside each row.
std::vector<double> alternating_ns(const std::vector<std::unique_ptr<Structure>>& structures,
                                   const RaySet& rays, std::size_t triangles,
                                   const MeasureOptions& measure) {
    MeasureOptions one = measure;
    one.repeats = 1;
    std::vector<std::vector<double>> ns(structures.size());
    for (int round = 0; round < std::max(1, measure.repeats); ++round) {
        for (std::size_t i = 0; i < structures.size(); ++i) {
            const Structure& s = *structures[i];
            const std::size_t stride = stride_for(s, rays.rays.size(), triangles, measure);
            std::vector<Result> answers;
            const SetTiming t = time_set(s, rays, stride, one, answers);
            ns[i].push_back(1e9 * t.seconds / static_cast<double>(t.rays));
        }
    }
    std::vector<double> medians;
    for (auto& v : ns) medians.push_back(median(std::move(v)));
    return medians;
}

}  // namespace

int run_sweep(const SweepOptions& o) {
    std::ofstream csv(o.csv);
    if (!csv) throw rt::Error(o.csv, "csv", "cannot write the file");
    csv << "triangles,structure,ns_per_ray,build_seconds,memory_bytes,ratio_to_embree\n";
    std::printf("%10s %-8s %12s %10s %10s\n", "triangles", "", "ns/ray", "build s", "x embree");
    std::vector<Row> rows;
    for (int wanted : o.triangle_counts) {
        const rt::TriangleMesh sphere = rt::tessellate_unit_sphere(slices_for(wanted));
        const rt::Camera camera =
            rt::Camera::look_at({0.3f, 0.4f, 3.0f}, {0, 0, 0}, {0, 1, 0}, 45.0f, o.width, o.height);
        const RaySet primary = primary_rays(camera);
        std::vector<std::unique_ptr<Structure>> structures;
        for (rt::AccelKind k : {rt::AccelKind::kBrute, rt::AccelKind::kGrid, rt::AccelKind::kBvh2,
                                rt::AccelKind::kBvh})
            structures.push_back(make_ours(k, o.measure.threads));
        if (auto embree = make_embree(o.measure.threads)) structures.push_back(std::move(embree));
        std::vector<double> build;
        for (auto& s : structures) {
            s->prepare(sphere);
            const rt::Stopwatch watch;
            s->build();
            build.push_back(watch.seconds());
        }
        const std::vector<double> ns =
            alternating_ns(structures, primary, sphere.triangles.size(), o.measure);
        const double embree = structures.back()->name() == "embree" ? ns.back() : 0.0;
        for (std::size_t i = 0; i < structures.size(); ++i) {
            const Structure& s = *structures[i];
            const double ratio = embree > 0.0 ? ns[i] / embree : 0.0;
            rows.push_back({sphere.triangles.size(), s.name(), ns[i]});
            csv << sphere.triangles.size() << ',' << s.name() << ',' << ns[i] << ',' << build[i]
                << ',' << s.memory_bytes() << ',' << ratio << '\n';
            std::printf("%10zu %-8s %12.1f %10.4f", sphere.triangles.size(), s.name().c_str(),
                        ns[i], build[i]);
            if (ratio > 0.0) std::printf(" %9.2fx", ratio);  // none without Embree
            std::printf("\n");
        }
    }
    csv.close();
    std::printf("data: %s\n", o.csv.c_str());
    write_plot(o, rows);
    return 0;
}

}  // namespace rt::bench
