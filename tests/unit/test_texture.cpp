// Textures (core/texture.h): the one sampling rule both pipelines follow, and the loaders
// that give meshes their texture coordinates and materials their images.
#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "core/gltf_loader.h"
#include "core/image.h"
#include "core/image_codec.h"
#include "core/jpeg_file.h"
#include "core/obj_loader.h"
#include "core/png_file.h"
#include "core/scene_loader.h"
#include "core/texture.h"
#include "test_util.h"

namespace rt {
namespace {

// 2 x 2 texels: red, green (top row), blue, white (bottom row).
Texture four_texels(Wrap wrap) {
    Texture t;
    t.width = t.height = 2;
    t.texels = {vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1), vec3(1, 1, 1)};
    t.wrap_u = t.wrap_v = wrap;
    return t;
}

void expect_near(const vec3& a, const vec3& b) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 1e-5f) << k;
}

// Texel centres sit at (i + 1/2) / size and return their texel; between them the four
// neighbours blend bilinearly; v = 0 is the top row.
TEST(Texture, BilinearBetweenTexelCentres) {
    const Texture t = four_texels(Wrap::kClamp);
    expect_near(t.sample({0.25f, 0.25f}), vec3(1, 0, 0));
    expect_near(t.sample({0.75f, 0.25f}), vec3(0, 1, 0));
    expect_near(t.sample({0.25f, 0.75f}), vec3(0, 0, 1));
    expect_near(t.sample({0.5f, 0.25f}), vec3(0.5f, 0.5f, 0));
    expect_near(t.sample({0.5f, 0.5f}), vec3(0.5f, 0.5f, 0.5f));
    expect_near(t.sample({0.375f, 0.25f}), vec3(0.75f, 0.25f, 0));  // a quarter of the way
}

// GL's wrap modes: clamp holds the edge texel, repeat comes round to the other side,
// mirror reflects at each edge; far outside [0, 1] each still gives a texel's colour.
TEST(Texture, WrapModesAsInGl) {
    expect_near(four_texels(Wrap::kClamp).sample({-3.0f, 0.25f}), vec3(1, 0, 0));
    expect_near(four_texels(Wrap::kClamp).sample({0.0f, 0.25f}), vec3(1, 0, 0));
    // At u = 0 repeat blends the first column with the last.
    expect_near(four_texels(Wrap::kRepeat).sample({0.0f, 0.25f}), vec3(0.5f, 0.5f, 0));
    expect_near(four_texels(Wrap::kRepeat).sample({1.25f, 0.25f}), vec3(1, 0, 0));
    expect_near(four_texels(Wrap::kMirror).sample({1.25f, 0.25f}), vec3(0, 1, 0));
    expect_near(four_texels(Wrap::kMirror).sample({-0.25f, 0.25f}), vec3(1, 0, 0));
    expect_near(four_texels(Wrap::kRepeat).sample({1e6f + 0.25f, 0.25f}), vec3(1, 0, 0));
    EXPECT_EQ(wrap_texel(-1, 4, Wrap::kRepeat), 3);
    EXPECT_EQ(wrap_texel(-1, 4, Wrap::kMirror), 0);
    EXPECT_EQ(wrap_texel(5, 4, Wrap::kMirror), 2);
    EXPECT_EQ(wrap_texel(9, 4, Wrap::kClamp), 3);
}

