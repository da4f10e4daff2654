// The JSON reader and the merge of shards' statistics into one
// sequence.json (frameray --merge-stats, or the shard that finishes last).
#include "anim/shard_statistics.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "anim/statistics.h"
#include "util/json.h"

using namespace frameray;
using util::JsonValue;

namespace {

// A shard's file as the frame loop writes it: shard `index` of `count`
// rendered `rendered` and kept `kept` (+C).
std::string shardText(int index, int count, const std::vector<int>& rendered,
                      const std::vector<int>& kept, size_t planned = 0) {
    anim::RunFigures run;
    run.scene = "demo";
    run.shardIndex = index;
    run.shardCount = count;
    run.framesPlanned = planned ? planned : rendered.size() + kept.size();
    run.framesFinished = rendered.size() + kept.size();
    run.wallSeconds = 2.0 + index;
    run.cpuSeconds = 1.5;
    run.workThreads = 1;
    std::vector<anim::FrameRecord> records;
    for (const int n : rendered) {
        anim::FrameRecord r;
        r.number = n;
        r.clock = n / 24.0;
        r.file = "demo" + std::to_string(n) + ".png";
        r.rays.camera = 100;
        r.rays.shadow = 10 * static_cast<std::uint64_t>(n);
        r.shapeTests = {{"sphere", 7}};
        r.parseSeconds = 0.25;
        r.renderSeconds = 0.5;
        records.push_back(r);
    }
    std::vector<anim::KeptFrame> keptFrames;
    for (const int n : kept)
        keptFrames.push_back({n, n / 24.0, "demo" + std::to_string(n) + ".png"});
    return anim::sequenceJson(run, records, keptFrames);
}

std::vector<std::int64_t> numbers(const JsonValue& list) {
    std::vector<std::int64_t> out;
    for (const JsonValue& f : list.items) out.push_back(*f.find("number")->asInteger());
    return out;
}

}  // namespace

TEST(Json, ReadsWhatItWritesKeepingOrderAndNumberText) {
    const std::string text =
        R"({"b": 1.500000, "a": [1, -2e3, "x\"\\\n\u00e9"], "t": true, "f": false, "n": null, "o": {}})";
    const JsonValue v = util::parseJson(text);
    ASSERT_EQ(v.kind, JsonValue::Kind::Object);
    EXPECT_EQ(v.members[0].first, "b");
    EXPECT_EQ(v.find("b")->text, "1.500000");
    EXPECT_DOUBLE_EQ(*v.find("b")->asDouble(), 1.5);
    EXPECT_FALSE(v.find("b")->asInteger());
    EXPECT_EQ(*v.find("a")->items[1].asDouble(), -2000.0);
    EXPECT_EQ(v.find("a")->items[2].text, "x\"\\\n\xc3\xa9");
    EXPECT_TRUE(v.find("t")->boolean);
    EXPECT_FALSE(v.find("f")->boolean);
    EXPECT_EQ(v.find("n")->kind, JsonValue::Kind::Null);
    EXPECT_EQ(v.find("missing"), nullptr);
    EXPECT_EQ(util::writeJsonInline(util::parseJson(util::writeJsonInline(v))),
              util::writeJsonInline(v));
}

TEST(Json, RefusesBrokenText) {
    for (const char* bad : {"", "{", "[1,]", "{\"a\" 1}", "\"abc", "01x", "[1] 2", "{\"a\": tru}",
                            "\"\\ud800\"", "1."})
        EXPECT_THROW(util::parseJson(bad), std::runtime_error) << bad;
}

