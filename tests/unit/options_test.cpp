#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "options/option_table.h"
#include "options/options.h"

using namespace frameray::options;

TEST(Options, SwitchesSetValues) {
    RenderOptions o;
    applyArguments(o, {"+W320", "+h240", "scene.pov", "+Oout.png", "-D", "+KFI3", "+KFF12", "+KI0.5", "+KF2", "+KC",
                       "+FN16", "+A0.2", "Declare=Foo=3"});
    EXPECT_EQ(o.width, 320);
    EXPECT_EQ(o.height, 240);
    EXPECT_EQ(o.inputFile, "scene.pov");
    EXPECT_EQ(o.outputFile, "out.png");
    EXPECT_FALSE(o.display);
    EXPECT_EQ(o.initialFrame, 3);
    EXPECT_EQ(o.finalFrame, 12);
    EXPECT_EQ(o.initialClock, 0.5);
    EXPECT_EQ(o.finalClock, 2);
    EXPECT_TRUE(o.cyclicAnimation);
    EXPECT_EQ(o.bitDepth, 16);
    EXPECT_TRUE(o.antialias);
    EXPECT_DOUBLE_EQ(o.antialiasThreshold, 0.2);
    ASSERT_EQ(o.declares.size(), 1u);
    EXPECT_EQ(o.declares[0].first, "Foo");
}

TEST(Options, LongestSwitchWins) {
    std::string_view value;
    EXPECT_EQ(findSwitch("KFF20", value)->iniKey, "Final_Frame");
    EXPECT_EQ(value, "20");
    EXPECT_EQ(findSwitch("KF0.5", value)->iniKey, "Final_Clock");
    EXPECT_EQ(findSwitch("WT2", value)->iniKey, "Work_Threads");
}

TEST(Options, UnknownSwitchAndBadValueAreErrors) {
    RenderOptions o;
    try {
        applyArguments(o, {"+ZZ9"});
        FAIL();
    } catch (const OptionError& e) {
        EXPECT_STREQ(e.what(), "command line: unknown switch '+ZZ9'");
    }
    EXPECT_THROW(applyArguments(o, {"+Wabc"}), OptionError);
    EXPECT_THROW(applyArguments(o, {"Width=0"}), OptionError);
}

TEST(Options, IniFilesWithSectionsAndSwitches) {
    const auto dir = std::filesystem::temp_directory_path() / "frameray_options_test";
    std::filesystem::create_directories(dir);
    const auto ini = dir / "t.ini";
    {
        std::ofstream out(ini);
        out << "; comment\nWidth = 100 ; trailing comment\nAntialias=on\n+kff20 +kc\n[Big]\nWidth=1000\n[Small]\nWidth=10\n";
    }
    RenderOptions o;
    applyArguments(o, {ini.string()});
    EXPECT_EQ(o.width, 100);
    EXPECT_TRUE(o.antialias);
    EXPECT_EQ(o.finalFrame, 20);
    EXPECT_TRUE(o.cyclicAnimation);
    applyArguments(o, {ini.string() + "[Small]"});
    EXPECT_EQ(o.width, 10);

    const auto bad = dir / "bad.ini";
    {
        std::ofstream out(bad);
        out << "Width=10\nNot_An_Option=3\n";
    }
    try {
        applyArguments(o, {bad.string()});
        FAIL();
    } catch (const OptionError& e) {
        EXPECT_NE(std::string(e.what()).find("bad.ini:2: unknown option 'Not_An_Option'"), std::string::npos);
    }
    std::filesystem::remove_all(dir);
}

TEST(Options, HelpListsEveryOption) {
    const std::string help = helpText();
    for (const OptionSpec& o : optionTable()) EXPECT_NE(help.find(o.iniKey), std::string::npos) << o.iniKey;
}

TEST(Options, ReadmeListsTheOptionTable) {
    // The README's option section is generated from the table
    // (build/bin/frameray --options-markdown); this keeps it current.
    std::ifstream in(FRAMERAY_SOURCE_DIR "/README.md");
    ASSERT_TRUE(in) << "README.md not found";
    const std::string readme((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(readme.find(optionsMarkdown()), std::string::npos)
        << "README.md's option table is out of date: paste the output of `frameray --options-markdown`";
}