// The shipped textured OBJ: map_Kd read (sRGB decoded: the grid's white lines are
// 235/255 encoded), a coordinate per corner, vt's v turned to the image's downward rows.
TEST(Texture, ObjMapKdAndCoordinates) {
    const MeshFile spot = load_obj(test::source_dir() / "assets" / "models" / "spot.obj");
    ASSERT_EQ(spot.textures.size(), 1u);
    EXPECT_EQ(spot.textures[0].width, 256);
    EXPECT_NEAR(spot.textures[0].at(0, 0).x, srgb_decode(235.0f / 255.0f), 1e-6f);
    ASSERT_EQ(spot.materials.size(), 1u);
    EXPECT_EQ(spot.materials[0].texture, 0u);
    EXPECT_EQ(spot.mesh.corner_uvs.size(), 3 * spot.mesh.triangles.size());
    // spot.obj's first face is 739/1 735/2 736/3; vt 1 is its first vt line.
    std::ifstream in(test::source_dir() / "assets" / "models" / "spot.obj");
    std::string line;
    while (std::getline(in, line) && line.rfind("vt ", 0) != 0) {
    }
    std::istringstream vt(line.substr(3));
    float u = 0, v = 0;
    vt >> u >> v;
    EXPECT_NEAR(spot.mesh.corner_uvs[0].x, u, 1e-6f);
    EXPECT_NEAR(spot.mesh.corner_uvs[0].y, 1.0f - v, 1e-6f);
}

// glTF: the base colour texture decoded from its file (and from a .glb's buffer), its
// sampler's wrap modes, TEXCOORD_0 per corner; a scene joins the textures of its meshes.
TEST(Texture, GltfBaseColourTextures) {
    const auto dir = test::source_dir() / "tests" / "data" / "gltf" / "khronos";
    for (const auto& file : {dir / "BoxTextured" / "BoxTextured.gltf", dir / "BoxTextured.glb"}) {
        const GltfScene box = load_gltf(file);
        ASSERT_EQ(box.geometry.textures.size(), 1u) << file;
        EXPECT_GT(box.geometry.textures[0].width, 1) << file;
        EXPECT_EQ(box.geometry.materials[0].texture, 0u) << file;
        EXPECT_EQ(box.geometry.mesh.corner_uvs.size(), 36u) << file;
    }
    const LoadedScene scene = load_scene(test::scene_path("textured.json"));
    ASSERT_EQ(scene.scene.textures.size(), 1u);
    std::size_t textured = 0;
    for (const Material& m : scene.scene.materials) textured += m.texture == 0u;
    EXPECT_EQ(textured, 1u);
}

std::vector<unsigned char> file_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Bytes placed so that they end where an unreadable page begins: a reader that looks
// past their end stops the test.
class GuardedBytes {
  public:
    GuardedBytes()
        : page_(static_cast<std::size_t>(sysconf(_SC_PAGESIZE))),
          pages_(static_cast<unsigned char*>(mmap(nullptr, 2 * page_, PROT_READ | PROT_WRITE,
                                                  MAP_PRIVATE | MAP_ANONYMOUS, -1, 0))) {
        if (pages_ == MAP_FAILED || mprotect(pages_ + page_, page_, PROT_NONE) != 0)
            throw std::runtime_error("GuardedBytes: no guard page");
    }
    ~GuardedBytes() { munmap(pages_, 2 * page_); }
    GuardedBytes(const GuardedBytes&) = delete;
    GuardedBytes& operator=(const GuardedBytes&) = delete;

    // The first n (at most a page) of `bytes`, ending at the guard.
    const unsigned char* place(const std::vector<unsigned char>& bytes, std::size_t n) {
        if (n > page_ || n > bytes.size()) throw std::runtime_error("GuardedBytes: too many");
        unsigned char* const at = pages_ + page_ - n;
        std::memcpy(at, bytes.data(), n);
        return at;
    }

  private:
    std::size_t page_;
    unsigned char* pages_;
};

// Read as a texture from a file, the bytes are one line naming the file and the image.
void expect_refused_as_texture(const unsigned char* bytes, std::size_t size,
                               const std::string& name) {
    const std::filesystem::path path = std::filesystem::temp_directory_path() / name;
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes), static_cast<std::streamsize>(size));
    try {
        (void)read_texture(path, "scene.obj", "map_Kd");
        ADD_FAILURE() << "read without an error";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.rfind("scene.obj: map_Kd: cannot read the image", 0), 0u) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
    std::filesystem::remove(path);
}

