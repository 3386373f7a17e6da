// The only file of core that touches OpenImageIO.
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "core/error.h"
#include "core/file_kind.h"
#include "core/image.h"
#include "core/texture.h"

namespace rt {

bool is_supported_output(const std::filesystem::path& path) {
    const std::string ext = lower_extension(path);
    return ext == ".png" || ext == ".exr";
}

void write_image(const Image& image, const std::filesystem::path& path) {
    const std::string file = path.string();
    if (!is_supported_output(path))
        throw Error(file, "output", "unsupported format; use .png or .exr");
    auto out = OIIO::ImageOutput::create(file);
    if (!out) throw Error(file, "output", OIIO::geterror());

    bool ok = false;
    if (lower_extension(path) == ".png") {
        OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
        // One row filter (libpng's PNG_FILTER_SUB), not libpng's trial of all five on every
        // row: half the encoder's instructions for a 1280 x 720 frame (451 M -> 223 M), and
        // files as small (the golden images: 0.99 x in all; docs/BENCHMARKS.md).
        spec.attribute("png:filter", 0x10);
        const std::vector<std::uint8_t> bytes = to_srgb8(image);
        ok = out->open(file, spec) && out->write_image(OIIO::TypeDesc::UINT8, bytes.data());
    } else {
        OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::HALF);
        spec.attribute("oiio:ColorSpace", "Linear");
        // Bottom row first in memory: hand OIIO the last row and a negative row stride.
        const auto row = static_cast<OIIO::stride_t>(sizeof(vec3)) * image.width;
        const auto* last_row = reinterpret_cast<const float*>(image.pixels.data()) +
                               static_cast<std::size_t>(image.height - 1) * image.width * 3;
        ok = out->open(file, spec) &&
             out->write_image(OIIO::TypeDesc::FLOAT, last_row, sizeof(vec3), -row);
    }
    if (!ok) throw Error(file, "output", out->geterror());
    if (!out->close()) throw Error(file, "output", out->geterror());
}

Image read_image(const std::filesystem::path& path) {
    const std::string file = path.string();
    auto in = OIIO::ImageInput::open(file);
    if (!in) throw Error(file, "input", OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    std::vector<float> data(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, data.data()))
        throw Error(file, "input", in->geterror());
    const bool encoded = spec.format.basetype == OIIO::TypeDesc::UINT8;
    Image image(spec.width, spec.height);
    for (int y = 0; y < spec.height; ++y) {
        for (int x = 0; x < spec.width; ++x) {
            const float* px =
                &data[(static_cast<std::size_t>(y) * spec.width + x) * spec.nchannels];
            vec3 c;
            for (int k = 0; k < 3; ++k) c[k] = px[std::min(k, spec.nchannels - 1)];
            image.at(x, spec.height - 1 - y) =
                encoded ? vec3(srgb_decode(c.x), srgb_decode(c.y), srgb_decode(c.z)) : c;
        }
    }
    return image;
}

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

// OpenImageIO's messages may run over several lines; the last says what went wrong.
std::string last_line(std::string message) {
    while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
        message.pop_back();
    const std::size_t nl = message.rfind('\n');
    return nl == std::string::npos ? message : message.substr(nl + 1);
}

// Eight bits a channel, sRGB decoded through the same table GL's SRGB8 formats use; a
// grey image is grey, alpha is dropped.
Texture texture_from(OIIO::ImageInput& in, const std::string& name, const std::string& file,
                     const std::string& where) {
    const OIIO::ImageSpec& spec = in.spec();
    constexpr long long kMaxTexels = 1ll << 26;  // 8192 x 8192
    if (spec.width <= 0 || spec.height <= 0 ||
        static_cast<long long>(spec.width) * spec.height > kMaxTexels)
        throw Error(file, where,
                    "the image is " + std::to_string(spec.width) + " x " +
                        std::to_string(spec.height) + " (at most 8192 x 8192)");
    const int channels = spec.nchannels;
    std::vector<unsigned char> data(static_cast<std::size_t>(spec.width) * spec.height * channels);
    if (!in.read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, data.data()))
        throw Error(file, where, last_line(in.geterror()));
    Texture t;
    t.name = name;
    t.width = spec.width;
    t.height = spec.height;
    t.texels.resize(static_cast<std::size_t>(t.width) * t.height);
    for (std::size_t i = 0; i < t.texels.size(); ++i) {
        const unsigned char* px = &data[i * static_cast<std::size_t>(channels)];
        const auto c = [&](int k) { return px[std::min(k, channels - 1)]; };
        t.texels[i] = channels < 3 ? from_srgb8(c(0), c(0), c(0)) : from_srgb8(c(0), c(1), c(2));
    }
    return t;
}

Texture read_texture_file(const std::filesystem::path& path, const std::string& file,
                          const std::string& where) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error(file, where, "no image file \"" + path.string() + "\"");
    const QuietStderr quiet;
    auto in = OIIO::ImageInput::open(path.string());
    if (!in)
        throw Error(
            file, where,
            "cannot read the image \"" + path.string() + "\": " + last_line(OIIO::geterror()));
    return texture_from(*in, path.string(), file, where);
}

Texture decode_texture_bytes(const std::vector<unsigned char>& bytes, const std::string& extension,
                             const std::string& file, const std::string& where) {
    const QuietStderr quiet;
    OIIO::Filesystem::IOMemReader reader(bytes.data(), bytes.size());
    auto in = OIIO::ImageInput::open("image" + extension, nullptr, &reader);
    if (!in) throw Error(file, where, "cannot decode the image: " + last_line(OIIO::geterror()));
    return texture_from(*in, file + ": " + where, file, where);
}

// Linked into a program (rt_image_io is an object library), this installs the reader
// before main() runs.
const bool kReaderInstalled =
    (install_image_reader({&read_texture_file, &decode_texture_bytes}), true);

}  // namespace

}  // namespace rt
