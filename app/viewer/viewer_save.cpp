// F12: the view on screen as a PNG, and from any view the raster, traced and difference
// images behind it (the raster drawn at the traced image's size, so that the three match).
// The window shows the absolute paths for a while; the log has one line per file.
#include <cstdio>

#include "app/gl/gl.h"
#include "app/viewer/viewer.h"
#include "core/compare.h"

namespace rt::viewer {
namespace {

// The first free rtview-N prefix in `dir`.
std::filesystem::path next_prefix(const std::filesystem::path& dir) {
    for (int n = 1;; ++n) {
        const auto prefix = dir / ("rtview-" + std::to_string(n));
        if (!std::filesystem::exists(prefix.string() + ".view.png")) return prefix;
    }
}

void write(const rt::Image& image, const std::string& path) {
    rt::write_image(image, path);
    std::printf("saved: %s\n", path.c_str());
}

// "saved: /abs/rtview-3.view.png\n  .raster.png, ..." for the window.
std::string message(const std::string& prefix, const std::vector<const char*>& kinds) {
    std::string text = "saved: " + prefix + "." + kinds.front() + ".png\n  and";
    for (std::size_t i = 1; i < kinds.size(); ++i)
        text += std::string(i > 1 ? "," : "") + " ." + kinds[i] + ".png";
    return text;
}

}  // namespace

void Viewer::save_view(int width, int height) {
    try {
        std::filesystem::create_directories(options_.save_dir);
        const std::string prefix =
            std::filesystem::absolute(next_prefix(options_.save_dir)).lexically_normal().string();
        // The window's pixels are sRGB already (the compositor encodes); decoding them
        // lets write_image encode them back to the same bytes.
        std::vector<std::uint8_t> bytes(static_cast<std::size_t>(width) * height * 3);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        glReadBuffer(GL_BACK);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bytes.data());
        rt::Image view(width, height);
        for (std::size_t i = 0; i < view.pixels.size(); ++i)
            for (int k = 0; k < 3; ++k)
                view.pixels[i][k] = rt::srgb_decode(static_cast<float>(bytes[3 * i + k]) / 255.0f);
        write(view, prefix + ".view.png");
        const rt::Camera camera = controller_->camera(traced_image_.width, traced_image_.height);
        const rt::Image raster = raster_->render(camera);
        raster_camera_.reset();  // the raster view's texture now holds this pass
        write(raster, prefix + ".raster.png");
        write(traced_image_, prefix + ".trace.png");
        write(rt::difference_image(raster, traced_image_, settings_.diff_scale),
              prefix + ".diff.png");
        std::fflush(stdout);
        saved_ = message(prefix, {"view", "raster", "trace", "diff"});
        if (traced_stale()) saved_ += "\n  (the traced image was still of the previous camera)";
        saved_at_.emplace();
    } catch (const std::exception& e) {
        error_ = std::string("save: ") + e.what();
        std::fprintf(stderr, "%s\n", error_.c_str());
    }
}

}  // namespace rt::viewer
