// Image files: PNG written and, as textures, read by libpng (core/png_file.h), JPEG
// textures read by libjpeg (core/jpeg_file.h); everything else through the codec module
// (core/image_codec.h), opened with dlopen the first time a program needs it. The program itself
// links no OpenImageIO.
#include <dlfcn.h>

#include <algorithm>
#include <cstddef>
#include <fstream>
#include <iterator>

#include "core/error.h"
#include "core/file_kind.h"
#include "core/image.h"
#include "core/image_codec.h"
#include "core/jpeg_file.h"
#include "core/png_file.h"
#include "core/program_dir.h"
#include "core/texture.h"

namespace rt {
namespace {

struct Loaded {
    const codec::ImageCodec* codec = nullptr;
    std::string error;  // why there is none
};

Loaded load() {
    const std::filesystem::path path =
        find_beside_program(std::filesystem::path("lib") / "rtview" / codec::kModuleName);
    // Never closed: the codec's libraries stay for the process's life.
    void* module = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!module) return {nullptr, dlerror()};
    const auto entry = reinterpret_cast<codec::EntryPoint>(dlsym(module, codec::kEntryPoint));
    if (!entry) return {nullptr, path.string() + ": no " + codec::kEntryPoint};
    const codec::ImageCodec* table = entry();
    if (!table || table->version != codec::kVersion)
        return {nullptr, path.string() + ": from another build of rtview"};
    return {table, {}};
}

const Loaded& loaded() {
    // Made once, by whichever thread asks first; never destroyed, so no exit-time order.
    static const Loaded* const once = new Loaded(load());
    return *once;
}

}  // namespace

const codec::ImageCodec& codec::module(const std::string& file, const std::string& where) {
    const Loaded& l = loaded();
    if (!l.codec)
        throw Error(file, where, "cannot open rtview's image codec (OpenImageIO): " + l.error);
    return *l.codec;
}

namespace {

using codec::module;

void check(const std::string& problem, const std::string& file, const std::string& where) {
    if (!problem.empty()) throw Error(file, where, problem);
}

// PNG and JPEG are decoded here, by libpng and libjpeg; anything else, and a CMYK JPEG, by
// the codec. False where the codec must decode; else `problem` is empty or says what
// went wrong.
bool decode_here(const std::vector<unsigned char>& bytes, codec::Pixels<std::uint8_t>& px,
                 std::string& problem) {
    if (is_png(bytes.data(), bytes.size())) {
        problem = decode_png(bytes.data(), bytes.size(), px);
        return true;
    }
    if (is_jpeg(bytes.data(), bytes.size())) {
        const JpegRead read = decode_jpeg(bytes.data(), bytes.size(), px);
        problem = read.problem;
        return read.handled;
    }
    return false;
}

// Eight bits a channel, sRGB decoded through the same table GL's SRGB8 formats use; a
// grey image is grey, alpha is dropped.
Texture texture_from(const codec::Pixels<std::uint8_t>& px, const std::string& name) {
    Texture t;
    t.name = name;
    t.width = px.width;
    t.height = px.height;
    t.texels.resize(static_cast<std::size_t>(t.width) * t.height);
    const int channels = px.channels;
    for (std::size_t i = 0; i < t.texels.size(); ++i) {
        const std::uint8_t* p = &px.data[i * static_cast<std::size_t>(channels)];
        const auto c = [&](int k) { return p[std::min(k, channels - 1)]; };
        t.texels[i] = channels < 3 ? from_srgb8(c(0), c(0), c(0)) : from_srgb8(c(0), c(1), c(2));
    }
    return t;
}

Texture read_texture_file(const std::filesystem::path& path, const std::string& file,
                          const std::string& where) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error(file, where, "no image file \"" + path.string() + "\"");
    std::ifstream in(path, std::ios::binary);
    const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                           std::istreambuf_iterator<char>());
    codec::Pixels<std::uint8_t> px;
    std::string problem;
    if (!decode_here(bytes, px, problem))
        problem = module(file, where).read_bytes(path.string(), px);
    else if (!problem.empty())
        problem = "cannot read the image \"" + path.string() + "\": " + problem;
    check(problem, file, where);
    return texture_from(px, path.string());
}

Texture decode_texture_bytes(const std::vector<unsigned char>& bytes, const std::string& extension,
                             const std::string& file, const std::string& where) {
    codec::Pixels<std::uint8_t> px;
    std::string problem;
    if (!decode_here(bytes, px, problem))
        problem = module(file, where).decode_bytes(bytes.data(), bytes.size(), extension, px);
    else if (!problem.empty())
        problem = "cannot decode the image: " + problem;
    check(problem, file, where);
    return texture_from(px, file + ": " + where);
}

// Linked into a program (rt_image_io is an object library), this installs the reader
// before main() runs; the module is opened only when a texture is read.
const bool kReaderInstalled =
    (install_image_reader({&read_texture_file, &decode_texture_bytes}), true);

}  // namespace

bool is_supported_output(const std::filesystem::path& path) {
    const std::string ext = lower_extension(path);
    return ext == ".png" || ext == ".exr";
}

void write_image(const Image& image, const std::filesystem::path& path) {
    const std::string file = path.string();
    if (!is_supported_output(path))
        throw Error(file, "output", "unsupported format; use .png or .exr");
    if (image.width <= 0 || image.height <= 0) throw Error(file, "output", "the image is empty");
    if (lower_extension(path) == ".png") {
        const std::vector<std::uint8_t> bytes = to_srgb8(image);
        check(write_png_file(file, image.width, image.height, bytes.data()), file, "output");
        return;
    }
    // The file's top row is the image's last; no copy turned over (a 16384 x 16384 frame
    // is 3 GB).
    const float* top_row = &image.at(0, image.height - 1).x;
    const auto row_step = -3 * static_cast<std::ptrdiff_t>(image.width);
    check(module(file, "output").write_exr(file, image.width, image.height, top_row, row_step),
          file, "output");
}

Image read_image(const std::filesystem::path& path) {
    const std::string file = path.string();
    codec::Pixels<float> px;
    bool encoded = false;
    check(module(file, "input").read_floats(file, px, encoded), file, "input");
    Image image(px.width, px.height);
    for (int y = 0; y < px.height; ++y) {
        for (int x = 0; x < px.width; ++x) {
            const float* p = &px.data[(static_cast<std::size_t>(y) * px.width + x) * px.channels];
            vec3 c;
            for (int k = 0; k < 3; ++k) c[k] = p[std::min(k, px.channels - 1)];
            image.at(x, px.height - 1 - y) =
                encoded ? vec3(srgb_decode(c.x), srgb_decode(c.y), srgb_decode(c.z)) : c;
        }
    }
    return image;
}

}  // namespace rt
