// Dither=on as povray 3.7 writes it (Dither_Method B2, B3, B4, FS).
// Expected pixels are povray 3.7.0.10's, measured on flat colours
// (background rgb v, assumed_gamma 1, File_Gamma 1.0, 8-bit PPM).
#include "image/dither.h"

#include <gtest/gtest.h>

#include <string>

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

TEST(Dither, NoneRoundsAndAlphaIsNotDithered) {
    EXPECT_EQ(pattern(flat(4, 4, (100 + 0.4) / 255, Dither::None), 100), "0000000000000000");
    EncodedImage rgba = flat(4, 4, (100 + 0.1) / 255, Dither::Bayer4);
    rgba.channels = 4;
    rgba.values.assign(4 * 4 * 4, static_cast<float>((100 + 0.1) / 255));
    const std::vector<double> q = quantizeToLevels(rgba, 255);
    for (size_t i = 3; i < q.size(); i += 4) EXPECT_EQ(q[i], 100) << i;
    EXPECT_EQ(q[3 * 4], 101);  // pixel (3, 0): matrix 0
}
