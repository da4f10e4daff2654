// The option layer: every option of the table, both forms, INI files,
// precedence, Create_Ini and the "not supported yet" check. Expected
// values come from povray 3.7 (Debian 3.7.0.10) where it shows them
// (Create_Ini output, image resolution lines, files written).
#include "options/options.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

#include "options/option_table.h"

using namespace frameray::options;
namespace fs = std::filesystem;

namespace {

RenderOptions parse(const std::vector<std::string>& args) {
    RenderOptions o;
    applyArguments(o, args);
    return o;
}

struct TempDir {
    fs::path path;
    explicit TempDir(const std::string& name) : path(fs::temp_directory_path() / name) {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() { fs::remove_all(path); }
    fs::path write(const std::string& name, const std::string& text) const {
        std::ofstream(path / name) << text;
        return path / name;
    }
};

const StreamOptions& stream(const RenderOptions& o, TextStream s) {
    return o.streams[static_cast<int>(s)];
}
const ShellCommand& hook(const RenderOptions& o, ShellHook h) {
    return o.commands[static_cast<int>(h)];
}

}  // namespace

TEST(Options, SwitchesSetValues) {
    RenderOptions o = parse({"+W320", "+h240", "scene.pov", "+Oout.png", "-D", "+KFI3", "+KFF12",
                             "+KI0.5", "+KF2", "+KC", "+FN16", "+A0.2", "Declare=Foo=3"});
    EXPECT_EQ(o.width, 320);
    EXPECT_EQ(o.height, 240);
    EXPECT_EQ(o.inputFile, "scene.pov");
    EXPECT_EQ(o.outputFile, "out.png");
    EXPECT_FALSE(o.display);
    EXPECT_EQ(o.initialFrame, 3);
    EXPECT_TRUE(o.initialFrameSet);
    EXPECT_EQ(o.finalFrame, 12);
    EXPECT_EQ(o.initialClock, 0.5);
    EXPECT_EQ(o.finalClock, 2);
    EXPECT_TRUE(o.cyclicAnimation);
    EXPECT_EQ(o.bitDepth, 16);
    EXPECT_TRUE(o.antialias);
    EXPECT_DOUBLE_EQ(o.antialiasThreshold, 0.2);
    ASSERT_EQ(o.declares.size(), 1u);
    EXPECT_EQ(o.declares[0].first, "Foo");
    EXPECT_EQ(o.declares[0].second, "3");
}

TEST(Options, EveryOptionBothForms) {
    // Output.
    EXPECT_EQ(parse({"+Iscene.pov"}).inputFile, "scene.pov");
    EXPECT_EQ(parse({"Input_File_Name=\"a b.pov\""}).inputFile, "a b.pov");
    EXPECT_EQ(parse({"Output_File_Name=frames/"}).outputFile, "frames/");
    EXPECT_FALSE(parse({"Output_To_File=off"}).outputToFile);
    EXPECT_FALSE(parse({"-F"}).outputToFile);
    EXPECT_TRUE(parse({"-F", "+F"}).outputToFile);
    EXPECT_EQ(parse({"Output_File_Type=T"}).outputType, 'T');
    for (char c : std::string("NPTCEHJB")) EXPECT_EQ(parse({std::string("+F") + c}).outputType, c);
    EXPECT_EQ(parse({"+fp"}).outputType, 'P');
    EXPECT_EQ(parse({"+FN5"}).bitDepth, 5);
    EXPECT_EQ(parse({"+FN17"}).bitDepth, 16);  // povray writes 16-bit channels
    EXPECT_EQ(parse({"+FN0"}).bitDepth, 8);    // and 8-bit ones here
    EXPECT_EQ(parse({"Output_File_Type=N8"}).bitDepth, 8);
    EXPECT_EQ(parse({"Bits_Per_Color=12"}).bitDepth, 12);
    EXPECT_THROW(parse({"+FS"}), OptionError);  // povray: "Failed to parse command-line option"
    EXPECT_THROW(parse({"+FX"}), OptionError);
    EXPECT_TRUE(parse({"+UA"}).outputAlpha);
    EXPECT_TRUE(parse({"Output_Alpha=on"}).outputAlpha);
    EXPECT_EQ(parse({"File_Gamma=2.2"}).fileGamma, 2.2);
    EXPECT_EQ(parse({"File_Gamma=sRGB"}).fileGamma, 0);
    EXPECT_EQ(parse({"Display_Gamma=1.8"}).displayGamma, 1.8);
    EXPECT_EQ(parse({"+HIhead.inc"}).includeHeader, "head.inc");
    // Window.
    RenderOptions w = parse({"+SR0.5", "+ER0.75", "+SC3", "+EC7"});
    EXPECT_EQ(w.startRow, 0.5);
    EXPECT_EQ(w.endRow, 0.75);
    EXPECT_EQ(w.startColumn, 3);
    EXPECT_EQ(w.endColumn, 7);
    w = parse({"Start_Row=2", "End_Row=4", "Start_Column=0.25", "End_Column=1.0"});
    EXPECT_EQ(w.startRow, 2);
    EXPECT_EQ(w.endColumn, 1.0);
    // Quality.
    EXPECT_FALSE(parse({"+A", "-A"}).antialias);
    EXPECT_FALSE(parse({"Antialias=off"}).antialias);
    EXPECT_EQ(parse({"Antialias_Threshold=0.1"}).antialiasThreshold, 0.1);
    EXPECT_EQ(parse({"+R4"}).antialiasDepth, 4);
    EXPECT_EQ(parse({"Antialias_Depth=2"}).antialiasDepth, 2);
    EXPECT_FALSE(parse({"-J"}).jitter);
    EXPECT_EQ(parse({"+J0.5"}).jitterAmount, 0.5);
    EXPECT_TRUE(parse({"+J0.5"}).jitter);
    EXPECT_FALSE(parse({"Jitter=off"}).jitter);
    EXPECT_EQ(parse({"Jitter_Amount=0.25"}).jitterAmount, 0.25);
    EXPECT_EQ(parse({"+AM2"}).samplingMethod, 2);
    EXPECT_EQ(parse({"Sampling_Method=1"}).samplingMethod, 1);
    EXPECT_EQ(parse({"+Q7"}).quality, 7);
    EXPECT_EQ(parse({"Quality=3"}).quality, 3);
    EXPECT_FALSE(parse({"-MB"}).bounding);
    EXPECT_EQ(parse({"+MB5"}).boundingThreshold, 5);
    EXPECT_EQ(parse({"Bounding_Threshold=7"}).boundingThreshold, 7);
    EXPECT_FALSE(parse({"Bounding=off"}).bounding);
    EXPECT_EQ(parse({"+MV3.5"}).version, 3.5);
    EXPECT_EQ(parse({"Version=3.1"}).version, 3.1);
    // Animation.
    EXPECT_EQ(parse({"+K0.3"}).clock, 0.3);
    EXPECT_TRUE(parse({"Clock=0"}).clockSet);
    EXPECT_EQ(parse({"Initial_Frame=4"}).initialFrame, 4);
    EXPECT_EQ(parse({"Final_Frame=40"}).finalFrame, 40);
    EXPECT_EQ(parse({"+KFI1.6"}).initialFrame, 1);
    EXPECT_EQ(parse({"Initial_Clock=-1"}).initialClock, -1);
    EXPECT_EQ(parse({"Final_Clock=5"}).finalClock, 5);
    EXPECT_EQ(parse({"+SF0.5"}).subsetStartFrame, 0.5);
    EXPECT_EQ(parse({"Subset_Start_Frame=3"}).subsetStartFrame, 3);
    EXPECT_EQ(parse({"+EF7"}).subsetEndFrame, 7);
    EXPECT_TRUE(parse({"Subset_End_Frame=0.9"}).subsetEndSet);
    EXPECT_TRUE(parse({"Cyclic_Animation=yes"}).cyclicAnimation);
    EXPECT_TRUE(parse({"+UF"}).fieldRender);
    EXPECT_TRUE(parse({"Field_Render=true"}).fieldRender);
    EXPECT_TRUE(parse({"+UO"}).oddField);
    EXPECT_FALSE(parse({"Odd_Field=0"}).oddField);
    EXPECT_EQ(parse({"Frame_Step=3"}).frameStep, 3);
    EXPECT_EQ(parse({"+STP2"}).frameStep, 2);
    // Run.
    EXPECT_TRUE(parse({"+C"}).continueTrace);
    EXPECT_TRUE(parse({"Continue_Trace=on"}).continueTrace);
    EXPECT_FALSE(parse({"-V"}).verbose);
    EXPECT_FALSE(parse({"Verbose=false"}).verbose);
    EXPECT_TRUE(parse({"+D"}).display);
    EXPECT_TRUE(parse({"+D0G"}).display);  // display type and palette letters
    EXPECT_TRUE(parse({"Display=1"}).display);
    EXPECT_TRUE(parse({"+P"}).pauseWhenDone);
    EXPECT_TRUE(parse({"Pause_When_Done=on"}).pauseWhenDone);
    RenderOptions x = parse({"+X100"});
    EXPECT_TRUE(x.testAbort);
    EXPECT_EQ(x.testAbortCount, 100);
    EXPECT_EQ(parse({"Test_Abort_Count=50"}).testAbortCount, 50);
    EXPECT_TRUE(parse({"Test_Abort=on"}).testAbort);
    EXPECT_EQ(parse({"+WT2"}).workThreads, 2);
    EXPECT_EQ(parse({"Work_Threads=1"}).workThreads, 1);
    EXPECT_EQ(parse({"+GIout.ini"}).createIni, "out.ini");
    EXPECT_EQ(parse({"Create_Ini=x.ini"}).createIni, "x.ini");
}

TEST(Options, LibraryPathAccumulates) {
    const RenderOptions o = parse({"+L/a", "Library_Path=\"/b c\"", "+L/d"});
    ASSERT_EQ(o.libraryPaths.size(), 3u);
    EXPECT_EQ(o.libraryPaths[1], "/b c");
    EXPECT_EQ(o.libraryPaths[2], "/d");
}

TEST(Options, Declares) {
    const RenderOptions o = parse({"Declare=A=1", "declare=B=\"text\"", "Declare=C=2.5"});
    ASSERT_EQ(o.declares.size(), 3u);
    EXPECT_EQ(o.declares[1].first, "B");
    EXPECT_EQ(o.declares[1].second, "text");
    EXPECT_THROW(parse({"Declare=NoValue"}), OptionError);
}

TEST(Options, TextStreams) {
    // +GWname: console on and a file; -GD: console off (povray's Create_Ini
    // shows Warning_Console=On, Warning_File="warn.txt", Debug_Console=Off).
    RenderOptions o = parse({"+GWwarn.txt", "-GD"});
    EXPECT_TRUE(stream(o, TextStream::Warning).console);
    EXPECT_EQ(stream(o, TextStream::Warning).file, "warn.txt");
    EXPECT_FALSE(stream(o, TextStream::Debug).console);
    EXPECT_TRUE(stream(o, TextStream::Debug).file.empty());
    // A boolean value names the default file (povray writes debug.out ...).
    o = parse({"Debug_File=on", "Fatal_File=1", "Render_File=true", "Statistic_File=yes",
               "Warning_File=on", "All_File=on"});
    EXPECT_EQ(stream(o, TextStream::Debug).file, "debug.out");
    EXPECT_EQ(stream(o, TextStream::Fatal).file, "fatal.out");
    EXPECT_EQ(stream(o, TextStream::Render).file, "render.out");
    EXPECT_EQ(stream(o, TextStream::Statistic).file, "stats.out");
    EXPECT_EQ(stream(o, TextStream::Warning).file, "warning.out");
    EXPECT_EQ(stream(o, TextStream::All).file, "alltext.out");
    o = parse({"Debug_Console=off", "Debug_File=dbg.txt", "All_Console=off", "+GSst.txt",
               "+GRrr.txt", "+GF"});
    EXPECT_FALSE(stream(o, TextStream::Debug).console);
    EXPECT_EQ(stream(o, TextStream::Debug).file, "dbg.txt");
    EXPECT_FALSE(stream(o, TextStream::All).console);
    EXPECT_EQ(stream(o, TextStream::Statistic).file, "st.txt");
    EXPECT_EQ(stream(o, TextStream::Render).file, "rr.txt");
    EXPECT_TRUE(stream(o, TextStream::Fatal).console);
    EXPECT_TRUE(parse({"Debug_File=off"}).streams[0].file.empty());
    // povray has no Statistics_File (it says "Problem with option setting").
    EXPECT_THROW(parse({"Statistics_File=on"}), OptionError);
}

TEST(Options, ShellCommands) {
    const RenderOptions o = parse(
        {"Pre_Scene_Command=echo a", "Pre_Frame_Command=\"echo %o %s\"", "Post_Frame_Command=x",
         "Post_Scene_Command=y", "User_Abort_Command=z", "Fatal_Error_Command=w",
         "Pre_Frame_Return=s", "Post_Frame_Return=-f", "Fatal_Error_Return=!q",
         "User_Abort_Return=i", "Pre_Scene_Return=A", "Post_Scene_Return=u"});
    EXPECT_EQ(hook(o, ShellHook::PreScene).command, "echo a");
    EXPECT_EQ(hook(o, ShellHook::PreFrame).command, "echo %o %s");
    EXPECT_EQ(hook(o, ShellHook::PostFrame).command, "x");
    EXPECT_EQ(hook(o, ShellHook::PostScene).command, "y");
    EXPECT_EQ(hook(o, ShellHook::UserAbort).command, "z");
    EXPECT_EQ(hook(o, ShellHook::FatalError).command, "w");
    EXPECT_EQ(hook(o, ShellHook::PreFrame).action, "s");
    EXPECT_EQ(hook(o, ShellHook::PostFrame).action, "-f");
    EXPECT_EQ(hook(o, ShellHook::FatalError).action, "!q");
    EXPECT_THROW(parse({"Pre_Frame_Return=x"}), OptionError);
    EXPECT_THROW(parse({"Pre_Frame_Return=ss"}), OptionError);
}

TEST(Options, LongestSwitchWins) {
    std::string_view value;
    EXPECT_EQ(findSwitch("KFF20", value)->iniKey, "Final_Frame");
    EXPECT_EQ(value, "20");
    EXPECT_EQ(findSwitch("KF0.5", value)->iniKey, "Final_Clock");
    EXPECT_EQ(findSwitch("WT2", value)->iniKey, "Work_Threads");
    EXPECT_EQ(findSwitch("W320", value)->iniKey, "Width");
    EXPECT_EQ(findSwitch("GWx", value)->iniKey, "Warning_Console");
    EXPECT_EQ(findSwitch("GIx.ini", value)->iniKey, "Create_Ini");
    EXPECT_EQ(findSwitch("HIx", value)->iniKey, "Include_Header");
    EXPECT_EQ(findSwitch("H240", value)->iniKey, "Height");
    EXPECT_EQ(findSwitch("AM2", value)->iniKey, "Sampling_Method");
    EXPECT_EQ(findSwitch("STP2", value)->iniKey, "Frame_Step");
    EXPECT_EQ(findSwitch("SR2", value)->iniKey, "Start_Row");
}

TEST(Options, EveryTableEntryIsReachable) {
    // Each key parses as Key=Value, each switch as +X; no switch shadows
    // another's key.
    for (const OptionSpec& spec : optionTable()) {
        EXPECT_EQ(findIniKey(spec.iniKey), &spec) << spec.iniKey;
        if (!spec.switchName.empty()) {
            std::string_view value;
            EXPECT_EQ(findSwitch(spec.switchName, value), &spec) << spec.switchName;
        }
    }
}

TEST(Options, UnknownSwitchAndBadValueAreErrors) {
    RenderOptions o;
    try {
        applyArguments(o, {"+ZZ9"});
        FAIL();
    } catch (const OptionError& e) {
        EXPECT_STREQ(e.what(), "command line: unknown switch '+ZZ9'");
    }
    try {
        applyArguments(o, {"Width=abc"});
        FAIL();
    } catch (const OptionError& e) {
        EXPECT_STREQ(e.what(), "command line: bad value for option 'Width': 'abc' is not a number");
    }
    EXPECT_THROW(applyArguments(o, {"+Wabc"}), OptionError);
    EXPECT_THROW(applyArguments(o, {"Width=0"}), OptionError);
    EXPECT_THROW(applyArguments(o, {"Foo=3"}), OptionError);
    EXPECT_THROW(applyArguments(o, {"Cyclic_Animation=maybe"}), OptionError);
    EXPECT_THROW(applyArguments(o, {"nofile.ini"}), OptionError);
}

TEST(Options, Booleans) {
    for (const char* on : {"on", "ON", "true", "yes", "1", "On"})
        EXPECT_TRUE(parse({std::string("Verbose=") + on}).verbose);
    for (const char* off : {"off", "false", "no", "0", "Off", "FALSE"})
        EXPECT_FALSE(parse({std::string("Verbose=") + off}).verbose);
    EXPECT_FALSE(parse({"-KC"}).cyclicAnimation);
    EXPECT_TRUE(parse({"+KC"}).cyclicAnimation);
}

TEST(Options, IniFilesWithSectionsAndSwitches) {
    TempDir dir("frameray_options_test");
    const auto ini =
        dir.write("t.ini",
                  "; comment\nWidth = 100 ; trailing comment\nAntialias=on\n+kff20 +kc\n"
                  "[Big]\nWidth=1000\n[Small]\nWidth=10\n");
    RenderOptions o;
    applyArguments(o, {ini.string()});
    EXPECT_EQ(o.width, 100);
    EXPECT_TRUE(o.antialias);
    EXPECT_EQ(o.finalFrame, 20);
    EXPECT_TRUE(o.cyclicAnimation);
    applyArguments(o, {ini.string() + "[Small]"});
    EXPECT_EQ(o.width, 10);
    applyArguments(o, {ini.string() + "[big]"});  // section names ignore case
    EXPECT_EQ(o.width, 1000);
    // A missing section reads nothing (povray renders on without a word);
    // frameray warns.
    const auto warnings = applyArguments(o, {ini.string() + "[None]"});
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("no section [None]"), std::string::npos);

