// Participating media: parsing of media { } and density { }, the phase
// functions, and render/media's method 3 sampling against values measured
// with povray 3.7 (16-bit linear renders of a slab of media).
#include "render/media.h"

#include <gtest/gtest.h>

#include <cmath>

#include "parse_support.h"
#include "render/world.h"
#include "sdl/interpreter.h"
#include "util/chi_square.h"

using namespace frameray;

namespace {

using Parsed = test_support::ParsedScene;

const scene::Media& firstInteriorMedia(const Parsed& p) {
    return *p.scene.objects.at(0)->interior->media.at(0);
}

// The light (emission) and transmittance of a slab [0, depth] along +z.
render::MediaResult slab(const scene::Scene& scene, double depth) {
    const render::World world(scene);
    render::MediaSet set;
    set.add(scene.objects.at(0)->interior->media);
    uint64_t samples = 0, shadows = 0;
    return render::integrateMedia(world, render::LightingQuality{}, {{0, 0, 0}, {0, 0, 1}}, depth,
                                  set, true, samples, shadows);
}

}  // namespace

TEST(MediaParse, DefaultsAndItems) {
    Parsed p(
        "box { 0, 1 hollow interior { media { } media { method 3 intervals 4 samples 7, 9 "
        "confidence 0.5 variance 0.1 ratio 0.7 aa_level 2 aa_threshold 0.2 jitter 0.3 "
        "absorption <1, 2, 3> emission 0.5 scattering { 5, rgb 0.25 eccentricity 0.6 extinction "
        "0.4 } } } }");
    const auto& media = p.scene.objects.at(0)->interior->media;
    ASSERT_EQ(media.size(), 2u);
    const scene::Media& d = *media[0];
    EXPECT_EQ(d.method, 3);
    EXPECT_EQ(d.intervals, 1);
    EXPECT_EQ(d.samplesMin, 10);
    EXPECT_EQ(d.aaLevel, 3);
    EXPECT_DOUBLE_EQ(d.aaThreshold, 0.1);
    EXPECT_DOUBLE_EQ(d.jitter, 0.0);
    EXPECT_DOUBLE_EQ(d.eccentricity, 0.0);
    EXPECT_DOUBLE_EQ(d.extinction, 1.0);
    const scene::Media& m = *media[1];
    EXPECT_EQ(m.intervals, 4);
    EXPECT_EQ(m.samplesMin, 7);
    EXPECT_EQ(m.samplesMax, 9);
    EXPECT_EQ(m.aaLevel, 2);
    EXPECT_DOUBLE_EQ(m.ratio, 0.7);
    EXPECT_DOUBLE_EQ(m.absorption.b, 3.0);
    EXPECT_DOUBLE_EQ(m.emission.g, 0.5);
    EXPECT_EQ(m.scatteringType, scene::ScatteringType::HenyeyGreenstein);
    EXPECT_NEAR(m.scattering.r, 0.25, 1e-7);
    EXPECT_DOUBLE_EQ(m.eccentricity, 0.6);
    EXPECT_DOUBLE_EQ(m.extinction, 0.4);
}

TEST(MediaParse, DeclaredMediaDensitiesAndMaps) {
    Parsed p(
        "#declare D = density { gradient x }\n"
        "#declare M = media { emission 1 density { D } }\n"
        "media { M density { D density_map { [0 rgb 0] [1 D scale 2] } } }\n"
        "sphere { 0, 1 hollow interior { media { M } } translate x * 3 }");
    ASSERT_EQ(p.scene.atmosphere.media.size(), 1u);
    EXPECT_EQ(p.scene.atmosphere.media[0]->densities.size(), 2u);
    // The gradient density, with the default grey ramp, moves with the
    // object: 0.25 at x = 3.25.
    const scene::Media& in = firstInteriorMedia(p);
    EXPECT_NEAR(in.densityAt({3.25, 0, 0}).r, 0.25, 1e-9);
}

TEST(MediaParse, Errors) {
    EXPECT_NE(test_support::parseErrorOf("media { aa_level 0 }").find("aa_level"),
              std::string::npos);
    EXPECT_NE(test_support::parseErrorOf("media { scattering { 7, 1 } }").find("scattering"),
              std::string::npos);
    EXPECT_NE(test_support::parseErrorOf("media { method 4 }").find("Unknown media sampling"),
              std::string::npos);
    EXPECT_EQ(test_support::parseErrorOf("media { method 1 }"), "");
    // povray 3.7's message for samples max below min.
    EXPECT_NE(test_support::parseErrorOf("media { samples 5, 2 }")
                  .find("Maximum number of samples per interval smaller than minimum number."),
              std::string::npos);
}

