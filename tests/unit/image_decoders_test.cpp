// The direct decoders (PNG, JPEG, TGA, PNM) against OpenImageIO, which
// read every image before them: the same size, channels, every value bit
// for bit, and the same declared gamma. Files of every kind the decoders
// handle are written here (and the include folder's and the conformance
// scenes' images are read too).
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

// After cstdio: jpeglib.h needs FILE.
#include <jpeglib.h>

#include "image/codecs.h"
#include "image/image_io.h"
#include "image/png_reader.h"
#include "image/png_writer.h"

namespace frameray {
namespace {

namespace fs = std::filesystem;

struct PngSpec {
    int width = 5, height = 4, colorType = PNG_COLOR_TYPE_RGB, depth = 8;
    bool interlaced = false, transparency = false, srgb = false;
    double gamma = 0;  // gAMA exponent, 0: none
};

// A PNG whose samples are a deterministic pattern filling the bit depth.
void writePng(const fs::path& path, const PngSpec& s) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_init_io(png, f);
    png_set_IHDR(png, info, s.width, s.height, s.depth, s.colorType,
                 s.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    int channels = 1;
    switch (s.colorType) {
        case PNG_COLOR_TYPE_GRAY_ALPHA:
            channels = 2;
            break;
        case PNG_COLOR_TYPE_RGB:
            channels = 3;
            break;
        case PNG_COLOR_TYPE_RGB_ALPHA:
            channels = 4;
            break;
        default:
            break;
    }
    if (s.colorType == PNG_COLOR_TYPE_PALETTE) {
        std::vector<png_color> palette(static_cast<size_t>(1) << s.depth);
        for (size_t i = 0; i < palette.size(); ++i)
            palette[i] = {static_cast<png_byte>(i * 37), static_cast<png_byte>(255 - i * 11),
                          static_cast<png_byte>(i * 5)};
        png_set_PLTE(png, info, palette.data(), static_cast<int>(palette.size()));
        if (s.transparency) {
            png_byte alpha[3] = {0, 128, 200};
            png_set_tRNS(png, info, alpha, 3, nullptr);
        }
    } else if (s.transparency) {
        png_color_16 key{};
        key.gray = 3;
        key.red = 3;
        key.green = 3 * 7 % (1 << s.depth);
        key.blue = 3 * 13 % (1 << s.depth);
        png_set_tRNS(png, info, nullptr, 0, &key);
    }
    if (s.gamma > 0) png_set_gAMA(png, info, s.gamma);
    if (s.srgb) png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    if (s.depth == 16) png_set_swap(png);
    if (s.depth < 8) png_set_packing(png);
    const int maxLevel = (1 << s.depth) - 1;
    const size_t rowSamples = static_cast<size_t>(s.width) * channels;
    std::vector<std::vector<uint16_t>> rows16(static_cast<size_t>(s.height));
    std::vector<std::vector<uint8_t>> rows8(static_cast<size_t>(s.height));
    std::vector<png_bytep> pointers;
    for (int y = 0; y < s.height; ++y) {
        auto& r16 = rows16[static_cast<size_t>(y)];
        auto& r8 = rows8[static_cast<size_t>(y)];
        for (size_t i = 0; i < rowSamples; ++i) {
            const int v = static_cast<int>((y * 131 + static_cast<int>(i) * 7 * (1 + i % 3))) %
                          (maxLevel + 1);
            r16.push_back(static_cast<uint16_t>(v * (s.depth == 16 ? 257 : 1)));
            r8.push_back(static_cast<uint8_t>(v));
        }
        pointers.push_back(s.depth == 16 ? reinterpret_cast<png_bytep>(r16.data()) : r8.data());
    }
    png_write_image(png, pointers.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(f);
}

void writeJpeg(const fs::path& path, bool grey) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    jpeg_compress_struct c{};
    jpeg_error_mgr err{};
    c.err = jpeg_std_error(&err);
    jpeg_create_compress(&c);
    jpeg_stdio_dest(&c, f);
    c.image_width = 23;
    c.image_height = 17;
    c.input_components = grey ? 1 : 3;
    c.in_color_space = grey ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_set_defaults(&c);
    jpeg_start_compress(&c, TRUE);
    std::vector<uint8_t> row(static_cast<size_t>(c.image_width) * c.input_components);
    while (c.next_scanline < c.image_height) {
        for (size_t i = 0; i < row.size(); ++i)
            row[i] = static_cast<uint8_t>((i * 29 + c.next_scanline * 53) % 256);
        JSAMPROW p = row.data();
        jpeg_write_scanlines(&c, &p, 1);
    }
    jpeg_finish_compress(&c);
    jpeg_destroy_compress(&c);
    std::fclose(f);
}

void writeBytes(const fs::path& path, const std::vector<uint8_t>& bytes) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
}

// A TGA of 6 x 3 pixels: type, bits per pixel, descriptor; RLE packets
// repeat pixel pairs; colour-mapped files get a 24-bit map of 4 entries.
std::vector<uint8_t> tga(int type, int bits, int descriptor) {
    const bool mapped = (type & 7) == 1;
    std::vector<uint8_t> b = {0,
                              static_cast<uint8_t>(mapped ? 1 : 0),
                              static_cast<uint8_t>(type),
                              0,
                              0,
                              static_cast<uint8_t>(mapped ? 4 : 0),
                              0,
                              static_cast<uint8_t>(mapped ? 24 : 0),
                              0,
                              0,
                              0,
                              0,
                              6,
                              0,
                              3,
                              0,
                              static_cast<uint8_t>(bits),
                              static_cast<uint8_t>(descriptor)};
    if (mapped)
        for (int i = 0; i < 4; ++i)
            b.insert(b.end(), {static_cast<uint8_t>(i * 60), static_cast<uint8_t>(200 - i * 30),
                               static_cast<uint8_t>(i * 17)});
    const int bytes = (bits + 7) / 8;
    auto pixel = [&](int n) {
        for (int k = 0; k < bytes; ++k)
            b.push_back(static_cast<uint8_t>(mapped ? n % 4 : (n * 41 + k * 77 + 3) % 256));
    };
    for (int n = 0; n < 18;) {
        if (type & 8) {
            if (n % 4 == 0) {  // a run of 2
                b.push_back(0x81);
                pixel(n);
                n += 2;
            } else {  // 2 literal pixels
                b.push_back(0x01);
                pixel(n);
                pixel(n + 1);
                n += 2;
            }
        } else {
            pixel(n++);
        }
    }
    return b;
}

class ImageDecoders : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / fmt::format("frameray_decoders_{}", ::getpid());
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    // The direct decoder's image equals OpenImageIO's, value for value
    // (within `levels` 16-bit levels).
    void expectSameAsOiio(const fs::path& path, int levels = 0) {
        SCOPED_TRACE(path.string());
        const image::SourceImage direct = image::readSource(path);
        const image::SourceImage oiio = image::codecs().readSource(path.string());
        ASSERT_TRUE(direct.pixels && oiio.pixels);
        const util::PixelBuffer& a = *direct.pixels;
        const util::PixelBuffer& b = *oiio.pixels;
        ASSERT_EQ(a.width(), b.width());
        ASSERT_EQ(a.height(), b.height());
        ASSERT_EQ(a.channels(), b.channels());
        EXPECT_EQ(a.bitDepth(), b.bitDepth());
        EXPECT_NEAR(direct.declaredGamma, oiio.declaredGamma, 1e-6);
        // The values the old reader gave: OpenImageIO's conversion to float.
        const image::EncodedImage floats = image::codecs().read(path.string(), true);
        ASSERT_EQ(floats.channels, b.channels());
        int mismatches = 0;
        for (size_t p = 0; p < a.pixelCount(); ++p)
            for (int c = 0; c < a.channels(); ++c) {
                const float fa = a.value(p, c), fb = b.value(p, c);
                const float ff =
                    floats
                        .values[p * static_cast<size_t>(floats.channels) + static_cast<size_t>(c)];
                const float tolerance = static_cast<float>(levels) / 65535.0f;
                if ((std::abs(fa - fb) > tolerance || std::abs(fa - ff) > tolerance) &&
                    ++mismatches < 5)
                    ADD_FAILURE() << "pixel " << p << " channel " << c << ": direct " << fa
                                  << ", OpenImageIO " << fb << " (as float " << ff << ")";
            }
        EXPECT_EQ(mismatches, 0);
    }