TEST(ShardStatistics, MergesEveryShardIntoOneSequence) {
    // 3 shards of 8 frames (1..8): shard i renders 1+i, 4+i, 7+i; shard 1
    // was requeued and kept frame 2 from its first attempt.
    const std::string merged =
        anim::mergeShardStatistics({shardText(2, 3, {3, 6}, {}), shardText(0, 3, {1, 4, 7}, {}),
                                    shardText(1, 3, {5, 8}, {2})});
    const JsonValue v = util::parseJson(merged);
    EXPECT_EQ(v.find("scene")->text, "demo");
    EXPECT_EQ(numbers(*v.find("frames")), (std::vector<std::int64_t>{1, 3, 4, 5, 6, 7, 8}));
    EXPECT_EQ(numbers(*v.find("kept_frames")), (std::vector<std::int64_t>{2}));
    EXPECT_EQ(v.find("frames_rendered")->text, "7");
    EXPECT_EQ(v.find("frames_kept")->text, "1");
    EXPECT_EQ(v.find("frames_finished")->text, "8");
    EXPECT_EQ(v.find("frames_planned")->text, "8");
    EXPECT_EQ(v.find("shard_count")->text, "3");
    // Sums of rays and tests; seconds summed except wall (the longest shard).
    EXPECT_EQ(v.find("rays")->find("camera")->text, "700");
    EXPECT_EQ(v.find("rays")->find("shadow")->text,
              std::to_string(10 * (1 + 3 + 4 + 5 + 6 + 7 + 8)));
    EXPECT_EQ(v.find("intersection_tests")->find("sphere")->text, "49");
    EXPECT_DOUBLE_EQ(*v.find("parse_seconds")->asDouble(), 7 * 0.25);
    EXPECT_DOUBLE_EQ(*v.find("cpu_seconds")->asDouble(), 4.5);
    EXPECT_DOUBLE_EQ(*v.find("wall_seconds")->asDouble(), 4.0);
    // Each shard's own figures, by index.
    const JsonValue& shards = *v.find("shards");
    ASSERT_EQ(shards.items.size(), 3u);
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(*shards.items[i].find("shard_index")->asInteger(), i);
        EXPECT_EQ(shards.items[i].find("frames"), nullptr);
    }
    EXPECT_EQ(shards.items[1].find("frames_kept")->text, "1");
    // A frame keeps its record as the shard wrote it.
    const JsonValue& frame5 = v.find("frames")->items[3];
    EXPECT_EQ(frame5.find("file")->text, "demo5.png");
    EXPECT_EQ(frame5.find("stats")->find("intersection_tests")->find("sphere")->text, "7");
    // The order of the files does not matter.
    EXPECT_EQ(merged, anim::mergeShardStatistics({shardText(0, 3, {1, 4, 7}, {}),
                                                  shardText(1, 3, {5, 8}, {2}),
                                                  shardText(2, 3, {3, 6}, {})}));
}

TEST(ShardStatistics, RefusesAnIncompleteOrMixedSet) {
    auto message = [](const std::vector<std::string>& texts) {
        try {
            anim::mergeShardStatistics(texts);
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string("merged");
    };
    // A shard missing, one not finished (cancelled before the requeue), two
    // runs' files, one shard twice, not a statistics file.
    EXPECT_NE(message({shardText(0, 2, {1}, {})}).find("no statistics of shard 1 of 2"),
              std::string::npos);
    EXPECT_NE(message({shardText(0, 2, {1}, {}), shardText(1, 2, {2}, {}, 3)})
                  .find("shard 1 of 2 has finished 1 of its 3 frames"),
              std::string::npos);
    EXPECT_NE(message({shardText(0, 2, {1}, {}), shardText(1, 3, {2}, {})}).find("different runs"),
              std::string::npos);
    EXPECT_NE(message({shardText(0, 2, {1}, {}), shardText(0, 2, {1}, {})}).find("given twice"),
              std::string::npos);
    EXPECT_NE(message({"{\"frames\": []}"}).find("shard_index"), std::string::npos);
}

TEST(ShardStatistics, WritesSequenceJsonInTheFolder) {
    const std::filesystem::path dir =
        std::filesystem::path(testing::TempDir()) / "frameray_shard_statistics";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    auto put = [&](const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
    };
    EXPECT_THROW(anim::mergeShardStatisticsIn(dir), std::runtime_error);  // nothing yet
    put("sequence.shard-0-of-2.json", shardText(0, 2, {1, 3}, {}));
    EXPECT_THROW(anim::mergeShardStatisticsIn(dir), std::runtime_error);  // shard 1 missing
    EXPECT_FALSE(std::filesystem::exists(dir / "sequence.json"));
    put("sequence.shard-1-of-2.json", shardText(1, 2, {2}, {4}));
    const anim::MergedStatistics m = anim::mergeShardStatisticsIn(dir);
    EXPECT_EQ(m.file, dir / "sequence.json");
    EXPECT_EQ(m.shards, 2u);
    EXPECT_EQ(m.framesRendered, 3u);
    EXPECT_EQ(m.framesKept, 1u);
    std::ifstream in(m.file);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text,
              anim::mergeShardStatistics({shardText(0, 2, {1, 3}, {}), shardText(1, 2, {2}, {4})}));
    // Files of an older run with another shard count are named, not mixed in.
    put("sequence.shard-0-of-4.json", shardText(0, 4, {1}, {}));
    try {
        anim::mergeShardStatisticsIn(dir);
        ADD_FAILURE() << "merged files of 2 and 4 shards";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("2 different shard counts (2, 4)"), std::string::npos)
            << e.what();
    }
    std::filesystem::remove_all(dir);
}
