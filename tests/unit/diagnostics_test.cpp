// Restrictions on scene files (sdl/file_access.h), spelling suggestions
// (util/spelling.h) and the include/macro chain of scene errors.
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <thread>

#include "anim/hooks.h"
#include "options/options.h"
#include "parse_support.h"
#include "sdl/file_access.h"
#include "util/spelling.h"

namespace fs = std::filesystem;
using namespace frameray;

namespace {

struct TempTree {
    fs::path root;
    TempTree() {
        root = fs::temp_directory_path() / ("frameray_access_" + std::to_string(::getpid()));
        fs::remove_all(root);
        fs::create_directories(root / "scene/sub");
        fs::create_directories(root / "lib");
        fs::create_directories(root / "out");
        fs::create_directories(root / "other");
    }
    ~TempTree() { fs::remove_all(root); }
};

sdl::FileAccessPolicy policyFor(const TempTree& t) {
    sdl::FileAccessFolders f;
    f.working = t.root / "scene";
    f.scene = t.root / "scene";
    f.output = t.root / "out/";
    f.library = {t.root / "lib"};
    return sdl::FileAccessPolicy::restrictedTo(f);
}

}  // namespace

TEST(FileAccess, DefaultPolicyAllowsEverything) {
    const sdl::FileAccessPolicy p;
    EXPECT_FALSE(p.restricted());
    EXPECT_EQ(p.checkRead("/etc/passwd", ""), "");
    EXPECT_EQ(p.checkWrite("/tmp/x", ""), "");
}

TEST(FileAccess, FoldersAndSubfoldersOnly) {
    TempTree t;
    const auto p = policyFor(t);
    EXPECT_EQ(p.checkRead(t.root / "scene/sub/a.inc", ""), "");
    EXPECT_EQ(p.checkRead(t.root / "lib/colors.inc", ""), "");
    EXPECT_EQ(p.checkRead(t.root / "out/frame.png", ""), "");  // written folders are readable
    EXPECT_NE(p.checkRead(t.root / "other/a.inc", ""), "");
    EXPECT_NE(p.checkRead("/etc/passwd", ""), "");
    EXPECT_EQ(p.checkWrite(t.root / "out/state.txt", ""), "");
    EXPECT_EQ(p.checkWrite(t.root / "scene/sub/state.txt", ""), "");
    EXPECT_NE(p.checkWrite(t.root / "lib/state.txt", ""), "");  // the library is read-only
    // '..' is resolved before the check, and a name that only shares a
    // prefix with a folder is not inside it.
    EXPECT_NE(p.checkWrite(t.root / "scene/../other/x", ""), "");
    EXPECT_NE(p.checkWrite(t.root / "scene_evil/x", ""), "");
    const std::string refusal = p.checkWrite(t.root / "scene/../other/x", "../other/x");
    EXPECT_NE(refusal.find("'../other/x' (" + (t.root / "other/x").string() + ")"),
              std::string::npos)
        << refusal;
    EXPECT_NE(refusal.find("Write_Path=" + (t.root / "other").string()), std::string::npos)
        << refusal;
}

TEST(FileAccess, LinksOutOfTheSceneFolderAreFollowed) {
    TempTree t;
    std::ofstream(t.root / "other/secret.txt") << "x";
    fs::create_symlink(t.root / "other/secret.txt", t.root / "scene/link.txt");
    fs::create_symlink(t.root / "other/secret.txt", t.root / "lib/font.ttf");
    const auto p = policyFor(t);
    // A link in the scene's folder cannot lead out of it; links in the
    // library (installed fonts) are taken by name.
    EXPECT_NE(p.checkRead(t.root / "scene/link.txt", ""), "");
    EXPECT_EQ(p.checkRead(t.root / "lib/font.ttf", ""), "");
}

