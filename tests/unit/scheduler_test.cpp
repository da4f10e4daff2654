// The frame scheduler's parts that need no render: sharding the sequence,
// the memory bound on frames in flight, the progress display and the
// statistics it writes.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "anim/memory_budget.h"
#include "anim/progress.h"
#include "anim/sequence.h"
#include "anim/statistics.h"
#include "options/options.h"
#include "parse_support.h"
#include "render/world.h"

using namespace frameray;
namespace fs = std::filesystem;

namespace {

anim::Sequence plan(std::vector<std::string> args) {
    options::RenderOptions o;
    args.insert(args.begin(), "s.pov");
    options::applyArguments(o, args);
    return anim::planSequence(o);
}

std::vector<int> numbers(const anim::Sequence& s) {
    std::vector<int> out;
    for (const auto& f : s.frames) out.push_back(f.number);
    return out;
}

}  // namespace

TEST(Shards, InterleaveTheSubsetSteppedFrames) {
    // Frames 3..12 every 2nd: 3 5 7 9 11; shard 1 of 2 takes positions 1, 3.
    const auto s = plan({"+KFI1", "+KFF12", "+SF3", "+EF12", "+STP2", "+SHI1", "+SHC2"});
    EXPECT_EQ(numbers(s), (std::vector<int>{5, 9}));
    EXPECT_EQ(s.framesInAllShards, 5u);
    EXPECT_EQ(s.shardIndex, 1);
    EXPECT_EQ(s.shardCount, 2);
    // Clocks and names are those of the whole sequence.
    EXPECT_EQ(s.frames[0].output.string(), "s05.png");
    EXPECT_EQ(s.frames[0].clock, static_cast<float>(4.0 / 11.0));  // povray: single precision
}

TEST(Shards, UnionIsTheWholeSequenceOnce) {
    const auto all = numbers(plan({"+KFI0", "+KFF23"}));
    std::vector<int> together;
    for (int i = 0; i < 5; ++i) {
        const auto part =
            numbers(plan({"+KFI0", "+KFF23", "Shard_Index=" + std::to_string(i), "Shard_Count=5"}));
        together.insert(together.end(), part.begin(), part.end());
    }
    std::sort(together.begin(), together.end());
    EXPECT_EQ(together, all);
}

TEST(Shards, OwnJournalAndStatistics) {
    const auto whole = plan({"+KFI1", "+KFF4", "+Oout/"});
    EXPECT_EQ(whole.journal.filename().string(), ".s.frameray-journal");
    EXPECT_EQ(whole.statisticsName, "sequence.json");
    const auto shard = plan({"+KFI1", "+KFF4", "+Oout/", "+SHI2", "+SHC3"});
    EXPECT_EQ(shard.journal.string(), "out/.s.shard-2-of-3.frameray-journal");
    EXPECT_EQ(shard.statisticsName, "sequence.shard-2-of-3.json");
}

TEST(Shards, MoreShardsThanFramesLeavesSomeEmpty) {
    EXPECT_EQ(numbers(plan({"+KFI1", "+KFF2", "+SHI3", "+SHC4"})), std::vector<int>{});
}

TEST(Shards, IndexOutsideTheCountIsAnError) {
    EXPECT_THROW(plan({"+KFI1", "+KFF4", "+SHI3", "+SHC3"}), options::OptionError);
    EXPECT_ANY_THROW(plan({"+KFI1", "+KFF4", "+SHI-1", "+SHC3"}));
    EXPECT_ANY_THROW(plan({"+KFI1", "+KFF4", "+SHC0"}));
}

TEST(MemoryBudget, FramesWithinThreeQuartersOfTheRoom) {
    const std::uint64_t MiB = 1 << 20;
    EXPECT_EQ(anim::framesWithin(8, 100 * MiB, 400 * MiB), 3u);   // 300 MiB / 100
    EXPECT_EQ(anim::framesWithin(2, 100 * MiB, 4000 * MiB), 2u);  // the option bounds it
    EXPECT_EQ(anim::framesWithin(8, 1000 * MiB, 400 * MiB), 1u);  // never below 1
    EXPECT_EQ(anim::framesWithin(5, 0, 400 * MiB), 5u);           // not measured
    EXPECT_EQ(anim::framesWithin(5, 100 * MiB, 0), 5u);           // room unknown
}

