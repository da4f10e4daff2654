// frameray's run log (anim/run_log.h): event formatting, levels, appending.
#include "anim/run_log.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace frameray::anim;
using frameray::options::LogFormat;
using frameray::options::LogLevel;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> lines(const fs::path& path) {
    std::ifstream in(path);
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
}

fs::path freshPath(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("frameray_run_log_" + std::to_string(getpid()));
    fs::create_directories(dir);
    const fs::path p = dir / name;
    fs::remove(p);
    return p;
}

}  // namespace

TEST(RunLog, FormatsEventsAsJsonMembers) {
    EXPECT_EQ(formatEvent(LogFormat::Json, "written",
                          {{"frame", 3}, {"clock", 0.25}, {"file", "a \"b\".png"}}),
              R"("event":"written","frame":3,"clock":0.25,"file":"a \"b\".png")");
    // JSON has no NaN or infinity.
    EXPECT_EQ(formatEvent(LogFormat::Json, "x", {{"a", std::numeric_limits<double>::quiet_NaN()}}),
              R"("event":"x","a":null)");
}

TEST(RunLog, FormatsEventsAsText) {
    EXPECT_EQ(formatEvent(LogFormat::Text, "kept", {{"frame", 7}, {"file", "f07.png"}}),
              R"(kept frame=7 file="f07.png")");
}

TEST(RunLog, KeepsLevelsFromItsOwnUpAndAppends) {
    const fs::path path = freshPath("levels.log");
    {
        RunLog log(path, LogLevel::Info, LogFormat::Json, nullptr);
        EXPECT_FALSE(log.enabled(LogLevel::Debug));
        EXPECT_TRUE(log.enabled(LogLevel::Error));
        log.event(LogLevel::Debug, "parse_done", {{"frame", 1}});
        log.event(LogLevel::Info, "written", {{"frame", 1}});
        log.event(LogLevel::Error, "failed", {{"frame", 2}, {"reason", "boom"}});
        EXPECT_EQ(log.close(), "");
    }
    std::vector<std::string> got = lines(path);
    ASSERT_EQ(got.size(), 2u);
    EXPECT_NE(got[0].find(R"("level":"info","event":"written","frame":1})"), std::string::npos)
        << got[0];
    EXPECT_NE(got[1].find(R"("level":"error","event":"failed")"), std::string::npos) << got[1];
    EXPECT_EQ(got[0].rfind(R"({"time":")", 0), 0u) << got[0];
    {
        // A second run (+C) appends after the first one's lines.
        RunLog log(path, LogLevel::Info, LogFormat::Json, nullptr);
        log.event(LogLevel::Info, "kept", {{"frame", 1}});
    }
    got = lines(path);
    ASSERT_EQ(got.size(), 3u);
    EXPECT_NE(got[2].find(R"("event":"kept")"), std::string::npos);
}

TEST(RunLog, OffWritesNothing) {
    const fs::path path = freshPath("off.log");
    RunLog log(path, LogLevel::Off, LogFormat::Text, nullptr);
    log.event(LogLevel::Error, "failed");
    EXPECT_EQ(log.close(), "");
    EXPECT_FALSE(fs::exists(path));
}

TEST(RunLog, KeepsEveryEventOfManyThreadsInOrderPerThread) {
    const fs::path path = freshPath("threads.log");
    {
        RunLog log(path, LogLevel::Info, LogFormat::Text, nullptr);
        std::vector<std::thread> threads;
        for (int t = 0; t < 4; ++t)
            threads.emplace_back([&log, t] {
                for (int i = 0; i < 100; ++i) log.event(LogLevel::Info, "e", {{"t", t}, {"i", i}});
            });
        for (std::thread& th : threads) th.join();
    }
    const std::vector<std::string> got = lines(path);
    ASSERT_EQ(got.size(), 400u);
    std::vector<int> next(4, 0);
    for (const std::string& line : got) {
        const size_t at = line.find(" e t=");
        ASSERT_NE(at, std::string::npos) << line;
        int t = -1, i = -1;
        std::istringstream(line.substr(at + 5)) >> t;
        i = std::stoi(line.substr(line.find(" i=") + 3));
        ASSERT_GE(t, 0);
        ASSERT_LT(t, 4);
        EXPECT_EQ(i, next[static_cast<size_t>(t)]++);
    }
}