    const auto bad = dir.write("bad.ini", "Width=10\nNot_An_Option=3\n");
    try {
        applyArguments(o, {bad.string()});
        FAIL();
    } catch (const OptionError& e) {
        EXPECT_NE(std::string(e.what()).find("bad.ini:2: unknown option 'Not_An_Option'"),
                  std::string::npos);
    }
    const auto badValue = dir.write("badvalue.ini", "\n\nHeight=tall\n");
    try {
        applyArguments(o, {badValue.string()});
        FAIL();
    } catch (const OptionError& e) {
        EXPECT_NE(std::string(e.what()).find("badvalue.ini:3: bad value for option 'Height'"),
                  std::string::npos);
    }
}

TEST(Options, SplinefollowIniLine) {
    // /usr/share/doc/povray/examples/animations/splinefollow/splinefollow.ini
    TempDir dir("frameray_options_spline");
    const auto ini =
        dir.write("splinefollow.ini",
                  "Antialias=On\nAntialias_Threshold=0.3\nAntialias_Depth=3\n"
                  "Input_File_Name=splinefollow.pov\n+kf0.1666 +kff20 +kc declare=fp=0\n"
                  "Cyclic_Animation=on\nPause_when_Done=off\n");
    const RenderOptions o = parse({ini.string()});
    EXPECT_DOUBLE_EQ(o.finalClock, 0.1666);
    EXPECT_EQ(o.finalFrame, 20);
    EXPECT_TRUE(o.cyclicAnimation);
    ASSERT_EQ(o.declares.size(), 1u);
    EXPECT_EQ(o.declares[0].first, "fp");
    EXPECT_EQ(o.declares[0].second, "0");
    EXPECT_EQ(o.inputFile, "splinefollow.pov");
    EXPECT_EQ(o.antialiasDepth, 3);
    EXPECT_FALSE(o.pauseWhenDone);
}

