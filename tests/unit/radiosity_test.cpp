#include "render/radiosity.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <vector>

#include "parse_support.h"
#include "render/radiosity_cache.h"
#include "render/radiosity_file.h"
#include "render/renderer.h"
#include "render/world.h"

using namespace frameray;

TEST(RadiosityOctree, QueryFindsEverySampleWhoseReachCoversThePoint) {
    render::RadiosityOctree tree;
    std::vector<Vec3> centers;
    std::vector<double> reach;
    // Samples of very different reach, spread over a wide range.
    for (int i = 0; i < 400; ++i) {
        const double a = i * 0.618034, b = i * 0.414214, c = i * 0.732051;
        centers.emplace_back(std::fmod(a, 1.0) * 200 - 100, std::fmod(b, 1.0) * 20 - 10,
                             std::fmod(c, 1.0) * 50);
        reach.push_back(0.01 + std::fmod(i * 0.37, 1.0) * (i % 7 == 0 ? 30 : 2));
        tree.insert(static_cast<std::uint32_t>(i), centers.back(), reach.back());
    }
    for (int q = 0; q < 300; ++q) {
        const Vec3 p(std::fmod(q * 0.5772, 1.0) * 220 - 110, std::fmod(q * 0.2718, 1.0) * 24 - 12,
                     std::fmod(q * 0.3141, 1.0) * 60 - 5);
        std::set<std::uint32_t> found;
        tree.query(p, [&](std::uint32_t i) { found.insert(i); });
        for (size_t i = 0; i < centers.size(); ++i) {
            if (length(p - centers[i]) >= reach[i]) continue;
            EXPECT_TRUE(found.count(static_cast<std::uint32_t>(i)))
                << "query " << q << " sample " << i;
        }
    }
}

namespace {

render::RadiositySample sampleAt(const Vec3& p, const Vec3& n, double irradiance, double radius,
                                 int depth) {
    render::RadiositySample s;
    s.point = p;
    s.normal = n;
    s.irradiance = RGB(irradiance);
    s.radius = radius;
    s.depth = depth;
    return s;
}

}  // namespace

// The pool of directions (the second value of `count`): samples take their
// rays from it in turn, `count` at a time; every run of the pool is
// cosine-weighted and stratified on its own (within a few percent), and a
// pool of `count` gives every sample the same set.
TEST(Radiosity, EverySampleShootsAStratifiedCosineWeightedRun) {
    for (size_t start = 0; start < 1600; start += 35) {
        double meanCos = 0;
        int within60 = 0;
        Vec3 sum(0);
        for (size_t i = 0; i < 35; ++i) {
            const Vec3 d = render::Radiosity::direction((start + i) % 1600);
            EXPECT_NEAR(length(d), 1.0, 1e-12);
            EXPECT_GE(d.z, 0.0);
            meanCos += d.z / 35;
            within60 += d.z > 0.5;
            sum = sum + d;
        }
        // The mean of cos is 2/3; the share within 60 degrees is 0.75.
        EXPECT_NEAR(meanCos, 2.0 / 3.0, 0.025) << start;
        EXPECT_NEAR(within60 / 35.0, 0.75, 0.03) << start;
        EXPECT_NEAR(sum.x / 35, 0.0, 0.06) << start;
        EXPECT_NEAR(sum.y / 35, 0.0, 0.06) << start;
    }
    // Samples take consecutive runs of the pool, each depth its own turn.
    scene::RadiositySettings set;
    set.count = 35;
    set.directionPool = 100;
    render::Radiosity shared(set, Vec3(0), false);
    render::RadiosityTask task(shared, true, true);
    EXPECT_EQ(task.takeDirections(0, 35), 0u);
    EXPECT_EQ(task.takeDirections(0, 35), 35u);
    EXPECT_EQ(task.takeDirections(1, 17), 0u);
    EXPECT_EQ(task.takeDirections(0, 35), 70u);
    EXPECT_EQ(task.takeDirections(0, 35), 5u);
    // A pool as large as count: every sample starts at 0, the same set.
    set.directionPool = 35;
    render::Radiosity single(set, Vec3(0), false);
    render::RadiosityTask one(single, true, true);
    EXPECT_EQ(one.takeDirections(0, 35), 0u);
    EXPECT_EQ(one.takeDirections(0, 35), 0u);
}

