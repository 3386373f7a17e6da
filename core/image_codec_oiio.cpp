// The image codec module (core/image_codec.h): the only file of rtview that touches
// OpenImageIO. Built as a shared module of its own and opened with dlopen when a program
// first reads or writes an image file; it links nothing of rtview's.
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <memory>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "core/image_codec.h"

namespace rt::codec {
namespace {

// libpng and libjpeg write their own diagnostics to stderr before OpenImageIO reports the
// error; the user sees one line, ours. Decoding runs while a scene loads, on one thread.
class QuietStderr {
  public:
    QuietStderr() {
        std::fflush(stderr);
        saved_ = dup(STDERR_FILENO);
        const int null = open("/dev/null", O_WRONLY);
        if (null >= 0) {
            dup2(null, STDERR_FILENO);
            close(null);
        }
    }
    ~QuietStderr() {
        std::fflush(stderr);
        if (saved_ >= 0) {
            dup2(saved_, STDERR_FILENO);
            close(saved_);
        }
    }
    QuietStderr(const QuietStderr&) = delete;
    QuietStderr& operator=(const QuietStderr&) = delete;

  private:
    int saved_ = -1;
};

// rtview's images are a frame or a texture, read or written once: OpenImageIO and
// OpenEXR do that work on the calling thread. Left to themselves they start pools of
// threads of their own for it (two more for one small EXR file here), which then end
// only while the process exits. Set when the module is opened, before its first call.
[[maybe_unused]] const bool kOnTheCallersThread = [] {
    OIIO::attribute("threads", 1);
    OIIO::attribute("exr_threads", -1);  // -1: no OpenEXR thread pool at all
    return true;
}();

// OpenImageIO's messages may run over several lines; the last says what went wrong.
std::string last_line(std::string message) {
    while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
        message.pop_back();
    const std::size_t nl = message.rfind('\n');
    return nl == std::string::npos ? message : message.substr(nl + 1);
}

std::string write_exr(const std::string& path, int width, int height, const float* top_row,
                      std::ptrdiff_t row_step) {
    OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::HALF);
    spec.attribute("oiio:ColorSpace", "Linear");
    auto out = OIIO::ImageOutput::create(path);
    if (!out) return last_line(OIIO::geterror());
    const auto pixel = static_cast<OIIO::stride_t>(3 * sizeof(float));
    const auto row =
        static_cast<OIIO::stride_t>(row_step * static_cast<std::ptrdiff_t>(sizeof(float)));
    if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, top_row, pixel, row) ||
        !out->close())
        return last_line(out->geterror());
    return {};
}

std::string read_floats(const std::string& path, Pixels<float>& out, bool& encoded) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return last_line(OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    out.width = spec.width, out.height = spec.height, out.channels = spec.nchannels;
    out.data.resize(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, out.data.data()))
        return last_line(in->geterror());
    encoded = spec.format.basetype == OIIO::TypeDesc::UINT8;
    return {};
}

std::string bytes_from(OIIO::ImageInput& in, Pixels<std::uint8_t>& out) {
    const OIIO::ImageSpec& spec = in.spec();
    if (spec.width <= 0 || spec.height <= 0 ||
        static_cast<long long>(spec.width) * spec.height > kMaxTexels)
        return "the image is " + std::to_string(spec.width) + " x " + std::to_string(spec.height) +
               " (at most 8192 x 8192)";
    out.width = spec.width, out.height = spec.height, out.channels = spec.nchannels;
    out.data.resize(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
    if (!in.read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, out.data.data()))
        return last_line(in.geterror());
    return {};
}

std::string read_bytes(const std::string& path, Pixels<std::uint8_t>& out) {
    const QuietStderr quiet;
    auto in = OIIO::ImageInput::open(path);
    if (!in) return "cannot read the image \"" + path + "\": " + last_line(OIIO::geterror());
    return bytes_from(*in, out);
}

std::string decode_bytes(const unsigned char* bytes, std::size_t size, const std::string& extension,
                         Pixels<std::uint8_t>& out) {
    const QuietStderr quiet;
    OIIO::Filesystem::IOMemReader reader(bytes, size);
    auto in = OIIO::ImageInput::open("image" + extension, nullptr, &reader);
    if (!in) return "cannot decode the image: " + last_line(OIIO::geterror());
    return bytes_from(*in, out);
}

const ImageCodec kCodec{kVersion, &write_exr, &read_floats, &read_bytes, &decode_bytes};

}  // namespace
}  // namespace rt::codec

extern "C" __attribute__((visibility("default"))) const rt::codec::ImageCodec*
rtview_image_codec() {
    return &rt::codec::kCodec;
}
