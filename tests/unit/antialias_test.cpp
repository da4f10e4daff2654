// Anti-aliasing sample placement and combination (render/antialias.h).
#include "render/antialias.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

#include "render/jitter.h"

namespace frameray::render {
namespace {

// An image plane that is black left of x = edge and white from it on.
struct VerticalEdge {
    explicit VerticalEdge(double e) : edge(e) {}
    double edge;
    mutable std::vector<std::pair<double, double>> positions;
    PixelSample operator()(double x, double y) const {
        positions.emplace_back(x, y);
        return PixelSample{RGB(x + 0.5 >= edge ? 1.0 : 0.0), 0.0};
    }
};

AntialiasSettings settings(int method, double jitter = 0.0) {
    AntialiasSettings s;
    s.method = method;
    s.threshold = 0.3;
    s.depth = 3;
    s.jitter = jitter;
    return s;
}

TEST(Antialias, NoAntialiasingSamplesPixelCentresOnly) {
    VerticalEdge plane{4.3};
    AntialiasCounts counts;
    const auto pixels = sampleBlock({0, 0, 8, 2}, settings(0), std::ref(plane), counts);
    ASSERT_EQ(pixels.size(), 16u);
    EXPECT_EQ(counts.samples, 16u);
    EXPECT_EQ(counts.supersampledPixels, 0u);
    for (const auto& [x, y] : plane.positions) {
        EXPECT_EQ(x, std::floor(x));
        EXPECT_EQ(y, std::floor(y));
    }
}

TEST(Antialias, Method1LeavesUniformAreasAlone) {
    VerticalEdge plane{100};  // all black
    AntialiasCounts counts;
    sampleBlock({0, 0, 8, 8}, settings(1), std::ref(plane), counts);
    EXPECT_EQ(counts.supersampledPixels, 0u);
    // 64 pixels plus the row above (8) and the column left (8) of the block.
    EXPECT_EQ(counts.samples, 80u);
}

TEST(Antialias, Method1AveragesTheCentreWithADepthSquaredGrid) {
    // Edge at x = 4.25 in pixel-centre coordinates (pixel 4 spans 3.5..4.5
    // in sample positions shifted by 0.5): pixel 3 is black at its centre,
    // pixel 4 white; both straddle-compare, so both are refined.
    VerticalEdge plane{4.0 + 0.5 - 0.25 + 0.5};
    AntialiasCounts counts;
    const auto pixels = sampleBlock({0, 0, 8, 1}, settings(1), std::ref(plane), counts);
    // Pixel 4 (centre sample 4.0 -> 4.5 < 4.75: black) has its sub-grid at
    // x = 4 - 1/3, 4, 4 + 1/3: only the right column (3 of 9) is white.
    EXPECT_NEAR(pixels[4].rgb.r, 3.0 / 10.0, 1e-12);
    // Pixel 5 is white at its centre and everywhere in its sub-grid.
    EXPECT_NEAR(pixels[5].rgb.r, 1.0, 1e-12);
    EXPECT_EQ(counts.supersampledPixels, 2u);
}

TEST(Antialias, Method1NeverRefinesTheBordersOfItsBlock) {
    // An edge right at the block's left border: the column left of the
    // block belongs to another block and keeps its single sample.
    VerticalEdge plane{8.0 + 0.5};
    AntialiasCounts counts;
    const auto pixels = sampleBlock({8, 0, 16, 1}, settings(1), std::ref(plane), counts);
    // Pixel 8, then pixel 9: refined pixel 8 (0.7) now differs from
    // pixel 9's white centre. The border column is never refined.
    EXPECT_EQ(counts.supersampledPixels, 2u);
    // Pixel 8: white centre, sub-grid columns at 7 2/3 (black), 8, 8 1/3.
    EXPECT_NEAR(pixels[0].rgb.r, 7.0 / 10.0, 1e-12);
}

TEST(Antialias, Method2RefinesOnlyWhereCornersDiffer) {
    VerticalEdge plane{100};
    AntialiasCounts uniform;
    sampleBlock({0, 0, 4, 4}, settings(2), std::ref(plane), uniform);
    EXPECT_EQ(uniform.samples, 25u);  // the 5 x 5 pixel corners
    EXPECT_EQ(uniform.supersampledPixels, 0u);

    VerticalEdge edge{2.3 + 0.5};
    AntialiasCounts counts;
    const auto pixels = sampleBlock({0, 0, 4, 1}, settings(2), std::ref(edge), counts);
    EXPECT_EQ(counts.supersampledPixels, 1u);
    EXPECT_GT(pixels[2].rgb.r, 0.0);
    EXPECT_LT(pixels[2].rgb.r, 1.0);
    EXPECT_EQ(pixels[1].rgb.r, 0.0);
    EXPECT_EQ(pixels[3].rgb.r, 1.0);
}

TEST(Antialias, JitterIsAFunctionOfPositionWithinHalfAPixel) {
    std::set<std::pair<double, double>> seen;
    for (int i = 0; i < 50; ++i) {
        const double x = i * 0.37, y = 3.0 - i * 0.11;
        const JitterOffset a = jitterAt(x, y);
        const JitterOffset b = jitterAt(x, y);
        EXPECT_EQ(a.x, b.x);
        EXPECT_EQ(a.y, b.y);
        EXPECT_GE(a.x, -0.5);
        EXPECT_LT(a.x, 0.5);
        EXPECT_GE(a.y, -0.5);
        EXPECT_LT(a.y, 0.5);
        seen.insert({a.x, a.y});
    }
    EXPECT_GT(seen.size(), 40u);  // offsets vary from position to position
}

TEST(Antialias, ResultDoesNotDependOnOtherBlocks) {
    VerticalEdge a{5.7}, b{5.7};
    AntialiasCounts ca, cb;
    const auto whole = sampleBlock({0, 0, 8, 8}, settings(1, 1.0), std::ref(a), ca);
    const auto again = sampleBlock({0, 0, 8, 8}, settings(1, 1.0), std::ref(b), cb);
    ASSERT_EQ(whole.size(), again.size());
    for (size_t i = 0; i < whole.size(); ++i) EXPECT_EQ(whole[i].rgb.r, again[i].rgb.r);
}

TEST(Antialias, Method1ConvertsEachSampleOnceForItsComparisons) {
    // Each pixel is compared four times (with its left and upper
    // neighbours, and by its right and lower ones); its colour is brought
    // to the comparison gamma once, and again only when refined.
    for (const double edge : {100.0, 4.3, 2.6}) {
        VerticalEdge plane{edge};
        AntialiasSettings s = settings(1);
        int conversions = 0;
        s.toLinear = [&](double v) {
            ++conversions;
            return v;
        };
        AntialiasCounts counts;
        sampleBlock({0, 0, 8, 8}, s, std::ref(plane), counts);
        // 64 pixels, the row above and the column left of the block.
        EXPECT_EQ(conversions, 3 * (80 + static_cast<int>(counts.supersampledPixels))) << edge;
        if (edge < 10) {
            EXPECT_GT(counts.supersampledPixels, 0u);
        }
    }
}

TEST(Antialias, DistanceComparesInAntialiasGamma) {
    AntialiasSettings s;
    s.gamma = 2.5;
    const PixelSample dark{RGB(0.05, 0, 0), 0};
    const PixelSample black{RGB(0.0), 0};
    // 0.05^(1/2.5) = 0.3017: just over the default threshold (povray
    // super-samples this edge, checked against it).
    EXPECT_NEAR(antialiasDistance(dark, black, s), std::pow(0.05, 0.4), 1e-12);
    s.toLinear = [](double v) { return std::pow(v, 2.2); };
    EXPECT_NEAR(antialiasDistance(dark, black, s), std::pow(std::pow(0.05, 2.2), 0.4), 1e-12);
}

}  // namespace
}  // namespace frameray::render