// povray 3.7's directions, measured: a plane under a sky whose colour is
// (x+1)/2, (y+1)/2, (z+1)/2 of the direction, radiosity with recursion
// limit 1 and a reuse radius too small to reuse, so every pixel of a
// 40x40 +WT1 render (16-bit, gamma 1) is one new sample, the mean of its
// rays' directions; counts 5, 7, 9 and 11 solved for the 1600 entries
// (residual 6e-5). Pool entry j is Halton point j+1 (bases 2, 3).
TEST(Radiosity, SamplesShootPovraysDirections) {
    const auto world = [](const Vec3& n, size_t index) {
        Vec3 u, v, w;
        render::Radiosity::sampleFrame(n, u, v, w);
        const Vec3 d = render::Radiosity::direction(index);
        return u * d.x + v * d.y + w * d.z;
    };
    const auto near = [](const Vec3& a, const Vec3& b, double tolerance) {
        return length(a - b) < tolerance;
    };
    // Single entries, normal +z (solved from the counts).
    const Vec3 up(0, 0, 1);
    EXPECT_TRUE(near(world(up, 0), Vec3(0.35351, 0.61236, 0.70713), 1e-3));
    EXPECT_TRUE(near(world(up, 1), Vec3(0.24999, -0.43303, 0.86595), 1e-3));
    EXPECT_TRUE(near(world(up, 2), Vec3(-0.66337, 0.55670, 0.50004), 1e-3));
    EXPECT_TRUE(near(world(up, 3), Vec3(0.33229, 0.12087, 0.93540), 1e-3));
    EXPECT_TRUE(near(world(up, 1599), Vec3(0.08282, -0.04916, 0.99531), 1e-3));
    // Other normals, count 5: pixel k shows the mean of entries 5k..5k+4.
    const auto mean5 = [&](const Vec3& n, size_t k) {
        Vec3 sum(0);
        for (size_t i = 0; i < 5; ++i) sum = sum + world(n, 5 * k + i);
        return sum * 0.2;
    };
    const Vec3 tilted = normalize(Vec3(1, 2, 3));
    EXPECT_TRUE(near(mean5(tilted, 0), Vec3(0.16374, 0.38793, 0.59002), 1e-3));
    EXPECT_TRUE(near(mean5(tilted, 1), Vec3(0.10021, 0.30550, 0.66168), 1e-3));
    EXPECT_TRUE(near(mean5(tilted, 77), Vec3(0.39275, 0.28023, 0.60107), 1e-3));
    const Vec3 side = normalize(Vec3(3, -1, 0.5));
    EXPECT_TRUE(near(mean5(side, 0), Vec3(0.68481, -0.19979, 0.12859), 1e-3));
    EXPECT_TRUE(near(mean5(side, 77), Vec3(0.61627, -0.44360, 0.13225), 1e-3));
    const Vec3 down(0, 0, -1);
    EXPECT_TRUE(near(mean5(down, 0), Vec3(-0.02702, 0.01567, -0.72418), 1e-3));
    EXPECT_TRUE(near(mean5(down, 77), Vec3(0.22594, 0.01741, -0.73669), 1e-3));
    // The frame switches from n x z to n x y at |n.z| = 0.9 (measured
    // between 0.89 and 0.9).
    Vec3 u, v, w;
    render::Radiosity::sampleFrame(normalize(Vec3(0.456, 0, 0.89)), u, v, w);
    EXPECT_TRUE(near(u, Vec3(0, -1, 0), 1e-3));
    render::Radiosity::sampleFrame(normalize(Vec3(0.4146, 0, 0.91)), u, v, w);
    EXPECT_TRUE(near(u, Vec3(-0.91, 0, 0.4146), 1e-3));
    EXPECT_TRUE(near(v, Vec3(0, 1, 0), 1e-3));
    // Facing +y or -y (within 0.001) povray takes the entries as they are,
    // or negated (read from its source; radiosity_down_facing measures it).
    const Vec3 d = render::Radiosity::direction(5);
    EXPECT_TRUE(near(world(Vec3(0, 1, 0), 5), Vec3(d.x, d.z, d.y), 1e-12));
    EXPECT_TRUE(near(world(Vec3(0, -1, 0), 5), Vec3(-d.x, -d.z, -d.y), 1e-12));
    EXPECT_TRUE(near(world(normalize(Vec3(0.01, -1, 0.02)), 5), Vec3(-d.x, -d.z, -d.y), 1e-12));
}