TEST(MediaPhase, MeasuredShapes) {
    scene::Media m;
    m.scatteringType = scene::ScatteringType::Isotropic;
    EXPECT_DOUBLE_EQ(m.phase(0.3), 1.0);
    m.scatteringType = scene::ScatteringType::HenyeyGreenstein;
    m.eccentricity = 0.5;
    EXPECT_NEAR(m.phase(1.0), 6.0, 1e-12);
    EXPECT_NEAR(m.phase(-1.0), 0.75 / 3.375, 1e-12);
    // povray 3.7, slab lit at 0, 90 and 180 degrees (extinction 0).
    m.scatteringType = scene::ScatteringType::Rayleigh;
    EXPECT_NEAR(m.phase(1.0), 1.5988, 1e-3);
    EXPECT_NEAR(m.phase(0.0), 0.7993, 1e-3);
    m.scatteringType = scene::ScatteringType::MieHazy;
    EXPECT_NEAR(m.phase(1.0), 5.7665, 2e-3);
    EXPECT_NEAR(m.phase(0.0), 0.5965, 2e-3);
    m.scatteringType = scene::ScatteringType::MieMurky;
    EXPECT_NEAR(m.phase(1.0), 25.281, 1e-2);
    EXPECT_NEAR(m.phase(0.9), 5.296, 1e-2);
}

TEST(MediaSampling, ConstantMediaAsPovray) {
    // emission 0.3 absorption 0.3 over 3 units: povray 3.7 gives 0.73693
    // for samples 1..3, 0.68688 for 4 and 5, 0.63905 for 10 (the default).
    for (const auto& [samples, expected] :
         {std::pair{"samples 1", 0.73693}, {"samples 5", 0.68688}, {"", 0.63905}}) {
        Parsed p(std::string("box { 0, 1 hollow interior { media { emission 0.3 absorption 0.3 "
                             "intervals 3 ") +
                 samples + " } } }");
        const render::MediaResult r = slab(p.scene, 3.0);
        EXPECT_NEAR(r.light.r, expected, 2e-5) << samples;
        EXPECT_NEAR(r.transmittance.g, std::exp(-0.9), 1e-12) << samples;
    }
}

TEST(MediaSampling, SamplePlacementAsPovray) {
    // An emitting step density (1 in front of z0, 0 behind) over one
    // unit: povray 3.7 puts samples 1's points at 0, 1/6, 1/3 (twice),
    // 1/2 and 2/3, each weighing 1/6 without subdivision (aa_level 1) ...
    auto weight = [](double z0, const char* settings) {
        Parsed p(std::string("box { 0, 1 hollow interior { media { emission 1 ") + settings +
                 " density { function { select(z - " + std::to_string(z0) + ", 1, 0) } } } } }");
        return slab(p.scene, 1.0).light.r;
    };
    EXPECT_NEAR(weight(0.01, "samples 1 aa_level 1"), 1.0 / 6, 1e-12);
    EXPECT_NEAR(weight(0.2, "samples 1 aa_level 1"), 2.0 / 6, 1e-12);
    EXPECT_NEAR(weight(0.4, "samples 1 aa_level 1"), 4.0 / 6, 1e-12);
    EXPECT_NEAR(weight(0.9, "samples 1 aa_level 1"), 1.0, 1e-12);
    // ... and with the default aa_level 3 the sub-interval holding the
    // step is halved twice: 1/24 of the light for the first point alone.
    EXPECT_NEAR(weight(0.01, "samples 1"), 1.0 / 24, 1e-12);
    EXPECT_NEAR(weight(0.05, "samples 1"), 2.0 / 24, 1e-12);
    EXPECT_NEAR(weight(0.1, "samples 1"), 4.0 / 24, 1e-12);
}

namespace {

// A slab [0, 4] whose density is 0 up to 2.5 and B ((z - 2.5) / 0.5)^2
// beyond: only the last of samples 4's three sub-intervals ([2, 3]) sees
// it, its points at 2, 2.5, 3 (0, 0, B) and, split, 2.75 (B / 4).
double lastSubInterval(double b) {
    Parsed p(
        "box { 0, 4 hollow interior { media { emission 0.2 samples 4 density { function { "
        "select(z - 2.5, 0, pow((z - 2.5) / 0.5, 2) * " +
        std::to_string(b) + ") } } } } }");
    // light = 0.2 * (interval length / 3 sub-intervals) * mean over [2, 3]
    // (to 1e-7: the density goes through a function pattern's colour map)
    return slab(p.scene, 4.0).light.r / (0.2 * 4.0 / 3.0) / b;
}

}  // namespace

