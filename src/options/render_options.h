// The typed result of all option sources (defaults, povray.ini, POVRAYOPT,
// INI files, switches): what a run renders and how. Defaults are POV-Ray
// 3.7's.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace frameray::options {

// The standard include files (Debian's povray-includes): always on the
// library path, and readable by every scene.
inline constexpr const char* kStandardIncludeFolder = "/usr/share/povray-3.7/include";
// povray's own INI files (quickres.ini, res640.ini...): an untrusted INI
// file may read them too (they are installed with povray and set nothing
// but image options).
inline constexpr const char* kStandardIniFolder = "/usr/share/povray-3.7/ini";

// POV-Ray's text streams, in the order of their option names.
enum class TextStream { Debug, Fatal, Render, Statistic, Warning, All };
inline constexpr int kTextStreams = 6;

struct StreamOptions {
    bool console = true;
    std::string file;  // empty: no file
};

// The moments POV-Ray shells out, in the order of their option names.
enum class ShellHook { PreScene, PreFrame, PostFrame, PostScene, UserAbort, FatalError };
inline constexpr int kShellHooks = 6;
// The hooks' names in the run log (the INI keys are Pre_Scene_Command ...).
inline constexpr const char* kShellHookNames[kShellHooks] = {
    "pre_scene", "pre_frame", "post_frame", "post_scene", "user_abort", "fatal_error"};

struct ShellCommand {
    std::string command;  // empty: none
    std::string action;   // the *_Return letters, e.g. "f" or "-s"
};

// frameray's own run log (anim/run_log.h): the least severe event kept,
// and the line format.
enum class LogLevel { Debug, Info, Warn, Error, Off };
enum class LogFormat { Text, Json };

// Output_AOVs' layer names, in the order the option keeps them.
inline constexpr std::string_view kAovNames[] = {"depth", "normal", "object_id", "albedo",
                                                 "motion"};
// Exr_Compression's codec names (OpenEXR's, as OpenImageIO spells them).
inline constexpr std::string_view kExrCompressions[] = {"none",  "rle", "zips", "zip",  "piz",
                                                        "pxr24", "b44", "b44a", "dwaa", "dwab"};

struct RenderOptions {
    // Input and output.
    std::string inputFile;
    std::string outputFile;  // empty: scene name in the working folder
    bool outputToFile = true;
    // Real_Time_Raytracing (+RTR): povray 3.7's beta render loop. Without a
    // display povray renders every frame once and writes no image; so does
    // frameray (it has no display).
    bool realTimeRaytracing = false;
    bool writesImages() const { return outputToFile && !realTimeRaytracing; }
    char outputType = 'N';  // N P T C E H J B
    int bitDepth = 8;       // bits per colour channel (Bits_Per_Color, +FN16)
    bool outputAlpha = false;
    double fileGamma = 0;  // <= 0: sRGB (POV-Ray 3.7's default)
    double displayGamma = 2.2;
    std::string includeHeader;        // Include_Header (+HI)
    bool grayscaleOutput = false;     // Grayscale_Output: one grey channel (PNG, PPM)
    bool dither = false;              // Dither: dither the quantisation to the file's levels
    std::string ditherMethod = "FS";  // Dither_Method: FS, B2, B3, B4
    bool appendFile = false;          // Append_File (+GP): stream files are appended to
    // Output_AOVs: extra layers of an EXR frame (render/aov_pass.h), in
    // kAovNames order, no repeats; empty: none.
    std::vector<std::string> outputAovs;
    std::string exrCompression = "zip";  // Exr_Compression: OpenEXR's codec name

    // Looking at a sequence: the contact sheet (anim/contact_sheet.h) and
    // the preview video (anim/preview_video.h) beside the frames.
    bool contactSheet = false;
    std::string previewVideo;  // "mp4", "webm"; empty: none
    double previewFps = 24;

    // Image and render window. Rows/columns as given: a value below 1
    // (start) or up to 1 (end) is a fraction of the image, others are
    // 1-based pixel numbers; 0 / -1 mean "not set".
    int width = 800;
    int height = 600;
    double startRow = 0, endRow = -1, startColumn = 0, endColumn = -1;

    // Animation. Frame options keep what was given; anim::planSequence
    // applies POV-Ray's rules.
    double clock = 0;
    bool clockSet = false;
    int initialFrame = 1, finalFrame = 1;
    bool initialFrameSet = false, finalFrameSet = false;
    double initialClock = 0, finalClock = 1;
    bool cyclicAnimation = false;
    double subsetStartFrame = 0, subsetEndFrame = 0;  // fractions below 1, frame numbers otherwise
    bool subsetStartSet = false, subsetEndSet = false;
    int frameStep = 1;
    bool fieldRender = false;
    // Distribution: this process renders the frames whose position in the
    // (subset, stepped) sequence modulo shardCount is shardIndex.
    int shardIndex = 0;
    int shardCount = 1;
    bool oddField = false;

    // Tracing quality.
    bool antialias = false;
    double antialiasThreshold = 0.3;
    double antialiasGamma = 2.5;
    int antialiasDepth = 3;
    bool jitter = true;
    double jitterAmount = 1.0;
    int samplingMethod = 1;
    int renderBlockSize = 32;
    int quality = 9;
    bool bounding = true;
    int boundingThreshold = 3;

    // Parsing.
    double version = 3.7;
    bool versionGiven = false;  // Version was set: the scene's version counts as declared
    std::vector<std::filesystem::path> libraryPaths;
    std::vector<std::pair<std::string, std::string>> declares;
    // Loop iterations and macro calls one frame's parse may run (0: no
    // limit); past it the frame ends with an error.
    long long maxParseIterations = 100'000'000;

    // Run.
    bool continueTrace = false;
    int workThreads = 0;     // 0: every core
    int framesInFlight = 0;  // frames parsed/rendered/written at once; 0: work threads + 1
    bool verbose = true;
    bool display = false;
    bool pauseWhenDone = false;
    bool testAbort = false;
    int testAbortCount = 1;
    std::string createIni;  // Create_Ini (+GI): write the effective options here
    // Radiosity cache files (Radiosity_File_Name, _From_File, _To_File;
    // povray's default name is object.rca, measured) and frameray's
    // Radiosity_Stable: every frame after the first starts from the first
    // frame's cache.
    std::string radiosityFile = "object.rca";
    bool radiosityFromFile = false;
    bool radiosityToFile = false;
    bool radiosityStable = false;
    LogLevel logLevel = LogLevel::Info;
    LogFormat logFormat = LogFormat::Text;
    // What reading the options warned of (also said on the console before
    // the run starts): the run log repeats them as option_warning events.
    std::vector<std::string> optionWarnings;

    std::array<StreamOptions, kTextStreams> streams;
    std::array<ShellCommand, kShellHooks> commands;

    // Restrictions (sdl/file_access.h): on by default, as povray.conf's.
    bool fileRestrictions = true;
    std::vector<std::filesystem::path> readPaths;   // Read_Path: more folders scenes may read
    std::vector<std::filesystem::path> writePaths;  // Write_Path: more folders scenes may write
    bool allowShellCommands = false;                // the *_Command options run only when on

    // INI keys set by any source so far, for Create_Ini.
    std::set<std::string> explicitlySet;
    // Options read that change nothing in frameray's output (Light_Buffer,
    // Preview_Start_Size, ...): the value as Create_Ini writes it back.
    std::map<std::string, std::string, std::less<>> acceptedValues;
};

}  // namespace frameray::options