TEST(MemoryBudget, ReadsMeminfoAndCgroups) {
    EXPECT_EQ(
        anim::memAvailableFrom("MemTotal:  1000 kB\nMemFree: 10 kB\nMemAvailable:   2048 kB\n"),
        std::optional<std::uint64_t>(2048 * 1024));
    EXPECT_FALSE(anim::memAvailableFrom("MemTotal: 1 kB\n"));

    const fs::path dir =
        fs::temp_directory_path() / ("frameray_cgroup_" + std::to_string(getpid()));
    fs::create_directories(dir / "memory");
    auto put = [](const fs::path& p, const std::string& text) { std::ofstream(p) << text; };
    EXPECT_FALSE(anim::cgroupRoom(dir));
    put(dir / "memory" / "memory.limit_in_bytes", "9223372036854771712\n");  // v1: no limit
    EXPECT_FALSE(anim::cgroupRoom(dir));
    put(dir / "memory" / "memory.limit_in_bytes", "1000\n");
    put(dir / "memory" / "memory.usage_in_bytes", "400\n");
    EXPECT_EQ(anim::cgroupRoom(dir), std::optional<std::uint64_t>(600));
    put(dir / "memory.max", "max\n");  // v2 without a limit falls back to v1 files
    EXPECT_EQ(anim::cgroupRoom(dir), std::optional<std::uint64_t>(600));
    put(dir / "memory.max", "5000\n");
    put(dir / "memory.current", "1000\n");
    EXPECT_EQ(anim::cgroupRoom(dir), std::optional<std::uint64_t>(4000));
    fs::remove_all(dir);

    EXPECT_GT(anim::residentBytes(), 0u);
    EXPECT_GE(anim::peakResidentBytes(), anim::residentBytes() / 2);
}

TEST(Progress, ModeFollowsVerboseAndTheConsole) {
    EXPECT_EQ(anim::progressModeFor(true, true, true), anim::ProgressMode::Terminal);
    EXPECT_EQ(anim::progressModeFor(true, true, false), anim::ProgressMode::Lines);
    EXPECT_EQ(anim::progressModeFor(false, true, true), anim::ProgressMode::Silent);  // -V
    EXPECT_EQ(anim::progressModeFor(true, false, true), anim::ProgressMode::Silent);  // -GR
}

TEST(Progress, EtaFromTheRenderedFramesOnly) {
    EXPECT_LT(anim::estimateRemaining(0, 0, 10, 5.0), 0);  // unknown yet
    EXPECT_DOUBLE_EQ(anim::estimateRemaining(2, 0, 10, 4.0), 16.0);
    // Frames kept by +C took no time: 2 rendered in 4 s, 6 kept, 2 to go.
    EXPECT_DOUBLE_EQ(anim::estimateRemaining(2, 6, 10, 4.0), 4.0);
    EXPECT_DOUBLE_EQ(anim::estimateRemaining(4, 6, 10, 4.0), 0.0);
}

TEST(Progress, Durations) {
    EXPECT_EQ(anim::formatDuration(3.25), "3.2 s");
    EXPECT_EQ(anim::formatDuration(125), "2 min 05 s");
    EXPECT_EQ(anim::formatDuration(7380), "2 h 03 min");
    EXPECT_EQ(anim::formatDuration(-1), "?");
}

TEST(Progress, TerminalLine) {
    EXPECT_EQ(anim::Progress::terminalLine(5, 20, {6, 7, 8}, 10.0, 30.0),
              "frames 5/20 (25%) | rendering 6 7 8 | elapsed 10.0 s | ETA 30.0 s");
    EXPECT_EQ(anim::Progress::terminalLine(0, 3, {}, 0.5, -1),
              "frames 0/3 (0%) | rendering - | elapsed 0.5 s | ETA ?");
    EXPECT_NE(anim::Progress::terminalLine(0, 30, {1, 2, 3, 4, 5, 6, 7, 8}, 1, 1).find("6 ..."),
              std::string::npos);
}

// Issue 29: frames per second and the slowest frame so far.
TEST(Progress, TerminalLineShowsPaceAndSlowestFrame) {
    EXPECT_EQ(anim::Progress::terminalLine(5, 20, {6, 7}, 10.0, 30.0, {0.5, 3, 4.25}),
              "frames 5/20 (25%) | 0.50 frames/s | slowest 3 (4.2 s) | rendering 6 7 | elapsed "
              "10.0 s | ETA 30.0 s");
    // Nothing rendered yet: no pace, no slowest frame.
    EXPECT_EQ(anim::Progress::terminalLine(0, 3, {1}, 0.5, -1, {}),
              "frames 0/3 (0%) | rendering 1 | elapsed 0.5 s | ETA ?");
}