// povray 3.7's settings per bounce: rays halve (at least 5), the error
// bound and reuse limits double, the weight wanted before reusing falls.
TEST(Radiosity, DepthSettingsFollowPovray) {
    scene::RadiositySettings set;
    set.count = 35;
    set.nearestCount = 5;
    set.recursionLimit = 4;
    const render::Radiosity r(set, Vec3(0), false);
    EXPECT_EQ(r.depth(0).rays, 35);
    EXPECT_EQ(r.depth(1).rays, 17);
    EXPECT_EQ(r.depth(2).rays, 8);
    EXPECT_EQ(r.depth(3).rays, 5);
    EXPECT_EQ(r.depth(0).reuseWeight, 5);
    EXPECT_EQ(r.depth(1).reuseWeight, 2);
    EXPECT_EQ(r.depth(2).reuseWeight, 1);
    EXPECT_DOUBLE_EQ(r.depth(2).boundFactor, 4);
    EXPECT_DOUBLE_EQ(r.depth(1).maximumReuse, 2 * set.maximumReuse);
}

TEST(Radiosity, LookupsWeighNearbySamplesAndAskForNewOnes) {
    scene::RadiositySettings set;
    set.errorBound = 1.0;
    set.lowErrorFactor = 0.5;
    set.nearestCount = 5;
    set.recursionLimit = 3;
    render::Radiosity r(set, Vec3(0, 10, 0), false);
    render::RadiosityTask pretrace(r, true, true);
    const Vec3 up(0, 1, 0);
    pretrace.add(sampleAt(Vec3(0, 0, 0), up, 1.0, 1.0, 0));
    // Pretrace: bound error_bound * low_error_factor, weights linear.
    const auto near = pretrace.interpolate(Vec3(0.3, 0, 0), up, 0);
    EXPECT_EQ(near.found, 1);
    EXPECT_NEAR(near.weight, 1 - 0.3 / 0.5, 1e-12);
    // Weight 0.4 is under a quarter of nearest_count: gather more.
    EXPECT_TRUE(pretrace.wantsSample(near, 0));
    EXPECT_EQ(pretrace.interpolate(Vec3(0.6, 0, 0), up, 0).found, 0);
    // Final pass, top level: the smooth weight; any weight is reused.
    render::RadiosityTask final(r, false, false);
    const auto far = final.interpolate(Vec3(0.8, 0, 0), up, 0);
    EXPECT_NEAR(far.weight, 2 * 0.2 * 0.2, 1e-12);
    EXPECT_FALSE(final.wantsSample(far, 0));
    EXPECT_TRUE(final.wantsSample({}, 0));
    EXPECT_NEAR(final.interpolate(Vec3(0.3, 0, 0), up, 0).weight, 1 - 2 * 0.3 * 0.3, 1e-12);
    // The normals' divergence counts twice its root: cos 0.98 adds 0.2828.
    const Vec3 tilted = normalize(Vec3(std::sqrt(1 - 0.98 * 0.98), 0.98, 0));
    const double t = 2 * std::sqrt(0.02);
    EXPECT_NEAR(final.interpolate(Vec3(0, 0, 0), tilted, 0).weight, 1 - 2 * t * t, 1e-9);
    // Facing away, or lying behind the sample's surface: not used.
    EXPECT_EQ(final.interpolate(Vec3(0.3, 0, 0), Vec3(0, -1, 0), 0).found, 0);
    EXPECT_EQ(final.interpolate(Vec3(0.2, -0.2, 0), up, 0).found, 0);
    // A lookup light that matters little (weight under 1/4) widens the bound.
    EXPECT_EQ(final.interpolate(Vec3(1.1, 0, 0), up, 0, 1.0).found, 0);
    EXPECT_EQ(final.interpolate(Vec3(1.1, 0, 0), up, 0, 0.05).found, 1);
    // Deeper lookups use only samples as deep, reuse with less weight.
    EXPECT_EQ(final.interpolate(Vec3(0.1, 0, 0), up, 1).found, 0);
    EXPECT_TRUE(pretrace.wantsSample({RGB(0.0), 1, 0.4}, 1));
    EXPECT_FALSE(pretrace.wantsSample({RGB(0.0), 1, 0.5}, 1));
    EXPECT_FALSE(pretrace.wantsSample({RGB(0.0), 1, 0.25}, 2));
    // A deeper sample is filed in a cell sized for an eighth of its reach:
    // lookups outside the (widened) cell never see it, even well within
    // the error bound. Radius 1, depth 1: reach 1 * 2 / 8 = 0.25, cell
    // [10, 11) seen from (9.5, 11.5).
    pretrace.add(sampleAt(Vec3(10, 0, 0), up, 0.5, 1.0, 1));
    EXPECT_EQ(final.interpolate(Vec3(11.4, 0, 0), up, 1).found, 1);
    EXPECT_EQ(final.interpolate(Vec3(9.4, 0, 0), up, 1).found, 0);
    // A final-pass block keeps its samples to itself.
    final.add(sampleAt(Vec3(5, 0, 0), up, 0.5, 1.0, 0));
    EXPECT_EQ(final.interpolate(Vec3(5, 0, 0), up, 0).found, 1);
    EXPECT_EQ(render::RadiosityTask(r, false, false).interpolate(Vec3(5, 0, 0), up, 0).found, 0);
}