TEST(Options, IniNamingIniAndQuotedValues) {
    TempDir dir("frameray_options_nested");
    dir.write("inner.ini", "Height=77\n[Sec]\nHeight=88\n");
    const auto outer =
        dir.write("outer.ini",
                  "Width=55\ninner.ini\n\"inner.ini[Sec]\"\nPre_Frame_Command=echo \"a;b\" %n ; c\n"
                  "Output_File_Name=\"my frames/\"\n");
    const RenderOptions o = parse({outer.string()});
    EXPECT_EQ(o.width, 55);
    EXPECT_EQ(o.height, 88);  // the later [Sec] wins
    EXPECT_EQ(hook(o, ShellHook::PreFrame).command, "echo \"a;b\" %n");
    EXPECT_EQ(o.outputFile, "my frames/");
}

TEST(Options, LaterSourcesWin) {
    TempDir dir("frameray_options_order");
    const auto ini = dir.write("a.ini", "Width=100\nHeight=50\n");
    RenderOptions o = parse({"+W10", ini.string(), "+H20"});
    EXPECT_EQ(o.width, 100);
    EXPECT_EQ(o.height, 20);
}

TEST(Options, StartupIniAndPovrayopt) {
    TempDir dir("frameray_options_startup");
    fs::create_directories(dir.path / "home/.povray/3.7");
    fs::create_directories(dir.path / "cwd");
    const auto sys = dir.write("system.ini", "Width=800\nHeight=600\nLibrary_Path=\"/sys\"\n");
    std::map<std::string, std::string> env;
    StartupEnvironment e;
    e.getenv = [&env](const char* n) -> const char* {
        const auto it = env.find(n);
        return it == env.end() ? nullptr : it->second.c_str();
    };
    e.workingDir = dir.path / "cwd";
    e.systemIni = sys;
    env["HOME"] = (dir.path / "home").string();
    // Only the system file.
    EXPECT_EQ(findStartupIni(e), sys);
    // ~/.povray/3.7/povray.ini replaces it (povray then has no library path).
    std::ofstream(dir.path / "home/.povray/3.7/povray.ini") << "Height=9\n";
    EXPECT_EQ(findStartupIni(e), dir.path / "home/.povray/3.7/povray.ini");
    // ./povray.ini comes before the home one.
    std::ofstream(dir.path / "cwd/povray.ini") << "Width=11\n";
    EXPECT_EQ(findStartupIni(e), dir.path / "cwd/povray.ini");
    // $POVINI before everything.
    const auto povini = dir.write("x.ini", "Width=15\n");
    env["POVINI"] = povini.string();
    EXPECT_EQ(findStartupIni(e), povini);

    // POVRAYOPT, then the startup file, then the command line.
    env["POVRAYOPT"] = "+W13 +H14 +KFF5";
    RenderOptions o;
    applyStartupOptions(o, e);
    EXPECT_EQ(o.width, 15);   // povray.ini after POVRAYOPT
    EXPECT_EQ(o.height, 14);  // from POVRAYOPT
    EXPECT_EQ(o.finalFrame, 5);
    applyArguments(o, {"+W17"});
    EXPECT_EQ(o.width, 17);
}

