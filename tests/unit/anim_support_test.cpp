// The frame loop's helpers: shell-out substitutions and return actions,
// and the resume journal.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "anim/hooks.h"
#include "anim/journal.h"

using namespace frameray::anim;
namespace fs = std::filesystem;

TEST(Hooks, Substitutions) {
    HookValues v;
    v.output = "frames/demo07.png";
    v.scene = "demo";
    v.frame = 7;
    v.clock = 0.25;
    v.width = 320;
    v.height = 240;
    EXPECT_EQ(substituteCommand("zip %s %o n=%n k=%k %wx%h 100%% %q", v),
              "zip demo frames/demo07.png n=7 k=0.25 320x240 100% %q");
}

TEST(Hooks, ReturnActions) {
    EXPECT_EQ(returnAction("", 1), HookAction::Continue);
    EXPECT_EQ(returnAction("i", 1), HookAction::Continue);
    EXPECT_EQ(returnAction("s", 0), HookAction::Continue);
    EXPECT_EQ(returnAction("s", 1), HookAction::SkipFrame);
    EXPECT_EQ(returnAction("A", 3), HookAction::SkipAll);
    EXPECT_EQ(returnAction("q", 1), HookAction::Quit);
    EXPECT_EQ(returnAction("u", 1), HookAction::UserAbort);
    EXPECT_EQ(returnAction("f", 1), HookAction::Fatal);
    EXPECT_EQ(returnAction("-s", 0), HookAction::SkipFrame);  // '-' acts on success
    EXPECT_EQ(returnAction("!f", 0), HookAction::Fatal);
    EXPECT_EQ(returnAction("-s", 1), HookAction::Continue);
}

TEST(Hooks, RunsThroughTheShell) {
    const fs::path flag = fs::temp_directory_path() / "frameray_hook_flag";
    fs::remove(flag);
    HookValues v;
    v.frame = 3;
    frameray::options::ShellCommand cmd{"echo %n > " + flag.string(), "f"};
    EXPECT_EQ(runHook(cmd, v), HookAction::Continue);
    std::ifstream in(flag);
    std::string text;
    in >> text;
    EXPECT_EQ(text, "3");
    fs::remove(flag);
    EXPECT_EQ(runHook({"exit 3", "f"}, v), HookAction::Fatal);
    EXPECT_EQ(runHook({"exit 0", "-s"}, v), HookAction::SkipFrame);
}

// %o and %s are names an INI file beside the scene may choose: the shell
// must read them back literally wherever the command puts them (outside
// quotes, in '...' or in "..."), never run what they contain.
TEST(Hooks, SubstitutionsAreQuotedForTheShell) {
    const fs::path dir = fs::temp_directory_path() / "frameray_hook_quoting";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string ran = (dir / "ran").string();
    HookValues v;
    v.output = "y$(touch " + ran + ")`touch " + ran + "` 'a' \"b\" \\c *;.png";
    v.scene = "s;touch " + ran;
    const fs::path out = dir / "out";
    for (const std::string& command : {std::string("printf '%%s|%%s' %o %s > "),
                                       std::string("printf '%%s|%%s' \"%o\" \"%s\" > "),
                                       std::string("printf '%%s|%%s' '%o' '%s' > "),
                                       std::string("printf '%%s|%%s' x%o \"y\"%s > ")}) {
        fs::remove(out);
        EXPECT_EQ(runHook({command + out.string(), "f"}, v), HookAction::Continue) << command;
        std::ifstream in(out);
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const bool prefixed = command.find("x%o") != std::string::npos;
        EXPECT_EQ(text, (prefixed ? "x" : "") + v.output + "|" + (prefixed ? "y" : "") + v.scene)
            << command;
        EXPECT_FALSE(fs::exists(ran)) << command;
    }
    // Plain names stay as they are.
    v.output = "frames/demo-07.png";
    EXPECT_EQ(substituteCommand("cp %o '%o' \"%o\"", v),
              "cp frames/demo-07.png 'frames/demo-07.png' \"frames/demo-07.png\"");
    fs::remove_all(dir);
}

TEST(Journal, VerifiesSizeAndHash) {
    const fs::path dir = fs::temp_directory_path() / "frameray_journal_test";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path img = dir / "a01.png", journal = dir / ".a.frameray-journal";
    std::ofstream(img, std::ios::binary) << "0123456789";
    {
        Journal j(journal, 42, false);
        j.record(1, clockText(0.5), img);
        EXPECT_TRUE(j.verified(1, clockText(0.5), img));
        EXPECT_FALSE(j.verified(1, clockText(0.6), img));  // another clock
        EXPECT_FALSE(j.verified(2, clockText(0.5), img));
    }
    {
        Journal j(journal, 42, true);  // resumed: still there
        EXPECT_TRUE(j.verified(1, clockText(0.5), img));
    }
    // Same size, other bytes: not trusted.
    std::ofstream(img, std::ios::binary) << "0123456780";
    EXPECT_FALSE(Journal(journal, 42, true).verified(1, clockText(0.5), img));
    // Truncated: not trusted.
    std::ofstream(img, std::ios::binary) << "01234";
    EXPECT_FALSE(Journal(journal, 42, true).verified(1, clockText(0.5), img));
    // Other settings: the journal is dropped.
    std::ofstream(img, std::ios::binary) << "0123456789";
    {
        Journal j(journal, 42, false);
        j.record(1, clockText(0.5), img);
    }
    Journal other(journal, 43, true);
    EXPECT_TRUE(other.discardedStale());
    EXPECT_FALSE(other.verified(1, clockText(0.5), img));
    // A line cut short by a crash is ignored.
    {
        Journal j(journal, 42, false);
        j.record(1, clockText(0.5), img);
    }
    std::ofstream(journal, std::ios::app) << "frame 2 0 10 0123";
    Journal cut(journal, 42, true);
    EXPECT_TRUE(cut.verified(1, clockText(0.5), img));
    EXPECT_FALSE(cut.verified(2, "0", img));
    // Without +C the journal starts afresh.
    EXPECT_FALSE(Journal(journal, 42, false).verified(1, clockText(0.5), img));
    fs::remove_all(dir);
}