// povray 3.7: a sample counts by the quality of its rays (a ray whose own
// lookup, a bounce deeper, found under a quarter of the weight it needed
// counts that much less), so a lookup near a half-quality sample finds
// half the weight, and may have to gather where it would have reused.
TEST(Radiosity, LookupsWeighSamplesByTheirQuality) {
    scene::RadiositySettings set;
    set.errorBound = 1.0;
    set.lowErrorFactor = 1.0;
    set.nearestCount = 2;
    render::Radiosity r(set, Vec3(0, 10, 0), false);
    render::RadiosityTask pretrace(r, true, true);
    const Vec3 up(0, 1, 0);
    render::RadiositySample full = sampleAt(Vec3(0, 0, 0), up, 1.0, 1.0, 0);
    render::RadiositySample half = sampleAt(Vec3(10, 0, 0), up, 1.0, 1.0, 0);
    half.quality = 0.5;
    pretrace.add(full);
    pretrace.add(half);
    const auto a = pretrace.interpolate(Vec3(0.4, 0, 0), up, 0);
    const auto b = pretrace.interpolate(Vec3(10.4, 0, 0), up, 0);
    EXPECT_NEAR(a.weight, 0.6, 1e-12);
    EXPECT_NEAR(b.weight, 0.3, 1e-12);
    EXPECT_FALSE(pretrace.wantsSample(a, 0));
    EXPECT_TRUE(pretrace.wantsSample(b, 0));
}

namespace {

render::FrameImage renderText(const std::string& text, int threads, render::FrameStats& stats,
                              render::FrameSettings settings = {}, int width = 48,
                              int height = 36) {
    test_support::ParsedScene parsed(text);
    render::World world(parsed.scene);
    settings.width = width;
    settings.height = height;
    settings.blockSize = 8;
    tbb::task_arena arena(threads);
    render::FrameImage image;
    arena.execute([&] { image = render::renderFrame(world, settings, stats); });
    return image;
}

std::string room(bool radiosity) {
    return std::string("#version 3.7;\nglobal_settings { assumed_gamma 1 ") +
           (radiosity ? "radiosity { count 40 recursion_limit 2 nearest_count 3 "
                        "pretrace_start 0.1 pretrace_end 0.05 }"
                      : "") +
           R"( }
camera { location <0, 1, -3> look_at <0, 0.5, 0> }
light_source { <1, 3, -1> rgb 1 }
box { <-2, 0, -4>, <2, 3, 2> inverse pigment { rgb 0.8 } finish { ambient 0 diffuse 0.7 } }
sphere { <0.3, 0.5, 0>, 0.5 pigment { rgb <1, 0.2, 0.1> } finish { ambient 0 diffuse 0.7 } }
)";
}

}  // namespace