// PNG textures are read by libpng (core/png_file.cpp), so that a textured scene does not
// load OpenImageIO; they must read as OpenImageIO read them before: every colour type and
// bit depth (tests/data/png/make.sh), a tRNS chunk, interlacing, every 16-bit value once,
// the glTF samples' and the shipped textures, from a file and from memory.
TEST(Texture, PngFilesReadAsTheCodecReadsThem) {
    std::vector<std::filesystem::path> files;
    for (const auto& dir : {test::source_dir() / "tests/data", test::source_dir() / "assets"})
        for (const auto& entry : std::filesystem::recursive_directory_iterator(dir))
            if (entry.path().extension() == ".png") files.push_back(entry.path());
    ASSERT_GE(files.size(), 21u);
    const codec::ImageCodec& oiio = codec::module("test", "codec");
    for (const auto& path : files) {
        SCOPED_TRACE(path.string());
        codec::Pixels<std::uint8_t> ours, theirs, from_memory;
        ASSERT_EQ(read_png_file(path.string(), ours), "");
        ASSERT_EQ(oiio.read_bytes(path.string(), theirs), "");
        EXPECT_EQ(ours.width, theirs.width);
        EXPECT_EQ(ours.height, theirs.height);
        ASSERT_EQ(ours.channels, theirs.channels);
        ASSERT_EQ(ours.data.size(), theirs.data.size());
        // OpenImageIO premultiplies the colour by alpha (in linear terms where a gAMA chunk
        // says so); libpng leaves it as stored, which is what a texture whose alpha is not
        // used should show (PNG stores colour unassociated; glTF's opaque mode ignores
        // alpha). So: alpha and opaque pixels alike, the rest no darker than the codec's;
        // files without alpha byte for byte.
        const int channels = ours.channels;
        const bool alpha = channels == 2 || channels == 4;
        std::size_t opaque = 0, translucent = 0;
        for (std::size_t p = 0; p < ours.data.size(); p += static_cast<std::size_t>(channels)) {
            const std::uint8_t a = alpha ? ours.data[p + channels - 1] : 255;
            (a == 255 ? opaque : translucent) += 1;
            for (int k = 0; k < channels; ++k) {
                const std::uint8_t mine = ours.data[p + k], codec = theirs.data[p + k];
                // Opaque at 8 bits may be 65534 of 65535 at 16: a step at most.
                const int most = !alpha || k == channels - 1 ? 0 : a == 255 ? 1 : 255;
                ASSERT_GE(mine, codec) << "pixel " << p / channels << ", channel " << k;
                ASSERT_LE(mine - codec, most) << "pixel " << p / channels << ", channel " << k;
            }
        }
        if (alpha && path.parent_path().filename() == "png") {  // make.sh's: both kinds
            EXPECT_GT(opaque, 0u);
            EXPECT_GT(translucent, 0u);
        }
        const std::vector<unsigned char> bytes = file_bytes(path);
        ASSERT_EQ(decode_png(bytes.data(), bytes.size(), from_memory), "");
        EXPECT_TRUE(from_memory.data == ours.data);
    }
}