// The descriptor itself is checked, not only the name: a scene-folder file
// swapped for a link to a secret between the check and the open (a race a
// scene's author can run from outside) must never be read through, and a
// link planted under a name a scene writes is not followed.
TEST(FileAccess, OpenedDescriptorsAreChecked) {
    TempTree t;
    std::ofstream(t.root / "other/secret.txt") << "secret";
    const auto p = policyFor(t);
    const fs::path data = t.root / "scene/data.txt";
    std::atomic<bool> stop{false};
    std::thread swapper([&] {
        for (int i = 0; !stop; ++i) {
            const fs::path tmp = t.root / "scene/swap.tmp";
            std::error_code ec;
            fs::remove(tmp, ec);
            if (i % 2) {
                fs::create_symlink(t.root / "other/secret.txt", tmp, ec);
            } else {
                std::ofstream(tmp) << "good";
            }
            fs::rename(tmp, data, ec);
        }
    });
    int opened = 0, leaked = 0;
    for (int i = 0; i < 4000; ++i) {
        const sdl::OpenedFile f = p.openForReading(data, "data.txt");
        if (!f.ok()) continue;
        ++opened;
        char buf[16] = {};
        if (::read(f.fd(), buf, sizeof buf - 1) > 0 && std::string(buf) == "secret") ++leaked;
    }
    stop = true;
    swapper.join();
    EXPECT_EQ(leaked, 0) << "of " << opened << " opened";

    // Writing: a link under the name is refused, its target untouched,
    // whether it leads out of the allowed folders or not (O_NOFOLLOW is
    // what stops a link swapped in after the check).
    fs::create_symlink(t.root / "other/secret.txt", t.root / "scene/state.txt");
    const sdl::OpenedFile w = p.openForWriting(t.root / "scene/state.txt", false, "state.txt");
    EXPECT_FALSE(w.ok());
    EXPECT_NE(w.error().find("is not allowed"), std::string::npos) << w.error();
    std::ifstream in(t.root / "other/secret.txt");
    std::string text;
    in >> text;
    EXPECT_EQ(text, "secret");
    std::ofstream(t.root / "scene/kept.txt") << "kept";
    fs::create_symlink(t.root / "scene/kept.txt", t.root / "scene/inside.txt");
    const sdl::OpenedFile v = p.openForWriting(t.root / "scene/inside.txt", false, "inside.txt");
    EXPECT_FALSE(v.ok());
    EXPECT_EQ(v.error(), "cannot open 'inside.txt' for writing: it is a symbolic link");
    EXPECT_EQ(fs::file_size(t.root / "scene/kept.txt"), 4u);
    // A plain file is opened, and truncated only when not appending.
    std::ofstream(t.root / "scene/log.txt") << "abc";
    EXPECT_TRUE(p.openForWriting(t.root / "scene/log.txt", true, "log.txt").ok());
    EXPECT_EQ(fs::file_size(t.root / "scene/log.txt"), 3u);
    EXPECT_TRUE(p.openForWriting(t.root / "scene/log.txt", false, "log.txt").ok());
    EXPECT_EQ(fs::file_size(t.root / "scene/log.txt"), 0u);
    // A folder or a pipe is no file.
    EXPECT_FALSE(p.openForReading(t.root / "scene/sub", "sub").ok());
}

// #fopen under a name that holds an open file is an error, as in povray;
// files held by no identifier any more are closed at once.
TEST(FileAccess, FopenIdentifiersAreNotReused) {
    TempTree t;
    const std::string a = (t.root / "scene/a.txt").string();
    const std::string error =
        test_support::parseErrorOf("#fopen F \"" + a + "\" write\n#fopen F \"" + a + "\" write\n");
    EXPECT_NE(error.find("t.pov:2:8: error: 'F' is an open file identifier"), std::string::npos)
        << error;
    // 3000 files opened in a macro's local scope: each closes when the
    // macro returns (the process allows 1024 open files by default).
    const std::string many =
        test_support::parseErrorOf("#macro W(I) #local G = 0; #fopen G \"" + a +
                                   "\" append #write (G, I) #end\n#for (I, 1, 3000) W(I) #end\n");
    EXPECT_EQ(many, "");
}