TEST(Radiosity, ImageDoesNotDependOnTheThreadCount) {
    render::FrameStats one, two;
    const render::FrameImage a = renderText(room(true), 1, one);
    const render::FrameImage b = renderText(room(true), 2, two);
    EXPECT_EQ(a.rgb, b.rgb);
    EXPECT_GT(one.rays.radiosity, 0u);
    EXPECT_EQ(one.rays.radiosity, two.rays.radiosity);
    EXPECT_EQ(one.radiosity.samples, two.radiosity.samples);
}

// A white plane under a white sky with one pretrace pass of cells a third
// of the image's longer side, seen by an orthographic camera whose right
// and up vectors are `rightUp` ("x * W up y * H").
std::string pretracePlane(const std::string& rightUp) {
    return R"(#version 3.7;
global_settings { radiosity { count 5 nearest_count 1 error_bound 0.0001 recursion_limit 1
  pretrace_start 0.3334 pretrace_end 0.3334 minimum_reuse 0.00001 maximum_reuse 0.00002 } }
camera { orthographic location <0, 0, -10> direction z right )" +
           rightUp + R"( }
sky_sphere { pigment { rgb 1 } }
plane { z, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
)";
}

// The samples the pretrace passes of a one-thread render of `scene` left.
std::vector<render::RadiositySample> pretraceSamples(const std::string& scene, int width,
                                                     int height) {
    render::FrameSettings keep;
    keep.keepRadiosity = true;
    render::FrameStats stats;
    const render::FrameImage image = renderText(scene, 1, stats, keep, width, height);
    std::vector<render::RadiositySample> pretrace;
    for (const render::RadiositySample& s : image.radiosityCache)
        if (s.pass != 0) pretrace.push_back(s);
    return pretrace;
}

// povray 3.7's pretrace spots lie at their cells' centres (moved by up to a
// pixel) even where the cell reaches past the image's edge (measured from
// the positions in its cache file: rad_def_test at 160x120, spots near
// y = 121.6 +- 1). Here 48x36 in cells of 16 pixels: the last row of spots
// is near y = 40, world y = 1.8 - 40/10 = -2.2; kept within the image
// they stopped at -1.8.
TEST(Radiosity, PretraceSpotsMayLieBeyondTheImage) {
    double lowest = 0;
    const auto pretrace = pretraceSamples(pretracePlane("x * 4.8 up y * 3.6"), 48, 36);
    for (const render::RadiositySample& s : pretrace) lowest = std::min(lowest, s.point.y);
    EXPECT_EQ(pretrace.size(), 9u);  // 3 x 3 spots
    EXPECT_LT(lowest, -2.05);
    EXPECT_GT(lowest, -2.35);
}

// povray 3.7 sizes the pretrace cells from the image's longer side: a
// portrait image 36 x 48 with pretrace 0.3334 has cells of 16 pixels, 3 x 3
// spots (from the width, 12 pixels: 3 x 4).
TEST(Radiosity, PretraceCellsFollowTheLongerSide) {
    EXPECT_EQ(pretraceSamples(pretracePlane("x * 3.6 up y * 4.8"), 36, 48).size(), 9u);
}

TEST(Radiosity, NoRadiosityRayWithoutARadiosityBlock) {
    render::FrameStats stats;
    renderText(room(false), 1, stats);
    EXPECT_EQ(stats.rays.radiosity, 0u);
    EXPECT_EQ(stats.radiosity.samples, 0u);
    EXPECT_GT(stats.rays.camera, 0u);
}