// A PNG cut short, or with a broken checksum, is one line naming the file and saying what
// is wrong, from a file and from memory; the signature of another format is not a PNG.
TEST(Texture, ABrokenPngIsOneLineNotACrash) {
    const std::vector<unsigned char> good =
        file_bytes(test::source_dir() / "tests/data/png/rgb8.png");
    std::vector<std::vector<unsigned char>> broken;
    for (std::size_t keep : {8u, 20u, 40u, 100u, 400u, 1000u})
        broken.emplace_back(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(keep));
    broken.push_back(good);
    broken.back()[30] ^= 0x55u;  // inside IHDR or the chunk after it: a checksum that fails
    for (const auto& bytes : broken) {
        SCOPED_TRACE(bytes.size());
        codec::Pixels<std::uint8_t> px;
        const std::string problem = decode_png(bytes.data(), bytes.size(), px);
        EXPECT_NE(problem, "");
        EXPECT_EQ(problem.find('\n'), std::string::npos) << problem;
        expect_refused_as_texture(bytes.data(), bytes.size(), "rtview_broken.png");
    }
    // From memory, nothing past the bytes given is read.
    GuardedBytes guarded;
    for (std::size_t keep = 8; keep <= std::min<std::size_t>(good.size(), 2000); keep += 7) {
        codec::Pixels<std::uint8_t> px;
        EXPECT_NE(decode_png(guarded.place(good, keep), keep, px), "") << keep;
    }
    const unsigned char jpeg[] = {0xff, 0xd8, 0xff, 0xe0, 0, 16, 'J', 'F', 'I', 'F'};
    EXPECT_FALSE(is_png(jpeg, sizeof jpeg));
}

// JPEG textures are read by libjpeg (core/jpeg_file.cpp): each subsampling, progressive,
// with restart markers, grey, at sizes that are not whole blocks (tests/data/jpeg/make.sh),
// byte for byte as OpenImageIO reads them; a CMYK file is left to the codec.
TEST(Texture, JpegFilesReadAsTheCodecReadsThem) {
    const codec::ImageCodec& oiio = codec::module("test", "codec");
    int read = 0, left = 0;
    for (const auto& entry :
         std::filesystem::directory_iterator(test::source_dir() / "tests/data/jpeg")) {
        if (entry.path().extension() != ".jpg") continue;
        SCOPED_TRACE(entry.path().string());
        const std::vector<unsigned char> bytes = file_bytes(entry.path());
        codec::Pixels<std::uint8_t> ours, theirs;
        const JpegRead mine = decode_jpeg(bytes.data(), bytes.size(), ours);
        ASSERT_EQ(oiio.read_bytes(entry.path().string(), theirs), "");
        if (!mine.handled) {
            EXPECT_EQ(entry.path().filename(), "cmyk.jpg");
            ++left;
            continue;
        }
        ++read;
        ASSERT_EQ(mine.problem, "");
        EXPECT_EQ(ours.width, theirs.width);
        EXPECT_EQ(ours.height, theirs.height);
        EXPECT_EQ(ours.channels, theirs.channels);
        EXPECT_TRUE(ours.data == theirs.data);
        // And as a texture, through whichever reader takes it.
        const Texture t = read_texture(entry.path(), "scene.obj", "map_Kd");
        EXPECT_EQ(t.width, theirs.width);
    }
    EXPECT_EQ(read, 7);
    EXPECT_EQ(left, 1);
    EXPECT_EQ(read_texture(test::source_dir() / "tests/data/jpeg/cmyk.jpg", "s", "w").width, 37);
}

// A JPEG cut short was read by OpenImageIO without a word, its missing rows grey: now it
// is one line naming the file, and nothing past the bytes given is read.
TEST(Texture, ACutJpegIsOneLineNotAGreyImage) {
    const std::vector<unsigned char> good =
        file_bytes(test::source_dir() / "tests/data/jpeg/grid.jpg");
    GuardedBytes guarded;
    for (std::size_t keep = 3; keep + 2 < good.size(); keep += 37) {
        SCOPED_TRACE(keep);
        const unsigned char* const at = guarded.place(good, keep);
        codec::Pixels<std::uint8_t> px;
        const JpegRead cut = decode_jpeg(at, keep, px);
        EXPECT_TRUE(cut.handled);
        EXPECT_NE(cut.problem, "");
        EXPECT_EQ(cut.problem.find('\n'), std::string::npos) << cut.problem;
        expect_refused_as_texture(at, keep, "rtview_cut.jpg");
    }
}

}  // namespace
}  // namespace rt