TEST(FileAccess, InterpreterRefusesAtTheDirective) {
    TempTree t;
    sdl::FrameContext ctx;
    ctx.fileAccess = policyFor(t);
    const std::string error =
        test_support::parseErrorOf("#version 3.7;\n#fopen F \"/etc/passwd\" read\n", ctx);
    EXPECT_NE(error.find("t.pov:2:2: error: reading '/etc/passwd' is not allowed"),
              std::string::npos)
        << error;
    EXPECT_NE(error.find("Read_Path=/etc"), std::string::npos) << error;
    const std::string write = test_support::parseErrorOf(
        "#fopen F \"" + (t.root / "other/x.txt").string() + "\" write\n", ctx);
    EXPECT_NE(write.find("is not allowed"), std::string::npos) << write;
    EXPECT_FALSE(fs::exists(t.root / "other/x.txt"));
}

TEST(Spelling, DistanceCountsSwapsAsOneEdit) {
    EXPECT_EQ(util::spellingDistance("delcare", "declare"), 1u);
    EXPECT_EQ(util::spellingDistance("spher", "sphere"), 1u);
    EXPECT_EQ(util::spellingDistance("Offset", "offset"), 1u);
    EXPECT_EQ(util::spellingDistance("Offset", "offset", true), 0u);
    EXPECT_EQ(util::spellingDistance("", "abc"), 3u);
}

TEST(Spelling, SuggestsOnlyCloseWords) {
    EXPECT_EQ(util::closestSpelling("pigmnt", {"finish", "pigment", "normal"}), "pigment");
    EXPECT_EQ(util::closestSpelling("xyzzy", {"finish", "pigment"}), "");
    EXPECT_EQ(util::closestSpelling("ab", {"abc"}), "");  // too short to guess
}

TEST(Diagnostics, UndeclaredIdentifierSuggestsADeclaredOne) {
    const std::string error =
        test_support::parseErrorOf("#declare Radius = 1;\nsphere { 0, Raduis }\n");
    EXPECT_NE(error.find("undeclared identifier 'Raduis'; did you mean 'Radius'?"),
              std::string::npos)
        << error;
}

TEST(Diagnostics, MacroChainFollowsTheCaret) {
    const std::string error = test_support::parseErrorOf(
        "#macro Inner(X) (X + Missing) #end\n#macro Outer(Y) Inner(Y) #end\n#declare A = "
        "Outer(1);\n");
    EXPECT_NE(
        error.find(
            "^\nnote: in macro 'Inner' called from t.pov:2:17\nnote: in macro 'Outer' called from "
            "t.pov:3:14"),
        std::string::npos)
        << error;
}

TEST(ShellCommands, RefusedUnlessAllowed) {
    options::RenderOptions o;
    EXPECT_EQ(anim::shellCommandRefusal(o), "");
    o.commands[static_cast<int>(options::ShellHook::PostFrame)].command = "echo hi";
    const std::string refusal = anim::shellCommandRefusal(o);
    EXPECT_NE(refusal.find("Post_Frame_Command 'echo hi' is refused"), std::string::npos)
        << refusal;
    EXPECT_NE(refusal.find("Allow_Shell_Commands=on"), std::string::npos) << refusal;
    o.allowShellCommands = true;
    EXPECT_EQ(anim::shellCommandRefusal(o), "");
}

TEST(ShellCommands, NamedIniFilesCannotWidenTheRestrictions) {
    const fs::path ini =
        fs::temp_directory_path() / ("frameray_widen_" + std::to_string(::getpid()) + ".ini");
    std::ofstream(ini) << "Width=9\nAllow_Shell_Commands=on\n";
    options::RenderOptions o;
    try {
        options::applyArguments(o, {ini.string()});
        ADD_FAILURE() << "Allow_Shell_Commands accepted from an INI file";
    } catch (const options::OptionError& e) {
        EXPECT_NE(
            std::string(e.what()).find(":2: option 'Allow_Shell_Commands' widens the restrictions"),
            std::string::npos)
            << e.what();
    }
    // The command line may.
    options::applyArguments(o, {"Allow_Shell_Commands=on"});
    EXPECT_TRUE(o.allowShellCommands);
    fs::remove(ini);
}