// nearest_count's second value (adaptive pretrace): a part of a tile stops
// refining once its lookups' weights cover that value on average. povray
// 3.7 on a room at 160x120, nearest_count 10 against 10, 4: 4234 against
// 3025 samples (0.71); frameray 4284 against 3115 (0.73). Here, smaller.
TEST(Radiosity, AdaptivePretraceStopsWhereCovered) {
    auto scene = [](const std::string& nearest) {
        return "#version 3.7;\nglobal_settings { assumed_gamma 1 radiosity { count 40 "
               "nearest_count " +
               nearest +
               " error_bound 0.8 pretrace_start 0.16 pretrace_end 0.01 } }\n"
               "camera { location <0, 1.5, -2.8> look_at <0, 1, 0> angle 70 }\n"
               "light_source { <0.5, 2.6, -0.5> rgb 1 }\n"
               "box { <-2, 0, -3>, <2, 3, 2> inverse pigment { rgb 0.85 } finish { ambient 0 "
               "diffuse 0.75 } }\n"
               "sphere { <-0.4, 0.5, 0.3>, 0.5 pigment { rgb <0.9, 0.8, 0.3> } finish { "
               "ambient 0 diffuse 0.75 } }\n";
    };
    render::FrameStats full, adaptive;
    auto render = [&](const std::string& text, render::FrameStats& stats) {
        test_support::ParsedScene parsed(text);
        render::World world(parsed.scene);
        render::FrameSettings settings;
        settings.width = 160;
        settings.height = 120;
        tbb::task_arena arena(1);
        arena.execute([&] { render::renderFrame(world, settings, stats); });
    };
    render(scene("10"), full);
    render(scene("10, 4"), adaptive);
    EXPECT_LT(adaptive.radiosity.samples, full.radiosity.samples * 0.85);
    EXPECT_GT(adaptive.radiosity.samples, full.radiosity.samples * 0.5);
}

TEST(RadiosityParser, SettingsRangesAndWarnings) {
    test_support::ParsedScene p(
        "global_settings { radiosity { count 50, 400 nearest_count 6, 2 error_bound 0.4 "
        "low_error_factor 0.7 recursion_limit 3 pretrace_start 0.1 pretrace_end 0.01 "
        "minimum_reuse 0.2 gray_threshold 0.5 brightness 2 adc_bailout 0.02 always_sample on "
        "max_sample 3 normal on media off } }\n"
        "sphere { 0, 1 no_radiosity radiosity { importance 0.25 } }");
    ASSERT_TRUE(p.scene.globals.radiosity);
    const scene::RadiositySettings& r = *p.scene.globals.radiosity;
    EXPECT_EQ(r.count, 50);
    EXPECT_EQ(r.directionPool, 400);
    EXPECT_EQ(r.nearestCount, 6);
    EXPECT_EQ(r.nearestCountPretrace, 2);
    EXPECT_DOUBLE_EQ(r.errorBound, 0.4);
    EXPECT_EQ(r.recursionLimit, 3);
    EXPECT_TRUE(r.alwaysSample);
    EXPECT_TRUE(r.normal);
    EXPECT_FALSE(r.media);
    // minimum_reuse above half the maximum: povray raises the maximum.
    EXPECT_DOUBLE_EQ(r.maximumReuse, 0.4);
    EXPECT_NE(p.sink.warnings.find("Increasing maximum_reuse to 0.400000"), std::string::npos);
    ASSERT_EQ(p.scene.objects.size(), 1u);
    EXPECT_TRUE(p.scene.objects[0]->noRadiosity);
    EXPECT_DOUBLE_EQ(p.scene.objects[0]->radiosityImportance, 0.25);

    using test_support::parseErrorOf;
    EXPECT_NE(parseErrorOf("global_settings { radiosity { nearest_count 30 } }")
                  .find("Radiosity nearest count must be a value from 1 to 20."),
              std::string::npos);
    EXPECT_NE(parseErrorOf("global_settings { radiosity { count 50, 10 } }")
                  .find("can not be more than direction pool size"),
              std::string::npos);
    EXPECT_NE(parseErrorOf("global_settings { radiosity { pretrace_start 0.01 pretrace_end 0.1 } }")
                  .find("pretrace end must be smaller than or equal to pretrace start"),
              std::string::npos);
    EXPECT_NE(parseErrorOf("sphere { 0, 1 radiosity { importance 0 } }")
                  .find("importance must be greater than 0.0 and at most 1.0"),
              std::string::npos);
}

