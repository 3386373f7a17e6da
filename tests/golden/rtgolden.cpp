// rtgolden: compares a new render against its accepted references with OpenImageIO,
// keeps the images of every comparison, and writes an HTML report in the manner of
// Blender's render-test report (reference | new | difference, failures first).
//
//   rtgolden compare NAME NEW.png REFERENCE_DIR REPORT_DIR --fail T --fail-percent P [--as
//   REFERENCE] rtgolden report REPORT_DIR
//
// The references of NAME (or of REFERENCE, when tests share one: EGL and OSMesa) are
// REFERENCE_DIR/NAME.png and any REFERENCE_DIR/NAME.alt*.png
// (another driver that legitimately differs, as in OSL's test suite); the new image
// passes if it matches any of them. With RTVIEW_UPDATE_GOLDEN=1 a failing image becomes
// the new NAME.png.

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <vector>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;
namespace algo = OIIO::ImageBufAlgo;

namespace {

struct Match {
    fs::path reference;
    OIIO::ImageBufAlgo::CompareResults result{};
    double fail_percent = 100.0;
    bool passed = false;
};

std::vector<fs::path> references(const fs::path& dir, const std::string& name) {
    std::vector<fs::path> out;
    if (fs::exists(dir / (name + ".png"))) out.push_back(dir / (name + ".png"));
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        const std::string file = entry.path().filename().string();
        if (file.rfind(name + ".alt", 0) == 0 && entry.path().extension() == ".png")
            out.push_back(entry.path());
    }
    return out;
}

Match compare(const OIIO::ImageBuf& image, const fs::path& reference, float fail,
              double fail_percent) {
    Match m;
    m.reference = reference;
    const OIIO::ImageBuf ref(reference.string());
    if (ref.spec().width != image.spec().width || ref.spec().height != image.spec().height)
        return m;
    m.result = algo::compare(image, ref, fail, fail / 2.0f);
    const double pixels = static_cast<double>(image.spec().width) * image.spec().height;
    m.fail_percent = 100.0 * static_cast<double>(m.result.nfail) / pixels;
    m.passed = !m.result.error && m.fail_percent <= fail_percent;
    return m;
}

// The absolute difference, brightened so that small errors show.
void write_difference(const OIIO::ImageBuf& a, const fs::path& reference, const fs::path& out) {
    const OIIO::ImageBuf ref(reference.string());
    if (ref.spec().width != a.spec().width || ref.spec().height != a.spec().height) return;
    OIIO::ImageBuf diff = algo::mul(algo::absdiff(a, ref), 8.0f);
    diff.write(out.string());
}

int run_compare(const std::string& name, const std::string& ref_name, const fs::path& new_image,
                const fs::path& ref_dir, const fs::path& report_dir, float fail,
                double fail_percent) {
    fs::create_directories(report_dir);
    OIIO::ImageBuf image(new_image.string());
    if (!image.read()) {
        std::cerr << new_image.string() << ": read: " << image.geterror() << '\n';
        return 1;
    }
    Match best;
    for (const fs::path& ref : references(ref_dir, ref_name)) {
        Match m = compare(image, ref, fail, fail_percent);
        if (m.passed || best.reference.empty() || m.fail_percent < best.fail_percent) best = m;
        if (m.passed) break;
    }
    fs::copy_file(new_image, report_dir / (name + ".new.png"),
                  fs::copy_options::overwrite_existing);
    std::string status = best.passed              ? "passed"
                         : best.reference.empty() ? "no reference"
                                                  : "FAILED";
    const char* update = std::getenv("RTVIEW_UPDATE_GOLDEN");
    if (!best.passed && update && std::string(update) == "1") {
        fs::copy_file(new_image, ref_dir / (ref_name + ".png"),
                      fs::copy_options::overwrite_existing);
        status = "updated";
    }
    if (!best.reference.empty()) {
        fs::copy_file(best.reference, report_dir / (name + ".ref.png"),
                      fs::copy_options::overwrite_existing);
        write_difference(image, best.reference, report_dir / (name + ".diff.png"));
    }
    const nlohmann::json record = {{"name", name},
                                   {"status", status},
                                   {"reference", best.reference.filename().string()},
                                   {"fail_threshold", fail},
                                   {"fail_percent_allowed", fail_percent},
                                   {"fail_percent", best.fail_percent},
                                   {"mean_error", best.result.meanerror},
                                   {"max_error", best.result.maxerror},
                                   {"psnr", std::min(best.result.PSNR, 999.0)}};
    std::ofstream(report_dir / (name + ".json")) << record.dump(2);
    std::cout << name << ": " << status << " against "
              << (best.reference.empty() ? "-" : best.reference.string()) << ": "
              << best.fail_percent << "% of pixels over " << fail << " (allowed " << fail_percent
              << "%), max error " << best.result.maxerror << ", mean " << best.result.meanerror
              << '\n';
    if (status != "passed")
        std::cout << "images and report: " << (report_dir / "index.html").string()
                  << " (written when the golden tests end)\n";
    if (status == "no reference")
        std::cout << "make one with: RTVIEW_UPDATE_GOLDEN=1 ctest --test-dir build -L golden\n";
    return status == "passed" || status == "updated" ? 0 : 1;
}

