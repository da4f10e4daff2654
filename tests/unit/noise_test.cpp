// Noise and noise-based patterns against values measured from povray 3.7
// (#debug of f_noise3d, vturbulence and function { pattern { ... } } at
// these points, printed with 17 digits).
#include "scene/noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "scene/crackle.h"
#include "scene/patterns.h"
#include "util/lattice_hash.h"

using namespace frameray;
using namespace frameray::scene;

namespace {

struct Sample {
    double x, y, z, value;
};

constexpr double kTolerance = 1e-12;

}  // namespace

TEST(Noise, RangeCorrectedGeneratorMatchesPovray) {
    const Sample samples[] = {
        {-36.563575588759875, 34.74337369372327, 26.377461897661405, 0.5201734733828024},
        {-24.49309742605783, -0.4564912908059071, -5.050893521126184, 0.33369318507633683},
        {15.15929727227629, 28.872335113551316, -40.61404132257651, 0.372474402259989},
        {-47.16525234779937, 33.57651039198697, -6.723293209494663, 0.47355019655627845},
        {26.2280082457942, -49.78939466488893, -5.461280594519856, 0.7566279370761886},
        {0, 0, 0, 0.29832243930790991},
        {0.3, 0.2, 0.1, 0.37343896248832870},
    };
    for (const Sample& s : samples)
        EXPECT_NEAR(solidNoise({s.x, s.y, s.z}, NoiseGenerator::RangeCorrected), s.value,
                    kTolerance)
            << s.x << " " << s.y << " " << s.z;
}

TEST(Noise, OriginalGeneratorMatchesPovrayIncludingClipping) {
    const Sample samples[] = {
        {0.5, 0.0, 0.0, 0.26651424999999995},
        {0.0, 0.5, 0.0, 0.0},  // clipped at 0
        {0.0, 0.0, 0.5, 0.52916775},
        {0.25, 0.0, 0.0, 0.23113545312499995},
        {-19.873234048428767, -46.898824853025, 36.552723697894564, 0.0},
        {-2.7250911334533185, 21.88239240658031, 37.881280025548165, 0.6982400807379048},
        {21.412948361120257, 42.109866758387454, -10.503659599925605, 0.535445995431602},
        {30.090877098522824, -5.5378943949239385, 43.55867217045211, 0.646153728768804},
    };
    for (const Sample& s : samples)
        EXPECT_NEAR(solidNoise({s.x, s.y, s.z}, NoiseGenerator::Original), s.value, kTolerance)
            << s.x << " " << s.y << " " << s.z;
}

// noise_generator 3: povray's f_noise_generator(x, y, z, 3) at these points.
TEST(Noise, PerlinGeneratorMatchesPovray) {
    const Sample samples[] = {
        {0.1, 0.2, 0.3, 0.65226085372009845},
        {1.5, 2.25, -3.75, 0.73358656915214959},
        {-0.3, -0.7, -1.9, 0.43799933830006715},
        {10.1, -20.3, 5.7, 0.37734394225072976},
        {123.456, -789.012, 345.678, 0.51139163957296963},
        {0, 0, 0, 0.51135430537303594},
        {-55.5, 44.4, -33.3, 0.49790128050020410},
        {0.9999, 0.0001, -0.0001, 0.52011025310398096},
    };
    for (const Sample& s : samples)
        EXPECT_NEAR(solidNoise({s.x, s.y, s.z}, NoiseGenerator::Perlin), s.value, kTolerance)
            << s.x << ", " << s.y << ", " << s.z;
}

TEST(NoisePatterns, PerlinGeneratorPatternsMatchPovray) {
    const Vec3 a{0.1, 0.2, 0.3}, b{1.5, 2.25, -3.75};
    auto value = [&](PatternKind kind, const Vec3& p) {
        Pattern pat;
        pat.kind = kind;
        pat.noiseGenerator = NoiseGenerator::Perlin;
        return pat.value(p);
    };
    EXPECT_NEAR(value(PatternKind::Wrinkles, a), 0.73837829018384549, kTolerance);
    EXPECT_NEAR(value(PatternKind::Wrinkles, b), 0.64926705366418880, kTolerance);
    EXPECT_NEAR(value(PatternKind::Agate, a), 0.99730066147025254, kTolerance);
    EXPECT_NEAR(value(PatternKind::Agate, b), 0.45622300260647208, kTolerance);
    EXPECT_NEAR(value(PatternKind::Granite, a), 0.18178678951938690, kTolerance);
    EXPECT_NEAR(value(PatternKind::Granite, b), 0.03941335712951002, kTolerance);
}

