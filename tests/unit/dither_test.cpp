// Dither=on as povray 3.7 writes it (Dither_Method B2, B3, B4, FS), and
// the PPM files the levels go to.
// Expected pixels are povray 3.7.0.10's, measured on flat colours
// (background rgb v, assumed_gamma 1, File_Gamma 1.0, 8-bit PPM).
#include "image/dither.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "image/ppm_writer.h"

using namespace frameray::image;

namespace {

// A w x h grey image of file value v (three equal channels).
EncodedImage flat(int w, int h, double v, Dither d) {
    EncodedImage img;
    img.width = w;
    img.height = h;
    img.channels = 3;
    img.values.assign(static_cast<size_t>(w) * h * 3, static_cast<float>(v));
    img.dither = d;
    return img;
}

// The red channel's levels minus `base`, one digit per pixel, row-major.
std::string pattern(const EncodedImage& img, int base) {
    const std::vector<double> q = quantizeToLevels(img, 255);
    std::string out;
    for (size_t i = 0; i < q.size(); i += 3) out += std::to_string(static_cast<int>(q[i]) - base);
    return out;
}

}  // namespace

TEST(Dither, BayerPatternsArePovrays) {
    // 100 + f of 255: which pixels go up to 101 (povray, 16 or 32 steps of f).
    EXPECT_EQ(pattern(flat(2, 2, (100 + 0.1) / 255, Dither::Bayer2), 100), "0100");
    EXPECT_EQ(pattern(flat(2, 2, (100 + 0.3) / 255, Dither::Bayer2), 100), "0110");
    EXPECT_EQ(pattern(flat(2, 2, (100 + 0.6) / 255, Dither::Bayer2), 100), "0111");
    EXPECT_EQ(pattern(flat(3, 3, (100 + 0.25) / 255, Dither::Bayer3), 100), "000101010");
    EXPECT_EQ(pattern(flat(3, 3, (100 + 0.75) / 255, Dither::Bayer3), 100), "110101111");
    EXPECT_EQ(pattern(flat(4, 4, (100 + 0.1) / 255, Dither::Bayer4), 100), "0001000001000000");
    EXPECT_EQ(pattern(flat(4, 4, (100 + 0.45) / 255, Dither::Bayer4), 100), "0101101001011010");
    // The pattern repeats from the top-left corner.
    EXPECT_EQ(pattern(flat(8, 1, (100 + 0.1) / 255, Dither::Bayer4), 100), "00010001");
    // A value on a level goes up where the matrix is 0: povray writes
    // black as 1 there.
    EXPECT_EQ(pattern(flat(4, 4, 0.0, Dither::Bayer4), 0), "0001000000000000");
    EXPECT_EQ(pattern(flat(2, 2, 1.0, Dither::Bayer2), 255), "0000");
}

TEST(Dither, FloydSteinbergMatchesPovrayOnTheseColours) {
    EXPECT_EQ(pattern(flat(8, 6, (100 + 0.25) / 255, Dither::FloydSteinberg), 100),
              "000000000101010100000000010101010000000001010100");
    EXPECT_EQ(pattern(flat(8, 6, (100 + 0.4) / 255, Dither::FloydSteinberg), 100),
              "010010100101000101001100010100100100101001010010");
}

// 16 x 16 flat fields of working value v (as povray's Declare=V= passes
// it: six significant digits), encoded with `gamma`, against povray
// 3.7.0.10's PPM pixels (Dither_Method=FS, assumed_gamma 1, File_Gamma
// 1.0 and 2.2): the levels minus `base`, one row per string.
std::string rows(double v, const GammaEncoding& gamma, int base) {
    EncodedImage img = flat(16, 16, gamma.encode(v), Dither::FloydSteinberg);
    img.encoding = gamma;
    const std::string p = pattern(img, base);
    std::string out;
    for (int y = 0; y < 16; ++y) out += p.substr(y * 16, 16) + "\n";
    return out;
}

std::string join(const std::vector<std::string>& lines) {
    std::string out;
    for (const auto& l : lines) out += l + "\n";
    return out;
}