TEST(Options, CreateIniWritesWhatWasSet) {
    // povray 3.7: +GIc.ini +KFF3 +KC Declare=Foo=3 +L/tmp +SR2 +A0.1 +X100
    // +GWwarn.txt writes these keys, sorted as here, booleans On/Off,
    // file names quoted, commands not.
    const RenderOptions o =
        parse({"s.pov", "+GIcreated.ini", "+KFF3", "+KC", "Declare=Foo=3",
               "+L/usr/share/povray-3.7/include", "+SR2", "+A0.1", "+X100", "+GWwarn.txt", "+FN16",
               "Pre_Frame_Command=echo hi %o", "+J0.5", "Jitter=off", "+W8", "+H6", "-D"});
    const std::string ini = createIniText(o);
    const std::string expected =
        "Antialias=On\n"
        "Antialias_Threshold=0.1\n"
        "Bits_Per_Color=16\n"
        "Create_Ini=\"created.ini\"\n"
        "Cyclic_Animation=On\n"
        "Declare=Foo=3\n"
        "Display=Off\n"
        "Final_Frame=3\n"
        "Height=6\n"
        "Input_File_Name=\"s.pov\"\n"
        "Jitter_Amount=0.5\n"
        "Jitter=Off\n"
        "Library_Path=\"/usr/share/povray-3.7/include\"\n"
        "Output_File_Type=N\n"
        "Output_To_File=On\n"
        "Pre_Frame_Command=echo hi %o\n"
        "Start_Row=2\n"
        "Test_Abort_Count=100\n"
        "Test_Abort=On\n"
        "Warning_Console=On\n"
        "Warning_File=\"warn.txt\"\n"
        "Width=8\n";
    EXPECT_EQ(ini, expected);
    // The written file reads back to the same options.
    TempDir dir("frameray_options_createini");
    const auto path = dir.write("created.ini", ini);
    const RenderOptions back = parse({path.string()});
    EXPECT_EQ(createIniText(back), ini);
}

