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

TEST(Radiosity, DirectionsAreCosineWeightedAndSpread) {
    scene::RadiositySettings set;
    set.count = 400;
    set.recursionLimit = 2;
    const render::Radiosity r(set, Vec3(0), false);
    std::vector<Vec3> scratch;
    const auto dirs = r.directions(400, scratch);
    ASSERT_EQ(dirs.size(), 400u);
    // Cosine-weighted over the hemisphere: the mean of cos is 2/3 and the
    // share within 60 degrees of the normal is sin^2(60) = 0.75.
    double meanCos = 0;
    int within60 = 0;
    Vec3 sum(0);
    for (const Vec3& d : dirs) {
        EXPECT_NEAR(length(d), 1.0, 1e-12);
        EXPECT_GE(d.z, 0.0);
        meanCos += d.z / dirs.size();
        within60 += d.z > 0.5;
        sum = sum + d;
    }
    EXPECT_NEAR(meanCos, 2.0 / 3.0, 0.005);
    EXPECT_NEAR(within60 / 400.0, 0.75, 0.005);
    EXPECT_NEAR(sum.x / 400, 0.0, 0.01);
    EXPECT_NEAR(sum.y / 400, 0.0, 0.01);
    // Deeper bounces shoot half as many rays, from sets made once.
    EXPECT_EQ(r.directions(200, scratch).size(), 200u);
    EXPECT_EQ(r.directions(37, scratch).size(), 37u);
}

TEST(Radiosity, LookupsBlendNearbySamplesAndAskForNewOnes) {
    scene::RadiositySettings set;
    set.errorBound = 1.0;
    set.lowErrorFactor = 0.5;
    set.nearestCount = 2;
    render::Radiosity r(set, Vec3(0, 10, 0), false);
    render::RadiosityTask pretrace(r, true, true);
    const Vec3 up(0, 1, 0);
    pretrace.add({Vec3(0, 0, 0), up, RGB(1.0), 1.0, 0});
    // Within error_bound * low_error_factor of one sample: one found, not
    // enough while pretracing (nearest_count 2), enough in the final pass.
    EXPECT_EQ(pretrace.interpolate(Vec3(0.3, 0, 0), up, 0).found, 1);
    EXPECT_TRUE(pretrace.wantsSample(1, 0));
    render::RadiosityTask final(r, false, false);
    EXPECT_FALSE(final.wantsSample(1, 0));
    EXPECT_TRUE(final.wantsSample(0, 0));
    // Too far, facing away, or gathered deeper: not used.
    EXPECT_EQ(pretrace.interpolate(Vec3(0.6, 0, 0), up, 0).found, 0);
    EXPECT_EQ(final.interpolate(Vec3(0.3, 0, 0), Vec3(0, -1, 0), 0).found, 0);
    pretrace.add({Vec3(0.2, 0, 0), up, RGB(0.0), 1.0, 1});
    EXPECT_EQ(final.interpolate(Vec3(0.1, 0, 0), up, 0).found, 1);
    // A lookup one bounce deep uses only samples gathered as deep (a
    // shallower sample holds more bounces than the lookup may see).
    const auto deeper = final.interpolate(Vec3(0.1, 0, 0), up, 1);
    EXPECT_EQ(deeper.found, 1);
    EXPECT_EQ(deeper.irradiance.r, 0.0);
    // A final-pass block keeps its samples to itself.
    final.add({Vec3(5, 0, 0), up, RGB(0.5), 1.0, 0});
    EXPECT_EQ(final.interpolate(Vec3(5, 0, 0), up, 0).found, 1);
    EXPECT_EQ(render::RadiosityTask(r, false, false).interpolate(Vec3(5, 0, 0), up, 0).found, 0);
}

namespace {

render::FrameImage renderText(const std::string& text, int threads, render::FrameStats& stats,
                              render::FrameSettings settings = {}) {
    test_support::ParsedScene parsed(text);
    render::World world(parsed.scene);
    settings.width = 48;
    settings.height = 36;
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

TEST(Radiosity, NoRadiosityRayWithoutARadiosityBlock) {
    render::FrameStats stats;
    renderText(room(false), 1, stats);
    EXPECT_EQ(stats.rays.radiosity, 0u);
    EXPECT_EQ(stats.radiosity.samples, 0u);
    EXPECT_GT(stats.rays.camera, 0u);
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
    const std::vector<render::RadiositySample> samples = {
        {Vec3(0.1, -2.0 / 3.0, 1e-9), Vec3(0, 1, 0), RGB(0.25, 1.0 / 7.0, 3.0), 0.123456789, 0},
        {Vec3(-5, 4, 3), normalize(Vec3(1, 1, 1)), RGB(0.0), 1e6, 2}};
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
    }
    // A povray cache file (its sample lines start with C and a depth).
    std::ofstream(dir / "pov.rca") << "C2\t-1.29\t-0.9\t0.76\t7ffe7f\t0.0985\t0.0988\t0.1161\n";
    try {
        render::readRadiosityFile(dir / "pov.rca");
        ADD_FAILURE() << "a povray file was read";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("not a frameray radiosity cache file"),
                  std::string::npos);
    }
    std::ofstream(dir / "bad.rca") << "frameray radiosity cache 1\n0 1 2 3\n";
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
