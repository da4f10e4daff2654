// Image maps: GIF palette decoding, the mappings and lookups of
// scene::ImageMap, and the image_map / image_pattern / bump_map parser
// (gamma rules, filter and transmit, errors).
#include "scene/image_map.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "image/gif_decoder.h"
#include "parse_support.h"
#include "scene/object.h"
#include "scene/texture.h"

namespace frameray {
namespace {

// A GIF of 9-bit LZW codes with a clear code every 254 pixels, so the code
// table never grows past 9 bits (the same trick the scene images use).
std::vector<uint8_t> tinyGif(int w, int h, const std::vector<uint8_t>& indices,
                             const std::vector<std::array<uint8_t, 3>>& palette) {
    std::vector<uint8_t> out = {'G', 'I', 'F', '8', '9', 'a'};
    auto u16 = [&out](int v) {
        out.push_back(static_cast<uint8_t>(v & 255));
        out.push_back(static_cast<uint8_t>(v >> 8));
    };
    u16(w);
    u16(h);
    out.insert(out.end(), {0xF7, 0, 0});
    for (int i = 0; i < 256; ++i) {
        const auto c = i < static_cast<int>(palette.size()) ? palette[static_cast<size_t>(i)]
                                                            : std::array<uint8_t, 3>{};
        out.insert(out.end(), c.begin(), c.end());
    }
    out.push_back(',');
    u16(0);
    u16(0);
    u16(w);
    u16(h);
    out.push_back(0);
    std::vector<int> codes;
    for (size_t i = 0; i < indices.size(); ++i) {
        if (i % 254 == 0) codes.push_back(256);
        codes.push_back(indices[i]);
    }
    codes.push_back(257);
    std::vector<uint8_t> packed;
    uint32_t bits = 0;
    int count = 0;
    for (int c : codes) {
        bits |= static_cast<uint32_t>(c) << count;
        count += 9;
        while (count >= 8) {
            packed.push_back(static_cast<uint8_t>(bits & 255));
            bits >>= 8;
            count -= 8;
        }
    }
    if (count) packed.push_back(static_cast<uint8_t>(bits & 255));
    out.push_back(8);
    for (size_t i = 0; i < packed.size(); i += 255) {
        const size_t n = std::min<size_t>(255, packed.size() - i);
        out.push_back(static_cast<uint8_t>(n));
        out.insert(out.end(), packed.begin() + static_cast<std::ptrdiff_t>(i),
                   packed.begin() + static_cast<std::ptrdiff_t>(i + n));
    }
    out.push_back(0);
    out.push_back(';');
    return out;
}

TEST(GifDecoder, ReadsIndicesAndPalette) {
    std::vector<uint8_t> indices;
    for (int i = 0; i < 600; ++i) indices.push_back(static_cast<uint8_t>((i * 7) % 5));
    const auto gif =
        tinyGif(30, 20, indices, {{1, 2, 3}, {4, 5, 6}, {7, 8, 9}, {10, 11, 12}, {13, 14, 15}});
    const image::PaletteImage img = image::decodeGif(gif);
    EXPECT_EQ(img.width, 30);
    EXPECT_EQ(img.height, 20);
    EXPECT_EQ(img.indices, indices);
    ASSERT_EQ(img.palette.size(), 256u);
    EXPECT_EQ(img.palette[4], (std::array<uint8_t, 3>{13, 14, 15}));
}

TEST(GifDecoder, RejectsOtherFiles) {
    EXPECT_THROW(image::decodeGif({'P', '6', '\n'}), std::runtime_error);
}

// A float image of `channels` channels holding `values` row by row.
std::shared_ptr<util::PixelBuffer> floatImage(int w, int h, int channels,
                                              const std::vector<float>& values) {
    auto px = std::make_shared<util::PixelBuffer>(w, h, channels, util::PixelBuffer::Sample::F32);
    std::copy(values.begin(), values.end(), reinterpret_cast<float*>(px->data()));
    return px;
}

// A 2 x 2 map: top row red, green; bottom row blue, white (as colours);
// grey 0, 0.25, 0.5, 1 (as scalars).
scene::ImageMap twoByTwo(scene::ImageMapping mapping, bool once,
                         scene::ImageInterpolation interp = scene::ImageInterpolation::None,
                         bool scalars = false) {
    if (scalars)
        return scene::ImageMap(
            std::make_shared<scene::ImageTexels>(floatImage(2, 2, 1, {0.0f, 0.25f, 0.5f, 1.0f}),
                                                 scene::ImageTexels::Scalar::Grey),
            mapping, once, interp);
    const auto px = floatImage(2, 2, 3, {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1});
    return scene::ImageMap(
        std::make_shared<scene::ImageTexels>(px, scene::ImageTexels::ColorDecoding{}), mapping,
        once, interp);
}

TEST(ImageMap, PlanarPutsTheTopRowAtYOne) {
    const auto m = twoByTwo(scene::ImageMapping::Planar, false);
    EXPECT_EQ(m.colorAt({0.25, 0.75, 3}).rgb.r, 1.0);   // top left: red
    EXPECT_EQ(m.colorAt({0.75, 0.75, 0}).rgb.g, 1.0);   // top right: green
    EXPECT_EQ(m.colorAt({0.25, 0.25, 0}).rgb.b, 1.0);   // bottom left: blue
    EXPECT_EQ(m.colorAt({-0.75, 1.75, 0}).rgb.r, 1.0);  // repeats
    const auto g =
        twoByTwo(scene::ImageMapping::Planar, false, scene::ImageInterpolation::None, true);
    EXPECT_DOUBLE_EQ(g.valueAt({0.75, 0.25, 0}), 1.0);
}

TEST(ImageMap, OnceIsTransparentOutsideTheUnitSquare) {
    const auto m = twoByTwo(scene::ImageMapping::Planar, true);
    EXPECT_EQ(m.colorAt({1.25, 0.5, 0}).transmit, 1.0);
    EXPECT_EQ(m.colorAt({0.25, -0.1, 0}).transmit, 1.0);
    EXPECT_EQ(m.colorAt({0.25, 0.75, 0}).transmit, 0.0);
}

TEST(ImageMap, BilinearReachesTexelColoursAtTheirCentres) {
    const auto m = twoByTwo(scene::ImageMapping::Planar, true, scene::ImageInterpolation::Bilinear);
    EXPECT_NEAR(m.colorAt({0.25, 0.75, 0}).rgb.r, 1.0, 1e-12);
    const Color mid = m.colorAt({0.5, 0.75, 0});
    EXPECT_NEAR(mid.rgb.r, 0.5, 1e-12);
    EXPECT_NEAR(mid.rgb.g, 0.5, 1e-12);
    // once clamps at the edges instead of wrapping.
    EXPECT_NEAR(m.colorAt({0.01, 0.75, 0}).rgb.r, 1.0, 1e-12);
}

TEST(ImageMap, NormalizedDistanceWeighsByInverseSquareDistance) {
    const auto m = twoByTwo(scene::ImageMapping::Planar, false,
                            scene::ImageInterpolation::NormalizedDistance, true);
    // Half way between the two texels of a row (and on the row's centre):
    // the row's texels at distance 0.5, the other row's at sqrt(1.25).
    const double near = 1 / 0.25, far = 1 / 1.25;
    const double expected =
        (0.0 * near + 0.25 * near + 0.5 * far + 1.0 * far) / (2 * near + 2 * far);
    EXPECT_NEAR(m.valueAt({0.5, 0.75, 0}), expected, 1e-12);
}

TEST(ImageMap, SphericalAndTorusCoordinates) {
    const auto s = twoByTwo(scene::ImageMapping::Spherical, false);
    double u, v;
    ASSERT_TRUE(s.imageCoordinates({2, 0, 0}, u, v));
    EXPECT_NEAR(u, 0.0, 1e-12);
    EXPECT_NEAR(v, 0.5, 1e-12);
    ASSERT_TRUE(s.imageCoordinates({0, 0, 1}, u, v));
    EXPECT_NEAR(u, 0.25, 1e-12);
    ASSERT_TRUE(s.imageCoordinates({0, 3, 0}, u, v));
    EXPECT_NEAR(v, 1.0, 1e-12);
    const auto c = twoByTwo(scene::ImageMapping::Cylindrical, true);
    EXPECT_FALSE(c.imageCoordinates({1, 1.5, 0}, u, v));
    ASSERT_TRUE(c.imageCoordinates({-1, 0.3, 0}, u, v));
    EXPECT_NEAR(u, 0.5, 1e-12);
    EXPECT_NEAR(v, 0.3, 1e-12);
    const auto t = twoByTwo(scene::ImageMapping::Torus, false);
    ASSERT_TRUE(t.imageCoordinates({1.5, 0, 0}, u, v));  // outer rim
    EXPECT_NEAR(v, 0.5, 1e-12);
    ASSERT_TRUE(t.imageCoordinates({1, -0.5, 0}, u, v));  // underneath
    EXPECT_NEAR(v, 0.25, 1e-12);
}

// 4 x 4 heights rising by 0.1 per column (x) and 0.2 per row down.
scene::ImageMap ramp() {
    std::vector<float> values;
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) values.push_back(static_cast<float>(0.1 * x + 0.2 * y));
    auto t = std::make_shared<scene::ImageTexels>(floatImage(4, 4, 1, values),
                                                  scene::ImageTexels::Scalar::Grey);
    return scene::ImageMap(t, scene::ImageMapping::Planar, false, scene::ImageInterpolation::None);
}

TEST(BumpMap, TiltsAcrossAndDownTheImageInTheNormalsFrame) {
    const auto m = ramp();
    const Vec3 p(0.4, 0.6, 0);  // texel (1, 1): every neighbour inside the image
    // Facing -z: across is +x, down is +y; heights rise towards +x and
    // down the image, so the normal leans to -x and +y.
    Vec3 n = scene::bumpMapNormal(m, 0.5, p, {0, 0, -1});
    Vec3 expected = normalize(Vec3(-0.5 * 0.1, 0.5 * 0.2, -1));
    EXPECT_NEAR(n.x, expected.x, 1e-6);
    EXPECT_NEAR(n.y, expected.y, 1e-6);
    EXPECT_NEAR(n.z, expected.z, 1e-6);
    // Facing +z, across flips to -x (n x y).
    n = scene::bumpMapNormal(m, 0.5, p, {0, 0, 1});
    EXPECT_NEAR(n.x, 0.05 / std::sqrt(1 + 0.05 * 0.05 + 0.1 * 0.1), 1e-6);
    // A vertical normal falls back to x across; down is x cross n.
    n = scene::bumpMapNormal(m, 0.5, p, {0, 1, 0});
    expected = normalize(Vec3(-0.05, 1, 0.1));
    EXPECT_NEAR(n.x, expected.x, 1e-6);
    EXPECT_NEAR(n.z, expected.z, 1e-6);
}

// Scene files beside the test's image files.
class ImageMapParse : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() /
               ("frameray_image_map_test_" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir_);
        std::ofstream(dir_ / "g.ppm", std::ios::binary)
            << "P6\n2 1\n255\n"
            << '\x40' << '\x40' << '\x40' << '\xff' << '\x00' << '\x00';
        // The same pixels as an 8-bit grey+colour PNG is more work to
        // write here; a GIF stands in for the sRGB formats.
        const auto gif = tinyGif(2, 1, {0, 1}, {{64, 64, 64}, {255, 0, 0}});
        std::ofstream(dir_ / "p.gif", std::ios::binary)
            .write(reinterpret_cast<const char*>(gif.data()),
                   static_cast<std::streamsize>(gif.size()));
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }
    std::string path(const char* name) const { return (dir_ / name).string(); }
    Color pigmentAt(const std::string& pigment, const Vec3& p) {
        test_support::ParsedScene s(
            "#version 3.7; global_settings { assumed_gamma 1 }\n"
            "sphere { 0, 1 pigment { " +
            pigment + " } }");
        return s.scene.objects.at(0)->texture->pigment->at(p);
    }
    std::filesystem::path dir_;
};