TEST(Options, UnsupportedValuesAreNamed) {
    EXPECT_EQ(firstUnsupported(parse({})), "");
    EXPECT_EQ(firstUnsupported(
                  parse({"+A0.2", "+UF", "+UO", "-UA", "+Q4", "+J", "+AM2", "+R3", "+BS16"})),
              "");
    EXPECT_EQ(firstUnsupported(parse({"+UA"})), "");
    EXPECT_EQ(firstUnsupported(parse({"+UA", "+FE"})),
              "Output_Alpha (alpha channel output (+UA) to EXR)");
    EXPECT_EQ(firstUnsupported(parse({"+Q2"})), "");
    EXPECT_EQ(firstUnsupported(parse({"+Q0"})), "");  // quick colours
    EXPECT_EQ(firstUnsupported(parse({"+Q1"})), "");
    EXPECT_EQ(firstUnsupported(parse({"+HIx.inc"})), "");  // Include_Header
    EXPECT_EQ(firstUnsupported(parse({"+O-"})), "");       // standard output
    EXPECT_EQ(firstUnsupported(parse({"Grayscale_Output=on", "+FP"})), "");
    // povray: "Unsupported combination of options".
    EXPECT_NE(firstUnsupported(parse({"Grayscale_Output=on", "+FT"})).find("Grayscale_Output"),
              std::string::npos);
}