TEST(Statistics, SequenceJsonPerFrameStatsAndSums) {
    anim::FrameRecord a;
    a.number = 1;
    a.file = "a01.png";
    a.rays.camera = 10;
    a.rays.shadow = 4;
    a.shapeTests = {{"plane", 7}, {"sphere", 3}};
    a.parseSeconds = 0.5;
    anim::FrameRecord b = a;
    b.number = 2;
    b.file = "a02.png";
    b.shapeTests = {{"box", 1}, {"sphere", 2}};
    anim::RunFigures run;
    run.scene = "a";
    run.framesPlanned = 3;
    run.framesFinished = 3;
    const std::string json = anim::sequenceJson(run, {a, b}, {{3, 1.0, "a03.png"}});
    EXPECT_NE(json.find("\"intersection_tests\": {\"plane\": 7, \"sphere\": 3}"), std::string::npos)
        << json;
    EXPECT_NE(json.find("\"intersection_tests\": {\"box\": 1, \"plane\": 7, \"sphere\": 5}"),
              std::string::npos)
        << json;
    EXPECT_NE(
        json.find("\"kept_frames\": [\n    {\"number\": 3, \"clock\": 1, \"file\": \"a03.png\"}"),
        std::string::npos)
        << json;
    EXPECT_NE(json.find("\"rays\": {\"camera\": 20, \"shadow\": 8,"), std::string::npos) << json;
    EXPECT_NE(json.find("\"frames_kept\": 1"), std::string::npos);
}

TEST(Statistics, SummaryTable) {
    anim::FrameRecord a;
    a.rays.camera = 300;
    a.rays.shadow = 100;
    anim::RunFigures run;
    run.framesPlanned = 4;
    run.wallSeconds = 2;
    run.cpuSeconds = 3;
    run.workThreads = 2;
    run.framesInFlight = 3;
    run.shardIndex = 1;
    run.shardCount = 2;
    const std::string table = anim::summaryTable(run, {a}, 2);
    EXPECT_NE(table.find("frames    1 rendered, 2 kept (+C) of 4 (shard 1 of 2)"),
              std::string::npos)
        << table;
    EXPECT_NE(table.find("wall      2.00 s"), std::string::npos) << table;
    EXPECT_NE(table.find("CPU       3.00 s (75% of 2 threads, 3 frames in flight)"),
              std::string::npos)
        << table;
    EXPECT_NE(table.find("rays      400 (camera 300, shadow 100,"), std::string::npos) << table;
    EXPECT_NE(table.find("rays/s    200"), std::string::npos) << table;
}

TEST(Statistics, WorldCountsIntersectionTestsByKind) {
    test_support::ParsedScene p(
        "sphere { <0,0,5>, 1 } sphere { <0,3,5>, 1 } union { box { -1, 1 } sphere { 0, 1 } "
        "translate <5,0,5> }\n"
        "plane { y, -2 }\n");
    const render::World world(p.scene);
    render::Hit hit;
    // Straight at the first sphere: the BVH leaves it alone to test; the
    // plane is outside the BVH and tested by every ray.
    ASSERT_TRUE(
        world.intersect(scene::Ray{Vec3(0, 0, 0), Vec3(0, 0, 1)}, 0, scene::kInfinity, hit));
    EXPECT_FALSE(world.occluded(scene::Ray{Vec3(5, 0, 0), Vec3(0, 0, -1)}, 0, 10));
    // The plain union is split into its box and sphere, each in the BVH.
    const render::ShapeTestCounts tests = world.shapeTests();
    ASSERT_EQ(tests.size(), 3u);  // sorted by kind
    EXPECT_EQ(tests[0], (std::pair<std::string, std::uint64_t>{"box", 0}));
    EXPECT_EQ(tests[1], (std::pair<std::string, std::uint64_t>{"plane", 2}));
    EXPECT_EQ(tests[2].first, "sphere");
    EXPECT_EQ(tests[2].second, 1u);
}

TEST(Shards, FileWritesRefusedBeforeTheFileIsTouched) {
    sdl::FrameContext ctx;
    ctx.refuseFileWrites = "no state through files here";
    const fs::path file =
        fs::temp_directory_path() / ("frameray_refused_" + std::to_string(getpid()) + ".txt");
    const std::string error =
        test_support::parseErrorOf("#fopen F \"" + file.string() + "\" write\n", ctx);
    EXPECT_NE(error.find("is opened for write: no state through files here"), std::string::npos)
        << error;
    EXPECT_NE(error.find("t.pov:1"), std::string::npos) << error;
    EXPECT_FALSE(fs::exists(file));
    EXPECT_NE(test_support::parseErrorOf("#fopen F \"" + file.string() + "\" read\n", ctx)
                  .find("if an earlier frame writes it, no state through files here"),
              std::string::npos);
    // Without the refusal both work as before.
    EXPECT_EQ(test_support::parseErrorOf("#fopen F \"" + file.string() + "\" append\n"), "");
    EXPECT_TRUE(fs::exists(file));
    fs::remove(file);
}