    fs::path dir_;
};

TEST_F(ImageDecoders, PngOfEveryColourTypeAndDepth) {
    struct Case {
        int type, depth;
    };
    const Case cases[] = {{PNG_COLOR_TYPE_GRAY, 1},        {PNG_COLOR_TYPE_GRAY, 2},
                          {PNG_COLOR_TYPE_GRAY, 4},        {PNG_COLOR_TYPE_GRAY, 8},
                          {PNG_COLOR_TYPE_GRAY, 16},       {PNG_COLOR_TYPE_GRAY_ALPHA, 8},
                          {PNG_COLOR_TYPE_GRAY_ALPHA, 16}, {PNG_COLOR_TYPE_RGB, 8},
                          {PNG_COLOR_TYPE_RGB, 16},        {PNG_COLOR_TYPE_RGB_ALPHA, 8},
                          {PNG_COLOR_TYPE_RGB_ALPHA, 16},  {PNG_COLOR_TYPE_PALETTE, 1},
                          {PNG_COLOR_TYPE_PALETTE, 4},     {PNG_COLOR_TYPE_PALETTE, 8}};
    int n = 0;
    for (const Case& c : cases)
        for (int variant = 0; variant < 2; ++variant) {
            PngSpec s;
            s.colorType = c.type;
            s.depth = c.depth;
            s.interlaced = variant == 1;
            // tRNS where the colour type allows it; a gamma on some.
            s.transparency = variant == 1 && !(c.type & PNG_COLOR_MASK_ALPHA);
            s.gamma = variant == 0 ? 0.45455 : 0;
            const fs::path path = dir_ / fmt::format("t{}.png", n++);
            writePng(path, s);
            expectSameAsOiio(path);
        }
    PngSpec s;
    s.srgb = true;
    writePng(dir_ / "srgb.png", s);
    expectSameAsOiio(dir_ / "srgb.png");
}