TEST(Noise, VectorNoiseMatchesPovrayVturbulence) {
    // vturbulence(2, 0.5, 1, P) is one octave: the vector noise itself.
    const double samples[][6] = {
        {0.3, 0.2, 0.1, -0.29007535236811371, -0.05351275171700226, -0.39439321300652036},
        {45.60342718892494, 44.782748705934935, -44.34486322731913, 0.20857270301384565,
         -0.4733230725884307, -0.218928757512868},
        {-41.512800484107835, 33.54988781294496, 23.596998906852335, 0.00906660130905137,
         0.34958990683642915, -0.04515662621469517},
        {10.680173364083792, 8.120401711200309, -34.161712974519446, -0.7084152385748613,
         -0.27717517250887946, -0.12407743478823266},
    };
    for (const auto& s : samples) {
        const Vec3 v = vectorNoise({s[0], s[1], s[2]});
        EXPECT_NEAR(v.x, s[3], kTolerance);
        EXPECT_NEAR(v.y, s[4], kTolerance);
        EXPECT_NEAR(v.z, s[5], kTolerance);
    }
}

namespace {

double patternValue(PatternKind kind, const Vec3& p, void (*setup)(Pattern&) = nullptr) {
    Pattern pat;
    pat.kind = kind;
    if (kind == PatternKind::Marble || kind == PatternKind::Wood) pat.waveType = WaveType::Triangle;
    if (setup) setup(pat);
    return pat.value(p);
}

const Vec3 kP0{-2.6395191026256546, -3.968339657692842, -1.0394175738931901};
const Vec3 kP1{-3.4502772919758975, -4.334849043204101, -0.9840898551492518};

}  // namespace

TEST(NoisePatterns, MatchPovrayPatternFunctions) {
    EXPECT_NEAR(patternValue(PatternKind::Granite, kP0), 0.34185101330111767, kTolerance);
    EXPECT_NEAR(patternValue(PatternKind::Granite, kP1), 0.28835114204855755, kTolerance);
    EXPECT_NEAR(patternValue(PatternKind::Agate, kP0), 0.746463514303355, kTolerance);
    EXPECT_NEAR(patternValue(PatternKind::Agate, kP1), 0.7956036904017512, kTolerance);
    EXPECT_NEAR(patternValue(PatternKind::Wrinkles, kP0), 0.23298340394694425, kTolerance);
    EXPECT_NEAR(patternValue(PatternKind::Wrinkles, kP1), 0.20167583714075987, kTolerance);
    EXPECT_NEAR(patternValue(PatternKind::Ripples, kP0), 0.6272731478803285, kTolerance);
    EXPECT_NEAR(patternValue(PatternKind::Ripples, kP1), 0.42477030681735395, kTolerance);
    EXPECT_NEAR(patternValue(PatternKind::Waves, kP0), 0.5023872732668132, kTolerance);
    EXPECT_NEAR(patternValue(PatternKind::Waves, kP1), 0.5825807751855292, kTolerance);
}

TEST(NoisePatterns, TurbulenceMatchesPovray) {
    // marble turbulence 0.7 octaves 3 omega 0.6 lambda 2.5
    auto marble = [](Pattern& p) { p.turbulence = Turbulence{Vec3(0.7), 3, 0.6f, 2.5f}; };
    EXPECT_NEAR(patternValue(PatternKind::Marble, kP0, marble), 0.8337078873529187, kTolerance);
    EXPECT_NEAR(patternValue(PatternKind::Marble, kP1, marble), 0.21575324798868678, kTolerance);
    // wood turbulence <0.3, 0.2, 0.1>
    auto wood = [](Pattern& p) { p.turbulence = Turbulence{Vec3(0.3, 0.2, 0.1), 6, 0.5f, 2.0f}; };
    EXPECT_NEAR(patternValue(PatternKind::Wood, kP0, wood), 0.2023856858219819, kTolerance);
    EXPECT_NEAR(patternValue(PatternKind::Wood, kP1, wood), 0.8527958276743233, kTolerance);
    // bozo turbulence 0.5 (a displacement of the point)
    auto bozo = [](Pattern& p) { p.turbulence = Turbulence{Vec3(0.5), 6, 0.5f, 2.0f}; };
    EXPECT_NEAR(patternValue(PatternKind::Bozo, kP0, bozo), 0.39388569139331314, kTolerance);
    EXPECT_NEAR(patternValue(PatternKind::Bozo, kP1, bozo), 0.2954656318841392, kTolerance);
}

TEST(NoisePatterns, BlockPatternsUsePovraysTolerance) {
    Pattern checker;
    checker.kind = PatternKind::Checker;
    // measured: 5e-11 below a cell boundary counts as on it, 2e-10 does not
    EXPECT_EQ(checker.index({0.5, -5e-11, 0.5}), 0);
    EXPECT_EQ(checker.index({0.5, -2e-10, 0.5}), 1);
    EXPECT_EQ(checker.index({0.5, -0.0005, 0.5}), 1);
}

TEST(Warps, BlackHoleMatchesPovray) {
    // gradient x warp { black_hole 0, 2 [strength 0.5 falloff 3 [inverse]] }
    auto gradientWith = [](const Warp& w, const Vec3& p) {
        Pattern pat;
        pat.kind = PatternKind::Gradient;
        pat.addWarp(w);
        return pat.value(p);
    };
    Warp w;
    w.kind = Warp::Kind::BlackHole;
    w.radius = 2;
    EXPECT_NEAR(gradientWith(w, {0.1, 0, 0}), 0.19025, 1e-12);
    w.strength = 0.5;
    w.falloff = 3;
    EXPECT_NEAR(gradientWith(w, {0.1, 0, 0}), 0.14286875, 1e-12);
    EXPECT_NEAR(gradientWith(w, {0.1, 0.3, 0}), 0.129835275195, 1e-11);
    w.inverse = true;
    EXPECT_NEAR(gradientWith(w, {0.1, 0, 0}), 0.05713125, 1e-12);
}