TEST_F(ImageMapParse, PpmIsLinearAndGifIsSrgb) {
    const Color ppm = pigmentAt("image_map { ppm \"" + path("g.ppm") + "\" }", {0.25, 0.5, 0});
    EXPECT_NEAR(ppm.rgb.r, 64 / 255.0, 1e-6);
    const Color gif = pigmentAt("image_map { gif \"" + path("p.gif") + "\" }", {0.25, 0.5, 0});
    EXPECT_NEAR(gif.rgb.r, 0.0512695, 1e-5);  // sRGB 64 in linear light
    const Color g1 =
        pigmentAt("image_map { gif \"" + path("p.gif") + "\" gamma 1 }", {0.25, 0.5, 0});
    EXPECT_NEAR(g1.rgb.r, 64 / 255.0, 1e-6);
}

TEST_F(ImageMapParse, PaletteFilterAndTransmit) {
    const std::string file = path("p.gif");
    const Color c =
        pigmentAt("image_map { gif \"" + file + "\" filter all 0.5 filter 1, 0.2 transmit 1, 0.7 }",
                  {0.75, 0.5, 0});
    EXPECT_DOUBLE_EQ(c.filter, 0.2);
    EXPECT_DOUBLE_EQ(c.transmit, 0.7);
    const Color d = pigmentAt("image_map { gif \"" + file + "\" filter 1, 0.2 filter all 0.5 }",
                              {0.75, 0.5, 0});
    EXPECT_DOUBLE_EQ(d.filter, 0.5);
    const Color e =
        pigmentAt("image_map { ppm \"" + path("g.ppm") + "\" transmit all 0.25 }", {0.75, 0.5, 0});
    EXPECT_DOUBLE_EQ(e.transmit, 0.25);
}