TEST(Options, HelpListsEveryOption) {
    const std::string help = helpText();
    for (const OptionSpec& o : optionTable())
        EXPECT_NE(help.find(o.iniKey), std::string::npos) << o.iniKey;
}

TEST(Options, ReadmeListsTheOptionTable) {
    // The README's option section is generated from the table
    // (build/bin/frameray --options-markdown); this keeps it current.
    std::ifstream in(FRAMERAY_SOURCE_DIR "/README.md");
    ASSERT_TRUE(in) << "README.md not found";
    const std::string readme((std::istreambuf_iterator<char>(in)),
                             std::istreambuf_iterator<char>());
    EXPECT_NE(readme.find(optionsMarkdown()), std::string::npos)
        << "README.md's option table is out of date: paste the output of `frameray "
           "--options-markdown`";
}

// The trust rule (README, Restrictions): an INI file named on the command
// line, or ./povray.ini, may come with a scene, so every file or folder it
// names must be in its own folder or the working folder.
TEST(Options, UntrustedIniNamesPathsOnlyInItsFolders) {
    TempDir dir("frameray_options_trust");
    fs::create_directories(dir.path / "scene");
    const auto refused = [&](const std::string& text) {
        const auto ini = dir.write("scene/t.ini", text);
        RenderOptions o;
        try {
            applyArguments(o, {ini.string()});
        } catch (const OptionError& e) {
            return std::string(e.what()).find("not allowed outside the INI file's folder") !=
                   std::string::npos;
        }
        return false;
    };
    EXPECT_TRUE(refused("Library_Path=/etc\n"));
    EXPECT_TRUE(refused("+L/etc\n"));
    EXPECT_TRUE(refused("Library_Path=../../..\n"));
    EXPECT_TRUE(refused("Output_File_Name=/tmp/\n"));
    EXPECT_TRUE(refused("Warning_File=/tmp/w.txt\n"));
    EXPECT_TRUE(refused("+GS/tmp/s.txt\n"));
    EXPECT_TRUE(refused("Create_Ini=/tmp/c.ini\n"));
    EXPECT_TRUE(refused("Include_Header=/etc/passwd\n"));
    EXPECT_TRUE(refused("/etc/other.ini\n"));
    EXPECT_TRUE(refused("/home/someone/.profile\n"));  // a scene named on a line of its own
    // In the INI's folder (or below it) and the working folder: fine.
    EXPECT_FALSE(refused("Library_Path=" + (dir.path / "scene/inc").string() + "\n"));
    EXPECT_FALSE(refused("Output_File_Name=" + (dir.path / "scene/frames/").string() + "\n"));
    EXPECT_FALSE(refused("Output_File_Name=frames/\nDebug_File=on\nLibrary_Path=.\n"));
    // Image, animation and quality options are the INI's to set.
    EXPECT_FALSE(refused("Width=64\nHeight=48\n+KFF10 +A0.1\nQuality=4\n"));
    // A symbolic link inside the scene's folder cannot lead out of it.
    fs::create_directory_symlink("/etc", dir.path / "scene/etc");
    EXPECT_TRUE(refused("Library_Path=" + (dir.path / "scene/etc").string() + "\n"));
    // The same options from the command line are the user's own.
    RenderOptions o;
    applyArguments(o, {"Library_Path=/etc", "+O/tmp/", "Debug_File=/tmp/d.txt"});
    EXPECT_EQ(o.libraryPaths.back(), fs::path("/etc"));
}