TEST(MediaSampling, AdaptiveSplitAsPovray) {
    // povray 3.7 (16-bit linear, 160 densities): the sub-interval splits
    // once the light difference times the interval length (4) reaches
    // aa_threshold 0.1 (summed over R, G, B: 3 * 0.2 * B * 4 >= 0.1) ...
    EXPECT_NEAR(lastSubInterval(0.02625), 1.0 / 3.0, 1e-7);  // no split: (0 + 0 + 1) / 3
    EXPECT_NEAR(lastSubInterval(0.05), 0.5 * (0 + 1.25 / 3.0), 1e-7);
    // ... then in [2.5, 3] (0, 1/4, 1) only the right half differs: it is
    // split, the left half counts (2 * 0 + 1/4) / 3 (povray 0.0034943 at
    // B = 0.07625: 11/64 of the sub-interval; a full split would be 17/96) ...
    EXPECT_NEAR(lastSubInterval(0.07625), 11.0 / 64.0, 1e-7);
    // ... and once both halves differ both are split (povray 0.0095064 at
    // B = 0.20125).
    EXPECT_NEAR(lastSubInterval(0.20125), 17.0 / 96.0, 1e-7);
}

TEST(MediaSampling, ChiSquareInverse) {
    // Tables of the chi-square distribution: the value exceeded with
    // probability 0.9, 0.5 and 0.1.
    EXPECT_NEAR(chiSquareUpperTailInverse(1, 0.9), 0.015791, 1e-6);
    EXPECT_NEAR(chiSquareUpperTailInverse(2, 0.9), 0.210721, 1e-6);
    EXPECT_NEAR(chiSquareUpperTailInverse(1, 0.5), 0.454936, 1e-6);
    EXPECT_NEAR(chiSquareUpperTailInverse(10, 0.1), 15.987179, 1e-5);
    EXPECT_NEAR(chiSquareUpperTailInverse(99, 0.9), 81.449, 1e-3);
    EXPECT_NEAR(chiSquareUpperTail(2, 0.210721), 0.9, 1e-6);
    EXPECT_EQ(chiSquareUpperTailInverse(3, 0.0), 0.0);
}

TEST(MediaSampling, ConfidenceThresholds) {
    // variance * q(k) / q(max - 1), q the chi-square value exceeded with
    // probability `confidence`; 0 for one sample.
    Parsed p(
        "box { 0, 1 hollow interior { media { method 2 samples 2, 400 confidence 0.5 "
        "variance 4 } } }");
    const scene::Media& m = firstInteriorMedia(p);
    ASSERT_EQ(m.sampleThreshold.size(), 400u);
    EXPECT_NEAR(m.sampleThreshold[1], 0.0139209, 1e-6);
    EXPECT_NEAR(m.sampleThreshold[398], 4.0, 1e-9);
    Parsed one("box { 0, 1 hollow interior { media { method 1 samples 1 } } }");
    EXPECT_EQ(firstInteriorMedia(one).sampleThreshold, std::vector<double>{0.0});
}

TEST(MediaSampling, Method2AsPovray) {
    // emission 0.3 absorption 0.3 over 3 units, samples 2 at 1/4 and 3/4:
    // each sample's light 0.3 * 3 dimmed by its distance from the start.
    Parsed p(
        "box { 0, 1 hollow interior { media { method 2 samples 2 emission 0.3 absorption "
        "0.3 } } }");
    const render::MediaResult r = slab(p.scene, 3.0);
    EXPECT_NEAR(r.light.r, 0.9 * (std::exp(-0.225) + std::exp(-0.675)) / 2.0, 1e-12);
    EXPECT_NEAR(r.transmittance.g, std::exp(-0.9), 1e-12);
    // Two intervals (a density makes `intervals` count): the second's light
    // dimmed by the first's optical depth.
    Parsed q(
        "box { 0, 1 hollow interior { media { method 2 samples 1 intervals 2 emission 0.3 "
        "absorption 0.3 density { rgb 1 } } } }");
    const render::MediaResult s = slab(q.scene, 3.0);
    const double half = 0.3 * 1.5 * std::exp(-0.3 * 0.75);
    EXPECT_NEAR(s.light.r, half + half * std::exp(-0.45), 1e-12);
}

TEST(MediaSampling, Method1MeanAsIntegral) {
    // Random points: the mean over many samples is the interval's integral
    // of 0.3 * 3 * exp(-0.3 d) over d in [0, 3], divided by 3.
    Parsed p(
        "box { 0, 1 hollow interior { media { method 1 samples 4000 emission 0.3 absorption "
        "0.3 } } }");
    const render::MediaResult r = slab(p.scene, 3.0);
    EXPECT_NEAR(r.light.r, 0.9 * (1.0 - std::exp(-0.9)) / 0.9, 5e-3);
    EXPECT_NEAR(r.transmittance.g, std::exp(-0.9), 1e-12);
}
