#include "compare_images.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace frameray::conformance {
namespace {

// A deterministic, non-flat RGB(A) image so that differences are measured
// against varied values rather than a constant.
Image gradient(int width, int height, int channels = 3) {
    Image image{width, height, channels, {}};
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            image.samples.push_back(float((x * 7 + y * 3) % 200 + 20));
            image.samples.push_back(float((x * 11) % 180 + 30));
            image.samples.push_back(float((y * 13) % 160 + 40));
            if (channels == 4) image.samples.push_back(255.0f);
        }
    }
    return image;
}

// Adds delta to channel c of the first `count` pixels (row-major order).
void offset_pixels(Image& image, int count, int c, float delta) {
    for (int i = 0; i < count; ++i) image.samples[i * image.channels + c] += delta;
}

TEST(CompareImages, BoxBlurAveragesWindowsCutAtBorders) {
    Image a{3, 1, 3, {0, 0, 0, 30, 60, 90, 90, 0, 30}};
    const Image b = box_blur(a, 1);
    EXPECT_FLOAT_EQ(b.at(0, 0, 0), 15.0f);  // pixels 0 and 1
    EXPECT_FLOAT_EQ(b.at(1, 0, 0), 40.0f);  // all three
    EXPECT_FLOAT_EQ(b.at(2, 0, 1), 30.0f);  // pixels 1 and 2
    EXPECT_EQ(box_blur(a, 0).samples, a.samples);
    // Noise of zero mean vanishes from a flat image.
    Image noisy{8, 8, 3, {}};
    for (int i = 0; i < 8 * 8 * 3; ++i) noisy.samples.push_back(100.0f + ((i / 3) % 2 ? 6 : -6));
    const Image smooth = box_blur(noisy, 2);
    EXPECT_NEAR(smooth.at(4, 4, 0), 100.0f, 1.5f);
}

TEST(CompareImages, IdenticalImagesMatchCompletely) {
    const Image a = gradient(32, 24);
    const CompareResult r = compare_images(a, a);
    EXPECT_EQ(r.total_pixels, 32u * 24u);
    EXPECT_EQ(r.matching_pixels, r.total_pixels);
    EXPECT_DOUBLE_EQ(r.match, 1.0);
    EXPECT_DOUBLE_EQ(r.max_abs_diff, 0.0);
    EXPECT_TRUE(std::isinf(r.psnr_db));
    EXPECT_GT(r.psnr_db, 0.0);
    EXPECT_TRUE(r.passed);
}

TEST(CompareImages, PixelsOffByFiveFail) {
    const Image golden = gradient(40, 25);  // 1000 pixels
    Image test = golden;
    offset_pixels(test, 17, 1, 5.0f);
    const CompareResult r = compare_images(test, golden);
    EXPECT_EQ(r.matching_pixels, 1000u - 17u);
    EXPECT_DOUBLE_EQ(r.match, 983.0 / 1000.0);
    EXPECT_DOUBLE_EQ(r.max_abs_diff, 5.0);
    EXPECT_FALSE(r.passed);  // 0.983 < 0.99
}

TEST(CompareImages, PixelsOffByFourStillMatch) {
    const Image golden = gradient(40, 25);
    Image test = golden;
    offset_pixels(test, 300, 0, 4.0f);
    offset_pixels(test, 300, 2, -4.0f);
    const CompareResult r = compare_images(test, golden);
    EXPECT_DOUBLE_EQ(r.match, 1.0);
    EXPECT_DOUBLE_EQ(r.max_abs_diff, 4.0);
    EXPECT_TRUE(r.passed);
    EXPECT_FALSE(std::isinf(r.psnr_db));
}

// Samples that came from 8-bit files via a float /255 and *255 round trip
// are not exact integers; an exact 4/255 difference must still match.
TEST(CompareImages, ToleranceSurvivesEightBitRoundTrip) {
    Image golden{1, 1, 3, {float(201) / 255.0f * 255.0f, 0.0f, 0.0f}};
    Image test{1, 1, 3, {float(205) / 255.0f * 255.0f, 0.0f, 0.0f}};
    EXPECT_DOUBLE_EQ(compare_images(test, golden).match, 1.0);
}

TEST(CompareImages, ThresholdDecidesPass) {
    const Image golden = gradient(10, 10);  // 100 pixels
    Image test = golden;
    offset_pixels(test, 2, 0, 50.0f);
    CompareOptions options;
    options.min_match = 0.98;
    EXPECT_TRUE(compare_images(test, golden, options).passed);  // exactly 0.98
    options.min_match = 0.99;
    EXPECT_FALSE(compare_images(test, golden, options).passed);
}

TEST(CompareImages, PsnrOfKnownError) {
    // Every sample of every pixel off by 1 → MSE 1 → PSNR = 20 log10(255).
    const Image golden = gradient(8, 8);
    Image test = golden;
    for (float& s : test.samples) s += 1.0f;
    const CompareResult r = compare_images(test, golden);
    EXPECT_NEAR(r.psnr_db, 20.0 * std::log10(255.0), 1e-9);
}

TEST(CompareImages, AlphaComparedOnlyWhenBothHaveIt) {
    const Image golden_rgba = gradient(10, 10, 4);
    Image test_rgba = golden_rgba;
    offset_pixels(test_rgba, 10, 3, -100.0f);
    EXPECT_DOUBLE_EQ(compare_images(test_rgba, golden_rgba).match, 0.9);

    // Against an RGB golden the alpha channel is ignored.
    const Image golden_rgb = gradient(10, 10, 3);
    EXPECT_DOUBLE_EQ(compare_images(test_rgba, golden_rgb).match, 1.0);
}

TEST(CompareImages, SizeMismatchIsReportedNotCompared) {
    const Image a = gradient(10, 10);
    const Image b = gradient(10, 11);
    const auto why = incompatibility(a, b);
    ASSERT_TRUE(why.has_value());
    EXPECT_NE(why->find("size mismatch"), std::string::npos);
    EXPECT_THROW(compare_images(a, b), std::invalid_argument);
    EXPECT_FALSE(incompatibility(a, a).has_value());
}

TEST(CompareImages, DiffImageMarksFailingPixelsRed) {
    const Image golden = gradient(10, 10);
    Image test = golden;
    offset_pixels(test, 3, 2, 20.0f);
    const Image diff = make_diff_image(test, golden);
    ASSERT_EQ(diff.channels, 3);
    ASSERT_EQ(diff.width, 10);
    ASSERT_EQ(diff.height, 10);
    for (int x = 0; x < 10; ++x) {
        const bool failing = x < 3;
        EXPECT_EQ(diff.at(x, 0, 0) >= 128.0f, failing) << "x=" << x;
        EXPECT_EQ(diff.at(x, 0, 1) == 0.0f && diff.at(x, 0, 2) == 0.0f, failing) << "x=" << x;
    }
}

TEST(CompareImages, ReportLineNamesOutcome) {
    const Image a = gradient(4, 4);
    const CompareOptions options;
    const std::string line = format_result(compare_images(a, a, options), options);
    EXPECT_NE(line.find("match 1.000000"), std::string::npos) << line;
    EXPECT_NE(line.find("psnr inf dB"), std::string::npos) << line;
    EXPECT_NE(line.find("PASS"), std::string::npos) << line;
}

}  // namespace
}  // namespace frameray::conformance