TEST(Options, WorkingFolderPovrayIniIsUntrusted) {
    TempDir dir("frameray_options_trust_startup");
    fs::create_directories(dir.path / "cwd");
    std::map<std::string, std::string> env{{"HOME", (dir.path / "home").string()}};
    StartupEnvironment e;
    e.getenv = [&env](const char* n) -> const char* {
        const auto it = env.find(n);
        return it == env.end() ? nullptr : it->second.c_str();
    };
    e.workingDir = dir.path / "cwd";
    e.systemIni = dir.path / "none.ini";
    std::ofstream(dir.path / "cwd/povray.ini") << "Library_Path=/etc\n";
    RenderOptions o;
    EXPECT_THROW(applyStartupOptions(o, e), OptionError);
    // $POVINI is the user's choice.
    env["POVINI"] = dir.write("mine.ini", "Library_Path=/etc\n").string();
    RenderOptions p;
    applyStartupOptions(p, e);
    EXPECT_EQ(p.libraryPaths.back(), fs::path("/etc"));
}

// povray refuses an INI line "Width 64"; frameray says what is wrong. A
// UTF-8 byte order mark before the first key is skipped.
TEST(Options, IniLinesWithoutEqualsAndByteOrderMarks) {
    TempDir dir("frameray_options_ini_lines");
    RenderOptions o;
    try {
        applyArguments(o, {dir.write("a.ini", "Height=9\nWidth 64\n").string()});
        FAIL();
    } catch (const OptionError& e) {
        EXPECT_NE(std::string(e.what()).find("a.ini:2: option 'Width' needs '='"),
                  std::string::npos);
    }
    EXPECT_THROW(applyArguments(o, {dir.write("b.ini", "Width\n").string()}), OptionError);
    EXPECT_THROW(applyArguments(o, {dir.write("c.ini", "+W8 64\n").string()}), OptionError);
    applyArguments(o, {dir.write("d.ini", "\xEF\xBB\xBFWidth=64\nHeight=48\n").string()});
    EXPECT_EQ(o.width, 64);
    EXPECT_EQ(o.height, 48);
    // A scene or INI file name on a line of its own still works.
    applyArguments(o, {dir.write("e.ini", "scene.pov\n+W5 d.ini\n").string()});
    EXPECT_EQ(o.inputFile, "scene.pov");
    EXPECT_EQ(o.width, 64);
}