// The gAMA and sRGB chunks of a PNG file's bytes (none when absent).
struct GammaChunks {
    std::optional<std::uint32_t> gama;
    std::optional<int> srgbIntent;
};

GammaChunks gammaChunksOf(const std::vector<unsigned char>& png) {
    GammaChunks out;
    auto be32 = [&](size_t at) {
        return static_cast<std::uint32_t>(png[at]) << 24 |
               static_cast<std::uint32_t>(png[at + 1]) << 16 |
               static_cast<std::uint32_t>(png[at + 2]) << 8 | png[at + 3];
    };
    for (size_t at = 8; at + 8 <= png.size();) {
        const std::uint32_t length = be32(at);
        const std::string type(reinterpret_cast<const char*>(&png[at + 4]), 4);
        if (type == "gAMA") out.gama = be32(at + 8);
        if (type == "sRGB") out.srgbIntent = png[at + 8];
        at += 12 + length;
    }
    return out;
}

// Frames state their File_Gamma as povray 3.7 writes them (measured with
// +FN: sRGB gives gAMA 45455 and an sRGB chunk, intent 0; File_Gamma=2.2
// gAMA 45455 only, 1.8 55556, 1.0 100000), and the reader takes the sRGB
// chunk back as the sRGB curve, a lone gAMA as its gamma.
TEST_F(ImageDecoders, PngStatesTheFileGammaAsPovrayDoes) {
    const std::vector<std::uint8_t> rgb(4 * 2 * 3, 100);
    struct Case {
        std::optional<double> gamma;
        std::optional<std::uint32_t> gama;
        std::optional<int> srgb;
        double declared;
    };
    const Case cases[] = {{std::nullopt, std::nullopt, std::nullopt, 0.0},
                          {0.0, 45455u, 0, 0.0},
                          {2.2, 45455u, std::nullopt, 2.2},
                          {1.8, 55556u, std::nullopt, 1.8},
                          {1.0, 100000u, std::nullopt, 1.0}};
    int n = 0;
    for (const Case& c : cases) {
        SCOPED_TRACE(n);
        const std::vector<unsigned char> png = image::encodePng(4, 2, 3, 8, rgb.data(), c.gamma);
        const GammaChunks chunks = gammaChunksOf(png);
        EXPECT_EQ(chunks.gama, c.gama);
        EXPECT_EQ(chunks.srgbIntent, c.srgb);
        const fs::path path = dir_ / fmt::format("g{}.png", n++);
        std::ofstream(path, std::ios::binary)
            .write(reinterpret_cast<const char*>(png.data()),
                   static_cast<std::streamsize>(png.size()));
        const image::SourceImage back = image::readPng(path);
        EXPECT_EQ(back.declaresSrgb, c.srgb.has_value());
        EXPECT_NEAR(back.declaredGamma, c.declared, 1e-6);
    }
}

