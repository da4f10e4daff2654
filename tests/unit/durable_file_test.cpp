#include "util/durable_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fs = std::filesystem;
using frameray::util::DurableAppendFile;
using frameray::util::replaceFileDurably;
using frameray::util::writeFileDurably;

namespace {

// A fresh folder per test under the system's temporary folder.
fs::path scratchFolder(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("frameray_durable_" + name + "_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string contents(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string errorOf(const auto& action) {
    try {
        action();
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(DurableFile, WritesAndReplacesWholeFilesLeavingNoTemporary) {
    const fs::path dir = scratchFolder("replace");
    writeFileDurably(dir / "a.txt", "first");
    EXPECT_EQ(contents(dir / "a.txt"), "first");
    replaceFileDurably(dir / "a.txt", "second, longer");
    EXPECT_EQ(contents(dir / "a.txt"), "second, longer");
    int files = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++files;
    EXPECT_EQ(files, 1);
    fs::remove_all(dir);
}

TEST(DurableFile, AMissingFolderIsAnErrorNamingTheFileAndTheReason) {
    const fs::path dir = scratchFolder("missing");
    fs::remove_all(dir);
    EXPECT_EQ(errorOf([&] { writeFileDurably(dir / "frame.png", "x"); }),
              "cannot write '" + (dir / "frame.png").string() + "': No such file or directory");
    // A temporary is reported under the name the user knows.
    EXPECT_EQ(errorOf([&] { writeFileDurably(dir / ".frame.png.1.tmp", "x", dir / "frame.png"); }),
              "cannot write '" + (dir / "frame.png").string() + "': No such file or directory");
    EXPECT_EQ(errorOf([&] { replaceFileDurably(dir / "sequence.json", "{}"); }),
              "cannot write '" + (dir / "sequence.json").string() + "': No such file or directory");
}

TEST(DurableFile, AppendsRecordsAndTruncatesWhenAsked) {
    const fs::path dir = scratchFolder("append");
    {
        DurableAppendFile file(dir / "journal", true);
        file.append("header\n");
        file.append("frame 1\n");
    }
    {
        DurableAppendFile file(dir / "journal", false);
        file.append("frame 2\n");
    }
    EXPECT_EQ(contents(dir / "journal"), "header\nframe 1\nframe 2\n");
    {
        DurableAppendFile file(dir / "journal", true);
        file.append("new\n");
    }
    EXPECT_EQ(contents(dir / "journal"), "new\n");
    fs::remove_all(dir);
}

TEST(DurableFile, RenamingOntoAMissingFolderRemovesTheSource) {
    const fs::path dir = scratchFolder("rename");
    writeFileDurably(dir / ".f.tmp", "data");
    EXPECT_EQ(errorOf([&] { frameray::util::renameDurably(dir / ".f.tmp", dir / "gone" / "f"); }),
              "cannot move a finished file to '" + (dir / "gone" / "f").string() +
                  "': No such file or directory");
    EXPECT_FALSE(fs::exists(dir / ".f.tmp"));
    fs::remove_all(dir);
}

// Append_File (+GP): stream files keep what earlier runs wrote, as povray's
// do (measured: two runs with +GP +GSstats.out give 40 then 80 lines).
TEST(DurableFile, CreateNoFollowTruncatesOrAppends) {
    const fs::path dir = scratchFolder("create_append");
    const fs::path file = dir / "stats.out";
    std::ofstream(file) << "first\n";
    int fd = frameray::util::createNoFollow(file, true);
    ASSERT_EQ(::write(fd, "second\n", 7), 7);
    ::close(fd);
    EXPECT_EQ(contents(file), "first\nsecond\n");
    fd = frameray::util::createNoFollow(file);
    ASSERT_EQ(::write(fd, "third\n", 6), 6);
    ::close(fd);
    EXPECT_EQ(contents(file), "third\n");
    fs::remove_all(dir);
}