TEST(RadiosityFile, SamplesComeBackBitForBitAndForeignFilesAreRefused) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "frameray_radiosity_file_test";
    fs::create_directories(dir);
    std::vector<render::RadiositySample> samples = {
        sampleAt(Vec3(0.1, -2.0 / 3.0, 1e-9), Vec3(0, 1, 0), 0.25, 0.123456789, 0),
        sampleAt(Vec3(-5, 4, 3), normalize(Vec3(1, 1, 1)), 0.0, 1e6, 2)};
    samples[0].irradiance.g = 1.0 / 7.0;
    samples[0].nearest = 0.0123;
    samples[0].toNearest = normalize(Vec3(1, 2, 3));
    samples[1].quality = 0.3125;  // a sample of weakly rated rays counts less when looked up
    render::writeRadiosityFile(dir / "a.rca", samples);
    const std::vector<render::RadiositySample> back = render::readRadiosityFile(dir / "a.rca");
    ASSERT_EQ(back.size(), samples.size());
    for (size_t i = 0; i < samples.size(); ++i) {
        EXPECT_EQ(back[i].point.x, samples[i].point.x);
        EXPECT_EQ(back[i].point.y, samples[i].point.y);
        EXPECT_EQ(back[i].point.z, samples[i].point.z);
        EXPECT_EQ(back[i].normal.x, samples[i].normal.x);
        EXPECT_EQ(back[i].irradiance.g, samples[i].irradiance.g);
        EXPECT_EQ(back[i].radius, samples[i].radius);
        EXPECT_EQ(back[i].depth, samples[i].depth);
        EXPECT_EQ(back[i].nearest, samples[i].nearest);
        EXPECT_EQ(back[i].toNearest.y, samples[i].toNearest.y);
        EXPECT_EQ(back[i].quality, samples[i].quality);
    }
    // The previous format (no quality) is still read: quality 1.
    std::ofstream(dir / "old.rca")
        << "frameray radiosity cache 2\n0 1 2 3 0 0 1 0.5 0.5 0.5 2 1 0 0 1\n";
    const std::vector<render::RadiositySample> old = render::readRadiosityFile(dir / "old.rca");
    ASSERT_EQ(old.size(), 1u);
    EXPECT_EQ(old[0].quality, 1.0);
    EXPECT_EQ(old[0].radius, 2.0);
    // A povray cache file (its sample lines start with C and a depth).
    std::ofstream(dir / "pov.rca") << "C2\t-1.29\t-0.9\t0.76\t7ffe7f\t0.0985\t0.0988\t0.1161\n";
    try {
        render::readRadiosityFile(dir / "pov.rca");
        ADD_FAILURE() << "a povray file was read";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("not a frameray radiosity cache file"),
                  std::string::npos);
    }
    std::ofstream(dir / "bad.rca") << "frameray radiosity cache 3\n0 1 2 3\n";
    EXPECT_THROW(render::readRadiosityFile(dir / "bad.rca"), std::runtime_error);
    EXPECT_THROW(render::readRadiosityFile(dir / "missing.rca"), std::runtime_error);
    fs::remove_all(dir);
}

// A frame started from another frame's whole cache (Radiosity_From_File,
// Radiosity_Stable) gathers few new samples (the pretrace still wants
// nearest_count near each of its points) and renders the same bytes for
// any thread count.
TEST(Radiosity, AFrameStartedFromAFullCacheReusesIt) {
    render::FrameSettings keep;
    keep.keepRadiosity = true;
    render::FrameStats first;
    render::FrameImage seeded = renderText(room(true), 2, first, keep);
    ASSERT_GT(seeded.radiosityCache.size(), 0u);
    EXPECT_EQ(seeded.radiosityCache.size(), first.radiosity.samples);
    render::FrameStats firstAgain;
    render::FrameImage again = renderText(room(true), 1, firstAgain, keep);
    EXPECT_EQ(seeded.radiosityCache.size(), again.radiosityCache.size());

    render::FrameSettings start;
    start.radiosityStart =
        std::make_shared<const std::vector<render::RadiositySample>>(seeded.radiosityCache);
    render::FrameStats one, two;
    const render::FrameImage a = renderText(room(true), 1, one, start);
    const render::FrameImage b = renderText(room(true), 2, two, start);
    EXPECT_EQ(a.rgb, b.rgb);
    EXPECT_EQ(one.radiosity.samples, two.radiosity.samples);
    EXPECT_LT(one.radiosity.samples * 4, seeded.radiosityCache.size());
    EXPECT_GT(one.radiosity.reused, 0u);
    EXPECT_TRUE(a.radiosityCache.empty());
}