int run_report(const fs::path& report_dir) {
    std::vector<nlohmann::json> records;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(report_dir, ec))
        if (entry.path().extension() == ".json")
            records.push_back(nlohmann::json::parse(std::ifstream(entry.path())));
    std::sort(records.begin(), records.end(), [](const auto& a, const auto& b) {
        const bool fa = a["status"] != "passed", fb = b["status"] != "passed";
        return fa != fb
                   ? fa
                   : a["name"].template get<std::string>() < b["name"].template get<std::string>();
    });
    std::ofstream html(report_dir / "index.html");
    html << "<!doctype html><html><head><meta charset=utf-8><title>rtview screenshot "
            "tests</title><style>"
            "body{font-family:sans-serif;background:#222;color:#ddd}td{padding:4px;vertical-align:"
            "top}"
            "img{width:256px;image-rendering:pixelated}.FAILED,.no{color:#f66}.passed{color:#6c6}</"
            "style></head><body>"
            "<h1>rtview screenshot "
            "tests</h1><table><tr><th>test</th><th>reference</th><th>new</th><th>difference "
            "(x8)</th></tr>\n";
    int failed = 0;
    for (const auto& r : records) {
        const std::string name = r["name"], status = r["status"];
        failed += status != "passed";
        html << "<tr><td><b>" << name << "</b><br><span class=\""
             << status.substr(0, status.find(' ')) << "\">" << status
             << "</span><br>ref: " << r["reference"].get<std::string>() << "<br>"
             << r["fail_percent"].get<double>() << "% over " << r["fail_threshold"].get<double>()
             << "<br>max " << r["max_error"].get<double>() << "</td>"
             << "<td><img src=\"" << name << ".ref.png\"></td><td><img src=\"" << name
             << ".new.png\"></td><td><img src=\"" << name << ".diff.png\"></td></tr>\n";
    }
    html << "</table></body></html>\n";
    std::cout << "screenshot report: " << (report_dir / "index.html").string() << " ("
              << records.size() << " tests, " << failed << " not passed)\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"rtgolden: screenshot comparison against accepted references"};
    app.require_subcommand(1);
    std::string name, ref_name, new_image, ref_dir, report_dir;
    float fail = 0.016f;
    double fail_percent = 1.0;
    auto* cmp = app.add_subcommand("compare", "Compare a new image with its references");
    cmp->add_option("name", name)->required();
    cmp->add_option("new", new_image)->required();
    cmp->add_option("references", ref_dir)->required();
    cmp->add_option("report", report_dir)->required();
    cmp->add_option("--fail", fail, "Per-channel difference that fails a pixel");
    cmp->add_option("--fail-percent", fail_percent, "Share of failing pixels allowed, in percent");
    cmp->add_option("--as", ref_name, "The references' name, when not NAME");
    auto* rep = app.add_subcommand("report", "Write REPORT_DIR/index.html");
    rep->add_option("report", report_dir)->required();
    CLI11_PARSE(app, argc, argv);
    try {
        if (ref_name.empty()) ref_name = name;
        return cmp->parsed()
                   ? run_compare(name, ref_name, new_image, ref_dir, report_dir, fail, fail_percent)
                   : run_report(report_dir);
    } catch (const std::exception& e) {
        std::cerr << "rtgolden: " << e.what() << '\n';
        return 1;
    }
}