TEST(Warps, MappingWarpsMatchPovray) {
    // Warped points measured with povray 3.7's pattern functions
    // (gradient x/y/z scale 1000 translate -500 before the warp).
    auto near = [](const Vec3& a, const Vec3& b) {
        EXPECT_NEAR(a.x, b.x, 5e-7);
        EXPECT_NEAR(a.y, b.y, 5e-7);
        EXPECT_NEAR(a.z, b.z, 5e-7);
    };
    Warp w;
    w.kind = Warp::Kind::Cylindrical;
    near(w.apply({0.3, 0.2, 0.7}), {0.1855595, 0.2, 0.7615773});
    near(w.apply({0, 0.5, -2}), {0.75, 0.5, 2});
    near(w.apply({0, 0.4, 0}), {0, 0.4, 0});  // on the axis: unchanged
    w.distExp = 2;
    near(w.apply({0.3, 0.2, 0.7}), {0.1076245, 0.2, 0.7615773});
    w.distExp = 0;
    w.orientation = normalize(Vec3(1, 1, 0));
    near(w.apply({0.3, 0.2, 0.7}), {0.6697268, -0.3970951, 0.0102110});
    w.kind = Warp::Kind::Spherical;
    w.orientation = {0, 0, 1};
    near(w.apply({0.3, 0.2, 0.7}), {0.1855595, 0.5817464, 0.7874008});
    w.distExp = 1.5;
    near(w.apply({1.5, -0.7, -0.4}), {2.1301070, 0.8114888, 1.7029386});
    w.kind = Warp::Kind::Toroidal;
    w.distExp = 0;
    near(w.apply({0.3, 0.2, 0.7}), {0.1855595, 0.8889125, 0.3111999});
    w.majorRadius = 2;
    w.distExp = 2;
    near(w.apply({-0.5, 1.2, 0.25}), {1.4987321, 3.1278043, 1.8752152});
    w.kind = Warp::Kind::Planar;
    w.orientation = normalize(Vec3(1, 2, 3));
    w.planeDistance = 0.3;
    near(w.apply({0.3, 0.2, 0.7}), {0.4810702, 0.0534522, 0.2672612});
}

// The vector noise the CPU runs (AVX2 where there is one) must give the
// portable form's results to the last bit: images may not depend on the
// machine.
TEST(Noise, VectorNoiseEqualsPortableFormBitForBit) {
    uint64_t state = 0x9E3779B97F4A7C15ULL;
    auto next = [&state] {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(state >> 11) * 0x1.0p-53;
    };
    for (int i = 0; i < 20000; ++i) {
        const double scale = i % 3 == 0 ? 1.0 : (i % 3 == 1 ? 100.0 : 1e4);
        const Vec3 p((next() - 0.5) * scale, (next() - 0.5) * scale, (next() - 0.5) * scale);
        const Vec3 a = vectorNoise(p), b = vectorNoisePortable(p);
        ASSERT_EQ(a.x, b.x) << p.x << " " << p.y << " " << p.z;
        ASSERT_EQ(a.y, b.y);
        ASSERT_EQ(a.z, b.z);
    }
}

// Far out (a ground fog with turbulence 1e7 units away, huge scales) the
// lattice index is beyond int: it takes INT_MIN as x86 truncation gives it
// (povray's and our earlier builds' values) instead of the undefined C++
// conversion the render fuzzer found; cell patterns clamp their index.
TEST(Noise, FarCoordinatesHaveDefinedLatticeCells) {
    EXPECT_EQ(latticeTruncate(3.7), 3);
    EXPECT_EQ(latticeTruncate(-3.7), -3);
    EXPECT_EQ(latticeTruncate(1e20), std::numeric_limits<int>::min());
    EXPECT_EQ(latticeTruncate(-6.2977e9), std::numeric_limits<int>::min());
    EXPECT_EQ(latticeTruncate(std::nan("")), std::numeric_limits<int>::min());
    EXPECT_EQ(latticeFloor(-3.5), -4);
    EXPECT_EQ(latticeFloor(1e20), 1 << 30);
    EXPECT_EQ(latticeFloor(-1e20), -(1 << 30));
    EXPECT_EQ(latticeFloor(std::nan("")), 0);
    for (const double far : {1e10, -6.2977e9, 3e15}) {
        const double n = solidNoise({far, 0.5, far}, NoiseGenerator::RangeCorrected);
        EXPECT_TRUE(std::isfinite(n)) << far;
        EXPECT_EQ(n, solidNoise({far, 0.5, far}, NoiseGenerator::RangeCorrected)) << far;
        EXPECT_TRUE(std::isfinite(
            crackle({far, far, 1}, CrackleSettings{}, NoiseGenerator::RangeCorrected)))
            << far;
    }
}