TEST_F(ImageMapParse, ImagePatternUsesTheFileGreyValue) {
    const Color c = pigmentAt(
        "image_pattern { ppm \"" + path("g.ppm") + "\" } color_map { [0 rgb 0] [1 rgb 1] }",
        {0.75, 0.5, 0});
    EXPECT_NEAR(c.rgb.r, 0.297, 1e-6);
}

TEST_F(ImageMapParse, BumpMapUseIndexTakesRawIndices) {
    test_support::ParsedScene s("#version 3.7; sphere { 0, 1 normal { bump_map { gif \"" +
                                path("p.gif") + "\" use_index bump_size 2 } } }");
    const auto& normal = s.scene.objects.at(0)->texture->normal;
    ASSERT_TRUE(normal && normal->bumpMap);
    EXPECT_DOUBLE_EQ(normal->amount, 2.0);
    EXPECT_DOUBLE_EQ(normal->bumpMap->texelValue(1, 0), 1.0);
}

TEST_F(ImageMapParse, MaxExtentOfAnImageMapIsItsResolution) {
    test_support::ParsedScene s("#version 3.7; #declare P = pigment { image_map { ppm \"" +
                                path("g.ppm") + "\" } }; #declare R = max_extent(P);");
    const auto r = std::get<sdl::VectorValue>(*s.interp.lookup("R")).xyz();
    EXPECT_EQ(r.x, 2);
    EXPECT_EQ(r.y, 1);
    EXPECT_EQ(r.z, 0);
    const std::string error =
        test_support::parseErrorOf("#declare P = pigment { rgb 1 }; #declare R = max_extent(P);");
    EXPECT_NE(error.find("must be an image map pigment"), std::string::npos);
}

TEST_F(ImageMapParse, Errors) {
    using test_support::parseErrorOf;
    const std::string ppm = path("g.ppm");
    auto scene = [](const std::string& pigment) {
        return "#version 3.7; sphere { 0, 1 pigment { " + pigment + " } }";
    };
    EXPECT_NE(parseErrorOf(scene("image_map { ppm \"" + ppm + "\" filter 1, 0.5 }"))
                  .find("cannot be used with non color-mapped image"),
              std::string::npos);
    EXPECT_NE(parseErrorOf(scene("image_map { ppm \"" + ppm + "\" interpolate 5 }"))
                  .find("Invalid interpolate value"),
              std::string::npos);
    EXPECT_NE(parseErrorOf(scene("image_map { ppm \"" + ppm + "\" map_type 3 }"))
                  .find("Invalid map_type value"),
              std::string::npos);
    EXPECT_NE(
        parseErrorOf(scene("image_map { ppm \"no_such_image.ppm\" }")).find("Cannot open file"),
        std::string::npos);
    EXPECT_NE(parseErrorOf(scene("image_map { ppm \"" + ppm + "\" uv_mapping }"))
                  .find("not supported yet"),
              std::string::npos);
}

}  // namespace
}  // namespace frameray