// The rest of povray 3.7's keys (issue 30). Measured with povray 3.7.0.10:
// each switch below sets the key Create_Ini then writes (+UL writes
// Light_Buffer=On, +KLA Clockless_Animation=On, +RFfoo
// Radiosity_File_Name="foo", +B Bounding=On, ...).
TEST(Options, OldAndPreviewKeysAreAcceptedAndWrittenBack) {
    const std::vector<std::pair<std::string, std::string>> switches = {
        {"+UL", "Light_Buffer=On"},
        {"-UV", "Vista_Buffer=Off"},
        {"+UD", "Draw_Vistas=On"},
        {"-UR", "Remove_Bounds=Off"},
        {"+SU", "Split_Unions=On"},
        {"+BM2", "Bounding_Method=2"},
        {"+RP3", "Render_Pattern=3"},
        {"+RS2", "Render_Block_Step=2"},
        {"+SP8", "Preview_Start_Size=8"},
        {"+EP2", "Preview_End_Size=2"},
        {"+MI64", "Max_Image_Buffer_Memory=64"},
        {"+GP", "Append_File=On"},
        {"+KLA", "Clockless_Animation=On"},
        {"+HR", "High_Reproducibility=On"},
        {"-RTR", "Real_Time_Raytracing=Off"},
        {"+RTR", "Real_Time_Raytracing=On"},
        {"+WL3", "Warning_Level=3"},
        {"+RFfoo", "Radiosity_File_Name=\"foo\""},
        {"-RFI", "Radiosity_From_File=Off"},
        {"-RFO", "Radiosity_To_File=Off"},
        {"+RVP", "Radiosity_Vain_Pretrace=On"},
        {"+B", "Bounding=On"},
        {"-B", "Bounding=Off"},
    };
    for (const auto& [sw, line] : switches)
        EXPECT_NE(createIniText(parse({sw})).find(line + "\n"), std::string::npos) << sw;
    const std::vector<std::pair<std::string, std::string>> keys = {
        {"Palette=G", "Palette=g"},
        {"Video_Mode=0", "Video_Mode=0"},
        {"Dither=on", "Dither=On"},
        {"Dither_Method=b3", "Dither_Method=B3"},
        {"Grayscale_Output=yes", "Grayscale_Output=On"},
        {"Bits_Per_Colour=12", "Bits_Per_Color=12"},
    };
    for (const auto& [key, line] : keys)
        EXPECT_NE(createIniText(parse({key})).find(line + "\n"), std::string::npos) << key;
    EXPECT_EQ(parse({"Bits_Per_Colour=5"}).bitDepth, 5);
    // povray 3.7.0 has no A2/A3 (3.7.1 does): "Failed to parse".
    EXPECT_THROW(parse({"Dither_Method=A2"}), OptionError);
    EXPECT_THROW(parse({"Light_Buffer=maybe"}), OptionError);
    // The obsolete ones povray reads from INI files ("INI option
    // 'Buffer_Output' is no longer used") and does not write back.
    for (const char* key :
         {"Buffer_Output=on", "Buffer_Size=10", "Create_Histogram=on", "Histogram_Type=C",
          "Histogram_Name=h.csv", "Histogram_Grid_Size=4.4"}) {
        const RenderOptions o = parse({key});
        EXPECT_EQ(createIniText(o).find(std::string(key).substr(0, 6)), std::string::npos) << key;
    }
}

TEST(Options, OptionsWithoutEffectSaySoOnce) {
    RenderOptions o;
    const auto warnings = applyArguments(o, {"+UL", "Light_Buffer=off", "+B", "+B100", "+SP4"});
    ASSERT_EQ(warnings.size(), 3u);
    EXPECT_NE(warnings[0].find("'Light_Buffer' has no effect"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[1].find("'Buffer_Size' has no effect"), std::string::npos) << warnings[1];
    EXPECT_NE(warnings[2].find("'Preview_Start_Size'"), std::string::npos) << warnings[2];
    EXPECT_TRUE(o.bounding);
}

TEST(Options, IncludeIniAndBareIniNames) {
    TempDir dir("frameray_include_ini");
    dir.write("size.ini", "Width=32\n[big]\nWidth=640\n");
    dir.write("main.ini", "Include_Ini=size.ini\nHeight=24\n");
    dir.write("section.ini", "Include_Ini=size.ini[big]\n");
    // povray's allstill.ini names res320 without its extension.
    dir.write("bare.ini", "size\n");
    RenderOptions a = parse({(dir.path / "main.ini").string()});
    EXPECT_EQ(a.width, 32);
    EXPECT_EQ(a.height, 24);
    EXPECT_EQ(parse({(dir.path / "section.ini").string()}).width, 640);
    RenderOptions b;
    const auto warnings = applyArguments(b, {(dir.path / "bare.ini").string()});
    EXPECT_EQ(b.width, 32);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("'size' read as the INI file"), std::string::npos);
    // An empty return action (povray's pngfli.ini) is the default.
    dir.write("empty.ini", "Pre_Frame_Return=\nPre_Frame_Command=\n");
    EXPECT_EQ(parse({(dir.path / "empty.ini").string()}).commands[1].action, "");
}

TEST(Options, UnsupportedNewValuesAreNamed) {
    EXPECT_EQ(firstUnsupported(parse({"+RTR"})), "");  // frames render, no image is written
    EXPECT_FALSE(parse({"+RTR"}).writesImages());
    EXPECT_TRUE(parse({"+RTR", "-RTR"}).writesImages());
    // Radiosity cache files are read and written (render/radiosity_file.h).
    EXPECT_EQ(firstUnsupported(parse({"+RFI", "Radiosity_To_File=on"})), "");
    EXPECT_EQ(firstUnsupported(parse({"+UL", "+RFfile", "+SP8", "Dither=off"})), "");
}