TEST(Dither, FloydSteinbergIsPovraysVariant) {
    // Column 0 takes the error meant for the row above (povray turns its
    // row buffers after reading it): at .5 each row pattern comes twice.
    const GammaEncoding linear = GammaEncoding::forScene(true, 1.0, 3.7, 1.0);
    EXPECT_EQ(
        rows(0.394118, linear, 100),
        join({"1010101010101010", "1010101010101010", "0101010101010101", "0101010101010101",
              "1010101010101010", "1010101010101010", "0101010101010101", "0101010101010101",
              "1010101010101010", "1010101010101010", "0101010101010101", "0101010101010101",
              "1010101010101010", "1010101010101010", "0101010101010101", "0101010101010101"}));
    EXPECT_EQ(
        rows(0.393725, linear, 100),
        join({"0100101001010010", "0101000101001010", "0100110100101001", "0101001010010100",
              "0100100010100010", "0101010101010101", "0100101000101010", "0101000110010001",
              "0100101001001010", "0101010100101001", "0100100010100100", "0101010101010101",
              "0100010100100100", "0101010010010010", "0100101001010101", "0101000101001010"}));
    // File_Gamma 2.2: the error is carried in working (linear) values.
    const GammaEncoding g22 = GammaEncoding::forScene(true, 1.0, 3.7, 2.2);
    EXPECT_EQ(
        rows(0.393137, g22, 166),
        join({"1111111111111111", "1101101101101101", "1111111111111111", "1101101101011011",
              "1111111111111111", "1010110110110101", "1111111111111111", "1110101011011011",
              "1011111111111111", "1111110110101101", "1101011111111111", "1111111011011011",
              "1011101111111110", "1110111101101111", "1111110111111011", "1011011110111110"}));
    EXPECT_EQ(
        rows(0.395098, g22, 167),
        join({"0000000000000000", "0010010010010010", "0000000000000000", "0101010101010100",
              "0000000000000001", "0010001001001000", "0000100000000010", "0100000100100000",
              "0001000000001001", "0000010101000000", "0101000000010100", "0000001001000001",
              "0010000000001000", "0000101001000010", "0100000000010000", "0001001010000100"}));
}

TEST(Dither, NoneRoundsAndAlphaIsNotDithered) {
    EXPECT_EQ(pattern(flat(4, 4, (100 + 0.4) / 255, Dither::None), 100), "0000000000000000");
    EncodedImage rgba = flat(4, 4, (100 + 0.1) / 255, Dither::Bayer4);
    rgba.channels = 4;
    rgba.values.assign(4 * 4 * 4, static_cast<float>((100 + 0.1) / 255));
    const std::vector<double> q = quantizeToLevels(rgba, 255);
    for (size_t i = 3; i < q.size(); i += 4) EXPECT_EQ(q[i], 100) << i;
    EXPECT_EQ(q[3 * 4], 101);  // pixel (3, 0): matrix 0
}

// PPM files carry povray's maximum value 2^bits - 1 at any depth (measured:
// +FP5 maxval 31, +FP12 4095, +FP16 65535), one byte per sample up to 255,
// two (most significant first) above; alpha is not written.
TEST(PpmWriter, MaximumValueIsTheDepthsAsPovrayWritesIt) {
    EncodedImage img = flat(2, 1, 0.5, Dither::None);
    for (const auto& [bits, header, sample] :
         {std::tuple{5, std::string("P6\n2 1\n31\n"), std::vector<unsigned char>{16}},
          std::tuple{8, std::string("P6\n2 1\n255\n"), std::vector<unsigned char>{128}},
          std::tuple{12, std::string("P6\n2 1\n4095\n"), std::vector<unsigned char>{0x08, 0x00}},
          std::tuple{16, std::string("P6\n2 1\n65535\n"),
                     std::vector<unsigned char>{0x80, 0x00}}}) {
        const double levels = std::ldexp(1.0, bits) - 1;
        const std::vector<unsigned char> file =
            encodePpm(2, 1, 3, bits, quantizeToLevels(img, levels));
        ASSERT_EQ(file.size(), header.size() + 6 * sample.size()) << bits;
        EXPECT_EQ(std::string(file.begin(), file.begin() + header.size()), header);
        EXPECT_EQ(std::vector<unsigned char>(file.begin() + header.size(),
                                             file.begin() + header.size() + sample.size()),
                  sample)
            << bits;
    }
    // Grey with alpha: P5, the grey only.
    EncodedImage ga = flat(1, 1, 1.0, Dither::None);
    ga.channels = 2;
    ga.values = {1.0f, 0.5f};
    const std::vector<unsigned char> grey = encodePpm(1, 1, 2, 8, quantizeToLevels(ga, 255));
    EXPECT_EQ(std::string(grey.begin(), grey.end()), std::string("P5\n1 1\n255\n") + '\xff');
}