TEST_F(ImageDecoders, PalettePngKeepsItsIndices) {
    PngSpec s;
    s.colorType = PNG_COLOR_TYPE_PALETTE;
    s.depth = 4;
    s.transparency = true;
    writePng(dir_ / "p.png", s);
    const image::SourceImage img = image::readPng(dir_ / "p.png");
    ASSERT_TRUE(img.isPalette());
    EXPECT_EQ(img.pixels->channels(), 4);  // tRNS: the palette has alpha
    EXPECT_EQ(img.pixels->index(0), 0);
    EXPECT_EQ(img.pixels->palette()[1][3], 128);
    EXPECT_EQ(img.pixels->palette()[5][3], 255);
}

TEST_F(ImageDecoders, Jpeg) {
    writeJpeg(dir_ / "c.jpg", false);
    writeJpeg(dir_ / "g.jpg", true);
    expectSameAsOiio(dir_ / "c.jpg");
    expectSameAsOiio(dir_ / "g.jpg");
}

TEST_F(ImageDecoders, Tga) {
    struct Case {
        int type, bits, descriptor;
    };
    const Case cases[] = {{2, 24, 0},  {2, 24, 0x20}, {2, 32, 8},    {2, 32, 0x28}, {10, 24, 0},
                          {10, 32, 8}, {3, 8, 0},     {11, 8, 0x20}, {1, 8, 0},     {9, 8, 0x20},
                          {2, 16, 1},  {2, 16, 0},    {2, 24, 0x10}, {2, 32, 0}};
    int n = 0;
    for (const Case& c : cases) {
        const fs::path path = dir_ / fmt::format("t{}.tga", n++);
        writeBytes(path, tga(c.type, c.bits, c.descriptor));
        expectSameAsOiio(path);
    }
}

TEST_F(ImageDecoders, Pnm) {
    struct File {
        const char* header;
        std::vector<uint8_t> raw;
    };
    const File files[] = {
        {"P6\n# comment\n3 2\n255\n", std::vector<uint8_t>(18, 0x7f)},
        {"P5 3 2 255\n", {1, 2, 3, 0xfd, 0xfe, 0xff}},
        {"P5\n2 2\n65535\n", {0x12, 0x34, 0xff, 0xff, 0x00, 0x01, 0x80, 0x00}},
        {"P2\n3 2\n15\n0 1 2\n13 14 15\n", {}},
        {"P3\n2 1\n255\n255 0 10  3 4 5\n", {}},
        {"P2\n7 1\n100\n0 1 33 49 50 99 100\n", {}},
        {"P2\n5 1\n1000\n0 1 499 999 1000\n", {}},
        {"P4\n10 2\n", {0xA5, 0x40, 0x0F, 0xC0}},
    };
    int n = 0;
    for (const File& file : files) {
        const std::string header = file.header;
        std::vector<uint8_t> bytes(header.begin(), header.end());
        bytes.insert(bytes.end(), file.raw.begin(), file.raw.end());
        const fs::path path = dir_ / fmt::format("t{}.pnm", n++);
        writeBytes(path, bytes);
        // OpenImageIO reads a 16-bit 65535 as 65534 (the direct decoder
        // keeps it, as povray does).
        expectSameAsOiio(path, 1);
    }
    // Plain bitmaps, which OpenImageIO cannot read: 1 is black.
    writeBytes(dir_ / "b.pbm", {'P', '1', '\n', '3', ' ', '1', '\n', '1', '0', '1'});
    const image::SourceImage bitmap = image::readSource(dir_ / "b.pbm");
    EXPECT_EQ(bitmap.pixels->value(0, 0), 0.0f);
    EXPECT_EQ(bitmap.pixels->value(1, 0), 1.0f);
    EXPECT_EQ(bitmap.pixels->value(2, 0), 0.0f);
}

TEST_F(ImageDecoders, IncludeAndSceneImages) {
    std::vector<fs::path> files;
    for (const fs::path& dir : {fs::path("/usr/share/povray-3.7/include"),
                                fs::path(FRAMERAY_SOURCE_DIR) / "tests/conformance/scenes"}) {
        if (!fs::is_directory(dir)) continue;
        for (const auto& entry : fs::directory_iterator(dir)) {
            const std::string ext = entry.path().extension().string();
            if (ext == ".png" || ext == ".jpg" || ext == ".tga" || ext == ".ppm" || ext == ".pgm")
                files.push_back(entry.path());
        }
    }
    for (const fs::path& path : files) expectSameAsOiio(path);
}

}  // namespace
}  // namespace frameray
