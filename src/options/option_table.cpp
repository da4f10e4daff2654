#include "options/option_table.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <initializer_list>
#include <stdexcept>
#include <utility>

namespace frameray::options {

namespace {

bool iequals(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

std::string trimQuotes(std::string_view v) {
    if (v.size() >= 2 &&
        ((v.front() == '"' && v.back() == '"') || (v.front() == '\'' && v.back() == '\'')))
        v = v.substr(1, v.size() - 2);
    return std::string(v);
}

// POV-Ray's boolean words. Returns -1 when `text` is not one.
int boolWord(std::string_view text) {
    static constexpr std::pair<std::string_view, bool> kWords[] = {
        {"on", true},   {"true", true},   {"yes", true}, {"1", true},
        {"off", false}, {"false", false}, {"no", false}, {"0", false},
    };
    for (const auto& [word, value] : kWords)
        if (iequals(text, word)) return value ? 1 : 0;
    return -1;
}

bool toBool(const OptionInput& in) {
    if (in.fromSwitch && in.value.empty()) return in.plus;
    const int b = boolWord(trimQuotes(in.value));
    if (b < 0)
        throw std::invalid_argument(
            fmt::format("'{}' is not a boolean (use on/off, true/false, yes/no, 1/0)", in.value));
    return in.fromSwitch ? (in.plus && b == 1) : b == 1;
}

double toFloat(std::string_view text) {
    const std::string s = trimQuotes(text);
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0' || !std::isfinite(v))
        throw std::invalid_argument(fmt::format("'{}' is not a number", text));
    return v;
}

// POV-Ray reads whole-number options as numbers and drops any fraction
// (+KFI1.6 is frame 1).
int toInt(std::string_view text) {
    const double v = std::trunc(toFloat(text));
    if (v < -2147483647.0 || v > 2147483647.0)
        throw std::invalid_argument(fmt::format("'{}' is out of range", text));
    return static_cast<int>(v);
}

int toPositiveInt(std::string_view text) {
    const int v = toInt(text);
    if (v < 1) throw std::invalid_argument(fmt::format("'{}' must be at least 1", text));
    return v;
}

double toNonNegative(std::string_view text) {
    const double v = toFloat(text);
    if (v < 0) throw std::invalid_argument(fmt::format("'{}' must not be negative", text));
    return v;
}

// One of a fixed set of words (case-insensitive), e.g. Log_Level's.
template <typename T>
T choice(std::string_view text, std::initializer_list<std::pair<std::string_view, T>> words) {
    const std::string v = trimQuotes(text);
    std::string names;
    for (const auto& [word, value] : words) {
        if (iequals(v, word)) return value;
        names += fmt::format("{}{}", names.empty() ? "" : ", ", word);
    }
    throw std::invalid_argument(fmt::format("'{}' is not one of {}", text, names));
}

constexpr std::string_view kLogLevelNames[] = {"debug", "info", "warn", "error", "off"};

void mark(RenderOptions& o, std::string_view key) {
    o.explicitlySet.emplace(key);
}

// Output_AOVs: a comma-separated subset of kAovNames ("none" or nothing:
// no extra layers), kept in kAovNames order without repeats.
std::vector<std::string> parseAovs(std::string_view text) {
    const std::string v = trimQuotes(text);
    std::vector<bool> asked(std::size(kAovNames), false);
    size_t start = 0;
    while (start <= v.size()) {
        size_t end = v.find_first_of(", ", start);
        if (end == std::string::npos) end = v.size();
        const std::string_view word = std::string_view(v).substr(start, end - start);
        start = end + 1;
        if (word.empty() || iequals(word, "none") || iequals(word, "off")) continue;
        size_t i = 0;
        while (i < std::size(kAovNames) && !iequals(word, kAovNames[i])) ++i;
        if (i == std::size(kAovNames))
            throw std::invalid_argument(fmt::format(
                "unknown layer '{}' (use depth, normal, object_id, albedo, motion)", word));
        asked[i] = true;
    }
    std::vector<std::string> out;
    for (size_t i = 0; i < asked.size(); ++i)
        if (asked[i]) out.emplace_back(kAovNames[i]);
    return out;
}

std::string joinedAovs(const RenderOptions& o) {
    std::string s;
    for (const std::string& a : o.outputAovs) s += (s.empty() ? "" : ",") + a;
    return s.empty() ? "none" : s;
}

// Output_File_Type letters of POV-Ray 3.7 and an optional bit depth: "N",
// "N16", "E".
void applyFileType(RenderOptions& o, std::string_view v) {
    if (v.empty()) return;
    const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(v[0])));
    if (std::string_view("NPTCEHJBS").find(c) == std::string_view::npos)
        throw std::invalid_argument(
            fmt::format("unknown output file type '{}' (use N P T C E H J B)", v));
    if (c == 'S')
        throw std::invalid_argument(
            "output file type 'S' (system format) is not available in POV-Ray 3.7 for Unix");
    o.outputType = c;
    if (v.size() > 1) {
        const int depth = toInt(v.substr(1));
        // POV-Ray accepts any depth here; 0 means the default and more
        // than 16 is written as 16.
        if (depth < 0) throw std::invalid_argument(fmt::format("bit depth {} is negative", depth));
        o.bitDepth = depth == 0 ? 8 : std::min(depth, 16);
        if (o.bitDepth != 8) mark(o, "Bits_Per_Color");
    }
}

// A stream file: a name, or a boolean (on: the stream's default name).
std::string streamFile(std::string_view value, std::string_view defaultName) {
    const std::string v = trimQuotes(value);
    const int b = boolWord(v);
    if (b == 1) return std::string(defaultName);
    if (b == 0) return {};
    return v;
}

constexpr std::string_view kStreamDefaultFile[kTextStreams] = {
    "debug.out", "fatal.out", "render.out", "stats.out", "warning.out", "alltext.out"};
constexpr std::string_view kStreamKeys[kTextStreams][2] = {
    {"Debug_Console", "Debug_File"},     {"Fatal_Console", "Fatal_File"},
    {"Render_Console", "Render_File"},   {"Statistic_Console", "Statistic_File"},
    {"Warning_Console", "Warning_File"}, {"All_Console", "All_File"},
};

template <TextStream S>
void applyStreamConsole(RenderOptions& o, const OptionInput& in) {
    constexpr int i = static_cast<int>(S);
    if (in.fromSwitch) {  // +GD[file] / -GD[file]
        o.streams[i].console = in.plus;
        if (!in.value.empty()) {
            o.streams[i].file = trimQuotes(in.value);
            mark(o, kStreamKeys[i][1]);
        }
        return;
    }
    o.streams[i].console = toBool(in);
}

template <TextStream S>
void applyStreamFile(RenderOptions& o, const OptionInput& in) {
    constexpr int i = static_cast<int>(S);
    o.streams[i].file = streamFile(in.value, kStreamDefaultFile[i]);
}

template <ShellHook H>
void applyCommand(RenderOptions& o, const OptionInput& in) {
    o.commands[static_cast<int>(H)].command = trimQuotes(in.value);
}

template <ShellHook H>
void applyReturn(RenderOptions& o, const OptionInput& in) {
    const std::string v = trimQuotes(in.value);
    // Empty (`Pre_Frame_Return=` in povray's own pngfli.ini): the default.
    if (v.empty()) {
        o.commands[static_cast<int>(H)].action.clear();
        return;
    }
    std::string_view letters(v);
    if (!letters.empty() && (letters[0] == '-' || letters[0] == '!')) letters.remove_prefix(1);
    if (letters.size() != 1 ||
        std::string_view("IiSsAaQqUuFf").find(letters[0]) == std::string_view::npos)
        throw std::invalid_argument(
            fmt::format("'{}' is not a return action (I ignore, S skip frame, A skip all, Q quit, "
                        "U user abort, F fatal; "
                        "a leading - or ! acts on a zero code)",
                        v));
    o.commands[static_cast<int>(H)].action = v;
}

// Create_Ini's formatting: On/Off, shortest floats, quoted file names.
std::string onOff(bool b) {
    return b ? "On" : "Off";
}
std::string num(double v) {
    return fmt::format("{}", v);
}
std::string quoted(const std::string& s) {
    return fmt::format("\"{}\"", s);
}
using Lines = std::vector<std::string>;

// Options frameray reads but that change nothing in its output: the value
// is checked as POV-Ray checks it and kept for Create_Ini.
void acceptBool(RenderOptions& o, const OptionInput& in) {
    o.acceptedValues[std::string(in.key)] = onOff(toBool(in));
}
void acceptInt(RenderOptions& o, const OptionInput& in) {
    o.acceptedValues[std::string(in.key)] = num(toInt(in.value));
}
// A one-letter setting (Palette, Video_Mode); povray keeps the first
// letter, in lower case.
void acceptLetter(RenderOptions& o, const OptionInput& in) {
    const std::string v = trimQuotes(in.value);
    if (v.empty()) throw std::invalid_argument("a letter is expected");
    o.acceptedValues[std::string(in.key)] =
        std::string(1, static_cast<char>(std::tolower(static_cast<unsigned char>(v[0]))));
}
// POV-Ray 3.6 options 3.7 dropped: read, not checked, not written back.
void acceptObsolete(RenderOptions&, const OptionInput&) {}
Lines writeNothing(const RenderOptions&) {
    return {};
}

#define FR_NO_EFFECT(text) [](const OptionInput&) -> const char* { return text; }
// An option without effect in frameray: KEY, SWITCH, TYPE, DEFAULT, HELP,
// APPLY (one of the accept* above), WHY (said once when it is set).
#define FR_ACCEPTED(KEY, SW, TYPE, DEF, HELP, APPLY, WHY) \
    { KEY, SW, OptionType::TYPE, DEF, HELP, APPLY, nullptr, nullptr, FR_NO_EFFECT(WHY) }
#define FR_OBSOLETE(KEY, SW, TYPE, HELP)                                                           \
    {                                                                                              \
        KEY, SW, OptionType::TYPE, "", HELP " (POV-Ray 3.6; no longer used).", acceptObsolete,     \
            writeNothing, nullptr,                                                                 \
            FR_NO_EFFECT("POV-Ray 3.7 no longer uses it either (it says it will become an error)") \
    }
constexpr const char* kPovrayIgnores = "POV-Ray 3.7 ignores it too";
constexpr const char* kNoPreview = "frameray renders without a preview window";

// Dither_Method's names in POV-Ray 3.7 (3.7.1's A2/A3 are not among them).
constexpr std::string_view kDitherMethods[] = {"FS", "B2", "B3", "B4"};

#define FR_WRITE(expr) [](const RenderOptions& o) -> Lines { return {expr}; }

template <TextStream S>
Lines writeStreamConsole(const RenderOptions& o) {
    return {onOff(o.streams[static_cast<int>(S)].console)};
}
template <TextStream S>
Lines writeStreamFile(const RenderOptions& o) {
    return {quoted(o.streams[static_cast<int>(S)].file)};
}
template <ShellHook H>
Lines writeCommand(const RenderOptions& o) {
    return {o.commands[static_cast<int>(H)].command};
}
template <ShellHook H>
Lines writeReturn(const RenderOptions& o) {
    return {o.commands[static_cast<int>(H)].action};
}

#define FR_STREAM(S, NAME, SW, WHAT)                                                      \
    {NAME "_Console",                                                                     \
     "G" SW,                                                                              \
     OptionType::Bool,                                                                    \
     "on",                                                                                \
     "Show the " WHAT " stream on the console (+G" SW "[file] also names its file, -G" SW \
     " hides it).",                                                                       \
     applyStreamConsole<S>,                                                               \
     writeStreamConsole<S>,                                                               \
     nullptr},                                                                            \
    {                                                                                     \
        NAME "_File", "", OptionType::Path, "",                                           \
            "Also write the " WHAT " stream to this file (on: the default name).",        \
            applyStreamFile<S>, writeStreamFile<S>, nullptr                               \
    }

#define FR_HOOK(H, NAME, WHEN)                                                    \
    {NAME "_Command",                                                             \
     "",                                                                          \
     OptionType::Command,                                                         \
     "",                                                                          \
     "Shell command run " WHEN                                                    \
     "; %o output file, %s scene name, %n frame, %k clock, %h height, "           \
     "%w width, %% a percent sign.",                                              \
     applyCommand<H>,                                                             \
     writeCommand<H>,                                                             \
     nullptr},                                                                    \
    {                                                                             \
        NAME "_Return", "", OptionType::Return, "",                               \
            "What a failing " NAME                                                \
            "_Command does: I ignore, S skip the frame, "                         \
            "A skip the rest, Q quit, U user abort, F fatal error; -X or !X act " \
            "on success instead.",                                                \
            applyReturn<H>, writeReturn<H>, nullptr                               \
    }

// In the order POV-Ray 3.7's Create_Ini writes options.
const OptionSpec kOptions[] = {
    FR_STREAM(TextStream::All, "All", "A", "all-text"),
    {"Allow_Shell_Commands", "", OptionType::Bool, "off",
     "Run the *_Command shell-outs; while off, a run that sets one stops with an error before "
     "anything is run "
     "(see Restrictions). Only from the command line, POVRAYOPT, povray.ini or frameray.conf, not "
     "from INI files "
     "named on the command line.",
     [](RenderOptions& o, const OptionInput& in) { o.allowShellCommands = toBool(in); },
     FR_WRITE(onOff(o.allowShellCommands)), nullptr},
    {"Antialias_Depth", "R", OptionType::Int, "3",
     "Maximum recursion depth of adaptive anti-aliasing (1..9).",
     [](RenderOptions& o, const OptionInput& in) {
         o.antialiasDepth = std::clamp(toInt(in.value), 1, 9);
     },
     FR_WRITE(num(o.antialiasDepth)), nullptr},
    {"Antialias", "A", OptionType::Bool, "off", "Anti-aliasing; +A0.3 also sets the threshold.",
     [](RenderOptions& o, const OptionInput& in) {
         if (in.fromSwitch) {
             o.antialias = in.plus;
             if (!in.value.empty()) {
                 o.antialiasThreshold = toNonNegative(in.value);
                 mark(o, "Antialias_Threshold");
             }
         } else {
             o.antialias = toBool(in);
         }
     },
     FR_WRITE(onOff(o.antialias)), nullptr},
    {"Antialias_Threshold", "", OptionType::Float, "0.3",
     "Colour difference that triggers super-sampling.",
     [](RenderOptions& o, const OptionInput& in) {
         o.antialiasThreshold = toNonNegative(in.value);
     },
     FR_WRITE(num(o.antialiasThreshold)), nullptr},
    {"Antialias_Gamma", "", OptionType::Float, "2.5",
     "Gamma in which anti-aliasing compares colours (0: linear light).",
     [](RenderOptions& o, const OptionInput& in) { o.antialiasGamma = toNonNegative(in.value); },
     FR_WRITE(num(o.antialiasGamma)), nullptr},
    {"Append_File", "GP", OptionType::Bool, "off",
     "Append to the text stream files (All_File, Debug_File, ...) instead of replacing them.",
     [](RenderOptions& o, const OptionInput& in) { o.appendFile = toBool(in); },
     FR_WRITE(onOff(o.appendFile)), nullptr},
    {"Bits_Per_Color", "", OptionType::Int, "8",
     "Bits per colour channel of the output file (also +FN16).",
     [](RenderOptions& o, const OptionInput& in) {
         o.bitDepth = std::clamp(toInt(in.value), 1, 16);
     },
     FR_WRITE(num(o.bitDepth)), nullptr},
    {"Bits_Per_Colour", "", OptionType::Int, "8", "Bits_Per_Color in British spelling.",
     [](RenderOptions& o, const OptionInput& in) {
         o.bitDepth = std::clamp(toInt(in.value), 1, 16);
         mark(o, "Bits_Per_Color");
     },
     writeNothing, nullptr},
    {"Bounding", "MB", OptionType::Bool, "on",
     "Automatic bounding; +MBn also sets the threshold (no effect on the image).",
     [](RenderOptions& o, const OptionInput& in) {
         if (in.fromSwitch) {
             o.bounding = in.plus;
             if (!in.value.empty()) {
                 o.boundingThreshold = std::max(toInt(in.value), 0);
                 mark(o, "Bounding_Threshold");
             }
         } else {
             o.bounding = toBool(in);
         }
     },
     FR_WRITE(onOff(o.bounding)), nullptr},
    FR_ACCEPTED("Bounding_Method", "BM", Int, "1",
                "Bounding scheme: 1 bounding volume hierarchy, 2 binary space partitioning (no "
                "effect on the image).",
                acceptInt, "frameray always bounds with Embree's hierarchy; the image is the same"),
    {"Bounding_Threshold", "", OptionType::Int, "3",
     "Fewest objects for automatic bounding (no effect on the image).",
     [](RenderOptions& o, const OptionInput& in) {
         o.boundingThreshold = std::max(toInt(in.value), 0);
     },
     FR_WRITE(num(o.boundingThreshold)), nullptr},
    FR_OBSOLETE("Buffer_Output", "", Bool, "Buffer the output file"),
    {"Buffer_Size", "B", OptionType::Int, "",
     "Output buffer in KiB (POV-Ray 3.6; no longer used). +B and -B without a number switch "
     "Bounding, as in povray.",
     [](RenderOptions& o, const OptionInput& in) {
         if (in.fromSwitch && in.value.empty()) {
             o.bounding = in.plus;
             mark(o, "Bounding");
         }
     },
     writeNothing, nullptr,
     [](const OptionInput& in) -> const char* {
         return in.fromSwitch && in.value.empty()
                    ? nullptr
                    : "POV-Ray 3.7 no longer uses it either (it says it will become an error)";
     }},
    {"Clock", "K", OptionType::Float, "0", "Clock value of a single (non-animated) frame.",
     [](RenderOptions& o, const OptionInput& in) {
         o.clock = toFloat(in.value);
         o.clockSet = true;
     },
     FR_WRITE(num(o.clock)), nullptr},
    FR_ACCEPTED("Clockless_Animation", "KLA", Bool, "off",
                "Clockless animation (no effect: POV-Ray 3.7 renders the same frames with it).",
                acceptBool, kPovrayIgnores),
    {"Contact_Sheet", "CS", OptionType::Bool, "off",
     "Beside an animation's frames, NAME.html (every frame as a thumbnail with its number, clock, "
     "render time and rays, failed frames marked, a play control; self-contained) and "
     "NAME-sheet.png (a grid of the thumbnails), rewritten as frames finish.",
     [](RenderOptions& o, const OptionInput& in) { o.contactSheet = toBool(in); },
     FR_WRITE(onOff(o.contactSheet)), nullptr},
    {"Continue_Trace", "C", OptionType::Bool, "off",
     "Resume a stopped animation: frames the journal records as finished and intact are kept, the "
     "rest rendered.",
     [](RenderOptions& o, const OptionInput& in) { o.continueTrace = toBool(in); },
     FR_WRITE(onOff(o.continueTrace)), nullptr},
    {"Create_Ini", "GI", OptionType::Path, "",
     "Write the effective options to this INI file (+GIname; a boolean value names a file called "
     "so, as povray does).",
     [](RenderOptions& o, const OptionInput& in) { o.createIni = trimQuotes(in.value); },
     FR_WRITE(quoted(o.createIni)), nullptr},
    FR_OBSOLETE("Create_Histogram", "", Bool, "Write a histogram of render times"),
    {"Cyclic_Animation", "KC", OptionType::Bool, "off",
     "The last frame leads back to the first: the clock stops one step short of Final_Clock.",
     [](RenderOptions& o, const OptionInput& in) { o.cyclicAnimation = toBool(in); },
     FR_WRITE(onOff(o.cyclicAnimation)), nullptr},
    FR_STREAM(TextStream::Debug, "Debug", "D", "#debug"),
    {"Declare", "", OptionType::Declare, "",
     "Declare=Name=Value: a float (six significant digits, as povray keeps it) or string "
     "identifier set before parsing.",
     [](RenderOptions& o, const OptionInput& in) {
         const std::string v = trimQuotes(in.value);
         const auto eq = v.find('=');
         if (eq == std::string::npos || eq == 0)
             throw std::invalid_argument(fmt::format("'{}' is not Name=Value", v));
         o.declares.emplace_back(v.substr(0, eq), trimQuotes(std::string_view(v).substr(eq + 1)));
     },
     [](const RenderOptions& o) {
         Lines lines;
         for (const auto& [name, value] : o.declares) lines.push_back(name + "=" + value);
         return lines;
     },
     nullptr},
    {"Display", "D", OptionType::Bool, "off",
     "Preview window (accepted; frameray renders in batch, without a window).",
     [](RenderOptions& o, const OptionInput& in) {
         // +D may carry POV-Ray's display type and palette letters (+D0G).
         o.display = in.fromSwitch ? in.plus : toBool(in);
     },
     FR_WRITE(onOff(o.display)), nullptr},
    {"Dither", "", OptionType::Bool, "off",
     "Dither the colours to the output file's levels (Dither_Method), as povray does.",
     [](RenderOptions& o, const OptionInput& in) { o.dither = toBool(in); },
     FR_WRITE(onOff(o.dither)), nullptr},
    {"Dither_Method", "", OptionType::String, "FS",
     "How Dither dithers: B2, B3, B4 Bayer patterns of that size, FS Floyd-Steinberg error "
     "diffusion in povray's own variant (all pixel for pixel as povray's).",
     [](RenderOptions& o, const OptionInput& in) {
         std::string v = trimQuotes(in.value);
         for (char& c : v) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
         if (std::find(std::begin(kDitherMethods), std::end(kDitherMethods), v) ==
             std::end(kDitherMethods))
             throw std::invalid_argument(fmt::format(
                 "'{}' is not a dither method of POV-Ray 3.7 (FS, B2, B3 or B4)", in.value));
         o.ditherMethod = v;
     },
     FR_WRITE(o.ditherMethod), nullptr},
    {"Display_Gamma", "", OptionType::Float, "2.2",
     "Gamma of the display (accepted; there is no display window).",
     [](RenderOptions& o, const OptionInput& in) {
         o.displayGamma = iequals(trimQuotes(in.value), "srgb") ? 2.2 : toFloat(in.value);
     },
     FR_WRITE(num(o.displayGamma)), nullptr},
    FR_ACCEPTED("Draw_Vistas", "UD", Bool, "off",
                "Draw the vista buffer's rectangles (no effect: POV-Ray 3.7 ignores it).",
                acceptBool, kPovrayIgnores),
    {"End_Column", "EC", OptionType::Window, "width",
     "Last column of the render window: a pixel number, or a fraction of the width up to 1.0.",
     [](RenderOptions& o, const OptionInput& in) { o.endColumn = toNonNegative(in.value); },
     FR_WRITE(num(o.endColumn)), nullptr},
    {"End_Row", "ER", OptionType::Window, "height",
     "Last row of the render window: a pixel number, or a fraction of the height up to 1.0.",
     [](RenderOptions& o, const OptionInput& in) { o.endRow = toNonNegative(in.value); },
     FR_WRITE(num(o.endRow)), nullptr},
    {"Exr_Compression", "", OptionType::String, "zip",
     "Compression of EXR frames (+FE): none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa, dwab.",
     [](RenderOptions& o, const OptionInput& in) {
         const std::string v = trimQuotes(in.value);
         for (const std::string_view name : kExrCompressions)
             if (iequals(v, name)) {
                 o.exrCompression = std::string(name);
                 return;
             }
         throw std::invalid_argument(fmt::format(
             "'{}' is not one of none, rle, zips, zip, piz, pxr24, b44, b44a, dwaa, dwab", v));
     },
     FR_WRITE(o.exrCompression), nullptr},
    FR_STREAM(TextStream::Fatal, "Fatal", "F", "fatal error"),
    FR_HOOK(ShellHook::FatalError, "Fatal_Error", "when a frame fails"),
    {"Field_Render", "UF", OptionType::Bool, "off",
     "Field rendering for interlaced video (accepted; POV-Ray 3.7 writes the same full frames with "
     "it on).",
     [](RenderOptions& o, const OptionInput& in) { o.fieldRender = toBool(in); },
     FR_WRITE(onOff(o.fieldRender)), nullptr},
    {"File_Restrictions", "", OptionType::Bool, "on",
     "Limit the files a scene reads (working, scene and library folders, Read_Path) and writes "
     "(working, scene and "
     "output folders, Write_Path); off lifts the limits (see Restrictions). Not from INI files "
     "named on the command "
     "line.",
     [](RenderOptions& o, const OptionInput& in) { o.fileRestrictions = toBool(in); },
     FR_WRITE(onOff(o.fileRestrictions)), nullptr},
    {"File_Gamma", "", OptionType::Float, "sRGB", "Gamma of the output file: a number or sRGB.",
     [](RenderOptions& o, const OptionInput& in) {
         o.fileGamma = iequals(trimQuotes(in.value), "srgb") ? 0 : toFloat(in.value);
     },
     FR_WRITE(o.fileGamma <= 0 ? std::string("sRGB") : num(o.fileGamma)), nullptr},
    {"Final_Clock", "KF", OptionType::Float, "1", "Clock value of the last frame.",
     [](RenderOptions& o, const OptionInput& in) { o.finalClock = toFloat(in.value); },
     FR_WRITE(num(o.finalClock)), nullptr},
    {"Final_Frame", "KFF", OptionType::Int, "1", "Last frame number of an animation.",
     [](RenderOptions& o, const OptionInput& in) {
         o.finalFrame = toInt(in.value);
         o.finalFrameSet = true;
     },
     FR_WRITE(num(o.finalFrame)), nullptr},
    {"Frame_Step", "STP", OptionType::Int, "1",
     "Render every n-th frame of the animation (or subset).",
     [](RenderOptions& o, const OptionInput& in) { o.frameStep = toInt(in.value); },
     FR_WRITE(num(o.frameStep)), nullptr},
    {"Frames_In_Flight", "WF", OptionType::Int, "threads + 1, at most 16",
     "Frames an animation keeps in flight at once: one is parsed (in frame order) while the others "
     "render. 1 "
     "renders frame after frame; the images are the same either way. Lowered to what fits in "
     "memory (the first "
     "frame, rendered alone, gives the estimate). With Pre_Frame_Command or Post_Frame_Command "
     "set, frames run one "
     "at a time.",
     [](RenderOptions& o, const OptionInput& in) { o.framesInFlight = toPositiveInt(in.value); },
     FR_WRITE(num(o.framesInFlight)), nullptr},
    {"Grayscale_Output", "", OptionType::Bool, "off",
     "Write one grey channel instead of red, green and blue (PNG and PPM only, as in povray).",
     [](RenderOptions& o, const OptionInput& in) { o.grayscaleOutput = toBool(in); },
     FR_WRITE(onOff(o.grayscaleOutput)),
     [](const RenderOptions& o) -> const char* {
         // povray: "Unsupported combination of options" for the others.
         return o.grayscaleOutput && o.outputType != 'N' && o.outputType != 'P'
                    ? "grey output to other files than PNG and PPM (povray refuses it too)"
                    : nullptr;
     }},
    {"Height", "H", OptionType::Int, "600", "Image height in pixels.",
     [](RenderOptions& o, const OptionInput& in) { o.height = toPositiveInt(in.value); },
     FR_WRITE(num(o.height)), nullptr},
    FR_ACCEPTED("High_Reproducibility", "HR", Bool, "off",
                "Trade speed for reproducible images (no effect: frameray's images are always "
                "the same for the same input).",
                acceptBool, "frameray's images are always reproducible"),
    FR_OBSOLETE("Histogram_Grid_Size", "HS", String, "Histogram grid size"),
    FR_OBSOLETE("Histogram_Name", "HN", Path, "Histogram file name"),
    FR_OBSOLETE("Histogram_Type", "HT", String, "Histogram file type"),
    {"Include_Header", "HI", OptionType::Path, "",
     "A file included before the scene's first line (searched as #include files are).",
     [](RenderOptions& o, const OptionInput& in) { o.includeHeader = trimQuotes(in.value); },
     FR_WRITE(quoted(o.includeHeader)), nullptr},
    {"Include_Ini", "", OptionType::IniFile, "",
     "Read another INI file (file.ini or file.ini[Section]) here, as if named on the command "
     "line.",
     [](RenderOptions&, const OptionInput&) {}, writeNothing, nullptr},
    {"Initial_Clock", "KI", OptionType::Float, "0", "Clock value of the first frame.",
     [](RenderOptions& o, const OptionInput& in) { o.initialClock = toFloat(in.value); },
     FR_WRITE(num(o.initialClock)), nullptr},
    {"Initial_Frame", "KFI", OptionType::Int, "1", "First frame number of an animation.",
     [](RenderOptions& o, const OptionInput& in) {
         o.initialFrame = toInt(in.value);
         o.initialFrameSet = true;
     },
     FR_WRITE(num(o.initialFrame)), nullptr},
    {"Input_File_Name", "I", OptionType::Path, "", "Scene file to render.",
     [](RenderOptions& o, const OptionInput& in) { o.inputFile = trimQuotes(in.value); },
     FR_WRITE(quoted(o.inputFile)), nullptr},
    {"Jitter_Amount", "", OptionType::Float, "1.0",
     "How far anti-aliasing samples are jittered, in pixels.",
     [](RenderOptions& o, const OptionInput& in) { o.jitterAmount = toNonNegative(in.value); },
     FR_WRITE(num(o.jitterAmount)), nullptr},
    {"Jitter", "J", OptionType::Bool, "on",
     "Jitter anti-aliasing samples; +J0.5 also sets the amount.",
     [](RenderOptions& o, const OptionInput& in) {
         if (in.fromSwitch) {
             o.jitter = in.plus;
             if (!in.value.empty()) {
                 o.jitterAmount = toNonNegative(in.value);
                 mark(o, "Jitter_Amount");
             }
         } else {
             o.jitter = toBool(in);
         }
     },
     FR_WRITE(onOff(o.jitter)), nullptr},
    {"Library_Path", "L", OptionType::PathList, "/usr/share/povray-3.7/include",
     "Folder searched for include files, fonts, images and INI files; accumulates.",
     [](RenderOptions& o, const OptionInput& in) {
         o.libraryPaths.emplace_back(trimQuotes(in.value));
     },
     [](const RenderOptions& o) {
         Lines lines;
         for (const auto& p : o.libraryPaths) lines.push_back(quoted(p.string()));
         return lines;
     },
     nullptr},
    FR_ACCEPTED("Light_Buffer", "UL", Bool, "on",
                "POV-Ray 3.6's light buffer speed-up (no effect: POV-Ray 3.7 ignores it).",
                acceptBool, kPovrayIgnores),
    {"Log_Format", "", OptionType::String, "text",
     "Line format of the run log NAME.frameray.log beside an animation's frames: text, or json "
     "(one JSON object per event, for farm monitors; schema in the README).",
     [](RenderOptions& o, const OptionInput& in) {
         o.logFormat =
             choice<LogFormat>(in.value, {{"text", LogFormat::Text}, {"json", LogFormat::Json}});
     },
     FR_WRITE(std::string(o.logFormat == LogFormat::Json ? "json" : "text")), nullptr},
    {"Log_Level", "", OptionType::String, "info",
     "Least severe event the run log keeps: debug (adds per-frame parse and render events, also "
     "shown on the console), info, warn, error, or off (no run log).",
     [](RenderOptions& o, const OptionInput& in) {
         o.logLevel = choice<LogLevel>(in.value, {{"debug", LogLevel::Debug},
                                                  {"info", LogLevel::Info},
                                                  {"warn", LogLevel::Warn},
                                                  {"error", LogLevel::Error},
                                                  {"off", LogLevel::Off}});
     },
     FR_WRITE(std::string(kLogLevelNames[static_cast<int>(o.logLevel)])), nullptr},
    FR_ACCEPTED("Max_Image_Buffer_Memory", "MI", Int, "128",
                "Megabytes of image kept in memory before povray swaps it to disk (no effect).",
                acceptInt, "frameray keeps each frame's image in memory"),
    {"Max_Parse_Iterations", "", OptionType::Int, "100000000",
     "Loop iterations (#while, #for) and macro calls one frame's parse may run before it stops "
     "with an error "
     "(a loop that never ends); 0: no limit.",
     [](RenderOptions& o, const OptionInput& in) {
         const double v = std::trunc(toNonNegative(in.value));
         if (v > 9e18) throw std::invalid_argument(fmt::format("'{}' is out of range", in.value));
         o.maxParseIterations = static_cast<long long>(v);
     },
     FR_WRITE(num(static_cast<double>(o.maxParseIterations))), nullptr},
    {"Odd_Field", "UO", OptionType::Bool, "off",
     "Start field rendering on the odd field (accepted, as Field_Render).",
     [](RenderOptions& o, const OptionInput& in) { o.oddField = toBool(in); },
     FR_WRITE(onOff(o.oddField)), nullptr},
    {"Output_AOVs", "AOV", OptionType::String, "none",
     "Extra layers in each EXR frame (+FE only), from the camera ray through each pixel's centre: "
     "any of depth (Z), normal (N.x N.y N.z), object_id (objectId), albedo (albedo.R G B), "
     "comma-separated. motion is not built yet.",
     [](RenderOptions& o, const OptionInput& in) { o.outputAovs = parseAovs(in.value); },
     FR_WRITE(joinedAovs(o)),
     [](const RenderOptions& o) -> const char* {
         for (const std::string& a : o.outputAovs)
             if (a == "motion") return "Output_AOVs=motion (motion vectors)";
         return nullptr;
     }},
    {"Output_Alpha", "UA", OptionType::Bool, "off", "Write an alpha channel (transparency mask).",
     [](RenderOptions& o, const OptionInput& in) { o.outputAlpha = toBool(in); },
     FR_WRITE(onOff(o.outputAlpha)),
     [](const RenderOptions& o) -> const char* {
         // PNG and TGA carry the alpha channel; ppm, jpeg, bmp and hdr
         // cannot and ignore it, as in povray.
         return o.outputAlpha && o.outputType == 'E' ? "alpha channel output (+UA) to EXR"
                                                     : nullptr;
     }},
    {"Output_File_Name", "O", OptionType::Path, "scene name",
     "Output image file, or a folder (ending in /) to put it in. Frame numbers are appended in "
     "animations; the "
     "file type's extension is added unless the name ends with it. - (+O-): standard output, the "
     "frames one after another (messages go to standard error).",
     [](RenderOptions& o, const OptionInput& in) { o.outputFile = trimQuotes(in.value); },
     FR_WRITE(quoted(o.outputFile)), nullptr},
    {"Output_File_Type", "F", OptionType::FileType, "N",
     "File type: N png, P ppm, T tga, C compressed tga, E exr, H hdr, J jpeg, B bmp; optional bit "
     "depth (+FN16). "
     "As a switch, +F[type] also turns file output on and -F off.",
     [](RenderOptions& o, const OptionInput& in) {
         if (in.fromSwitch) {
             o.outputToFile = in.plus;
             mark(o, "Output_To_File");
         }
         applyFileType(o, trimQuotes(in.value));
     },
     FR_WRITE(std::string(1, o.outputType)), nullptr},
    {"Output_To_File", "", OptionType::Bool, "on", "Write the image to a file.",
     [](RenderOptions& o, const OptionInput& in) { o.outputToFile = toBool(in); },
     FR_WRITE(onOff(o.outputToFile)), nullptr},
    FR_ACCEPTED("Palette", "", String, "",
                "Palette of the preview window (no effect: there is no preview window).",
                acceptLetter, kNoPreview),
    {"Pause_When_Done", "P", OptionType::Bool, "off",
     "Wait for a key at the end (accepted; no effect in batch).",
     [](RenderOptions& o, const OptionInput& in) { o.pauseWhenDone = toBool(in); },
     FR_WRITE(onOff(o.pauseWhenDone)), nullptr},
    FR_HOOK(ShellHook::PostFrame, "Post_Frame", "after each frame"),
    FR_HOOK(ShellHook::PostScene, "Post_Scene", "after the last frame"),
    FR_HOOK(ShellHook::PreFrame, "Pre_Frame", "before each frame"),
    FR_HOOK(ShellHook::PreScene, "Pre_Scene", "before the first frame"),
    FR_ACCEPTED("Preview_End_Size", "EP", Int, "1",
                "Block size of the last mosaic preview pass (no effect: there is no preview).",
                acceptInt, kNoPreview),
    {"Preview_Fps", "", OptionType::Float, "24",
     "Frames per second of the preview video (Preview_Video).",
     [](RenderOptions& o, const OptionInput& in) {
         const double v = toFloat(in.value);
         if (!(v > 0) || v > 1000)
             throw std::invalid_argument(fmt::format("'{}' is not between 0 and 1000", in.value));
         o.previewFps = v;
     },
     FR_WRITE(num(o.previewFps)), nullptr},
    FR_ACCEPTED("Preview_Start_Size", "SP", Int, "1",
                "Block size of the first mosaic preview pass (no effect: there is no preview).",
                acceptInt, kNoPreview),
    {"Preview_Video", "PV", OptionType::String, "off",
     "Once every frame of an animation exists: NAME.mp4 (H.264) or NAME.webm (VP9) beside the "
     "frames, one video frame per image at Preview_Fps, made by the ffmpeg program; off: none.",
     [](RenderOptions& o, const OptionInput& in) {
         if (in.fromSwitch && !in.plus) return o.previewVideo.clear();
         o.previewVideo = choice<std::string>(
             in.value, {{"off", ""}, {"none", ""}, {"mp4", "mp4"}, {"webm", "webm"}});
     },
     FR_WRITE(o.previewVideo.empty() ? std::string("off") : o.previewVideo), nullptr},
    {"Quality", "Q", OptionType::Int, "9", "Render quality 0..11.",
     [](RenderOptions& o, const OptionInput& in) {
         o.quality = std::clamp(toInt(in.value), 0, 11);
     },
     FR_WRITE(num(o.quality))},
    {"Radiosity_File_Name", "RF", OptionType::Path, "object.rca",
     "Radiosity cache file for Radiosity_From_File / Radiosity_To_File (frameray's own format).",
     [](RenderOptions& o, const OptionInput& in) { o.radiosityFile = trimQuotes(in.value); },
     FR_WRITE(quoted(o.radiosityFile)), nullptr},
    {"Radiosity_From_File", "RFI", OptionType::Bool, "off",
     "Start every frame's radiosity from the samples in the cache file (the pretrace still runs "
     "and adds samples where the file has too few).",
     [](RenderOptions& o, const OptionInput& in) { o.radiosityFromFile = toBool(in); },
     FR_WRITE(onOff(o.radiosityFromFile)), nullptr},
    {"Radiosity_Stable", "", OptionType::Bool, "off",
     "frameray: in an animation, every frame after the first starts its radiosity from the first "
     "frame's samples, so a static scene under a moving camera does not flicker (for scenes whose "
     "objects and lights do not move).",
     [](RenderOptions& o, const OptionInput& in) { o.radiosityStable = toBool(in); },
     FR_WRITE(onOff(o.radiosityStable)), nullptr},
    {"Radiosity_To_File", "RFO", OptionType::Bool, "off",
     "Save each frame's radiosity samples to the cache file (the last frame's stay).",
     [](RenderOptions& o, const OptionInput& in) { o.radiosityToFile = toBool(in); },
     FR_WRITE(onOff(o.radiosityToFile)), nullptr},
    FR_ACCEPTED("Radiosity_Vain_Pretrace", "RVP", Bool, "on",
                "Show the radiosity pretrace in the preview (no effect on the image).", acceptBool,
                kNoPreview),
    {"Read_Path", "", OptionType::PathList, "",
     "Another folder (with its subfolders) scenes may read from; accumulates. Not from INI files "
     "named on the "
     "command line.",
     [](RenderOptions& o, const OptionInput& in) {
         o.readPaths.emplace_back(trimQuotes(in.value));
     },
     [](const RenderOptions& o) {
         Lines lines;
         for (const auto& p : o.readPaths) lines.push_back(quoted(p.string()));
         return lines;
     },
     nullptr},
    {"Real_Time_Raytracing", "RTR", OptionType::Bool, "off",
     "POV-Ray 3.7's beta render loop into the preview window: without a display (as always in "
     "frameray) every frame renders once and no image is written, as povray does.",
     [](RenderOptions& o, const OptionInput& in) { o.realTimeRaytracing = toBool(in); },
     FR_WRITE(onOff(o.realTimeRaytracing)), nullptr},
    FR_ACCEPTED("Remove_Bounds", "UR", Bool, "on",
                "Remove bounded_by from scenes that do not need it (no effect: POV-Ray 3.7 "
                "ignores it).",
                acceptBool, kPovrayIgnores),
    FR_STREAM(TextStream::Render, "Render", "R", "render progress"),
    {"Render_Block_Size", "BS", OptionType::Int, "32",
     "Side of the square pixel blocks rendered at once; anti-aliasing depends on it as in povray "
     "(4..).",
     [](RenderOptions& o, const OptionInput& in) {
         o.renderBlockSize = std::max(toInt(in.value), 4);
     },
     FR_WRITE(num(o.renderBlockSize)), nullptr},
    FR_ACCEPTED("Render_Block_Step", "RS", Int, "1",
                "Step through the blocks of Render_Pattern by this many (only the order of "
                "rendering changes, not the image).",
                acceptInt, "it changes only the order blocks are rendered in"),
    FR_ACCEPTED("Render_Pattern", "RP", Int, "0",
                "Order in which blocks are rendered, 0..5 (only the order changes, not the image).",
                acceptInt, "it changes only the order blocks are rendered in"),
    {"Sampling_Method", "AM", OptionType::Int, "1",
     "Anti-aliasing method: 1 non-recursive, 2 adaptive.",
     [](RenderOptions& o, const OptionInput& in) {
         o.samplingMethod = std::clamp(toInt(in.value), 1, 2);
     },
     FR_WRITE(num(o.samplingMethod)), nullptr},
    {"Start_Column", "SC", OptionType::Window, "1",
     "First column of the render window: a pixel number, or a fraction of the width below 1.0. "
     "Pixels outside "
     "the window are written black (alpha 0).",
     [](RenderOptions& o, const OptionInput& in) { o.startColumn = toNonNegative(in.value); },
     FR_WRITE(num(o.startColumn)), nullptr},
    {"Shard_Count", "SHC", OptionType::Int, "1",
     "Split the frames among this many processes (Slurm array tasks, Kubernetes Job indexes): each "
     "renders every "
     "Shard_Count-th frame of the (subset, stepped) sequence, starting at Shard_Index, into the "
     "same folder, with "
     "its own journal (+C resumes it). Refused for scenes whose frames pass state through files "
     "(#fopen write).",
     [](RenderOptions& o, const OptionInput& in) { o.shardCount = toPositiveInt(in.value); },
     FR_WRITE(num(o.shardCount)), nullptr},
    {"Shard_Index", "SHI", OptionType::Int, "0",
     "Which shard this process renders: 0 to Shard_Count - 1.",
     [](RenderOptions& o, const OptionInput& in) {
         o.shardIndex = toInt(in.value);
         if (o.shardIndex < 0)
             throw std::invalid_argument(fmt::format("'{}' must not be negative", in.value));
     },
     FR_WRITE(num(o.shardIndex)), nullptr},
    FR_ACCEPTED("Split_Unions", "SU", Bool, "off",
                "Split bounded unions for automatic bounding (no effect: POV-Ray 3.7 ignores it).",
                acceptBool, kPovrayIgnores),
    {"Start_Row", "SR", OptionType::Window, "1",
     "First row of the render window: a pixel number, or a fraction of the height below 1.0.",
     [](RenderOptions& o, const OptionInput& in) { o.startRow = toNonNegative(in.value); },
     FR_WRITE(num(o.startRow)), nullptr},
    FR_STREAM(TextStream::Statistic, "Statistic", "S", "statistics"),
    {"Subset_End_Frame", "EF", OptionType::Float, "final frame",
     "Render only frames up to this one; a value below 1.0 is a fraction of the frame count.",
     [](RenderOptions& o, const OptionInput& in) {
         o.subsetEndFrame = toFloat(in.value);
         o.subsetEndSet = true;
     },
     FR_WRITE(num(o.subsetEndFrame)), nullptr},
    {"Subset_Start_Frame", "SF", OptionType::Float, "initial frame",
     "Render only frames from this one; a value below 1.0 is a fraction of the frame count.",
     [](RenderOptions& o, const OptionInput& in) {
         o.subsetStartFrame = toFloat(in.value);
         o.subsetStartSet = true;
     },
     FR_WRITE(num(o.subsetStartFrame)), nullptr},
    {"Test_Abort_Count", "", OptionType::Int, "1",
     "Pixels between checks for a user abort (accepted).",
     [](RenderOptions& o, const OptionInput& in) {
         o.testAbortCount = std::max(toInt(in.value), 1);
     },
     FR_WRITE(num(o.testAbortCount)), nullptr},
    {"Test_Abort", "X", OptionType::Bool, "off",
     "Check for a user abort while rendering; +X100 also sets the count (accepted: frameray always "
     "stops on "
     "Ctrl-C within 2 s).",
     [](RenderOptions& o, const OptionInput& in) {
         if (in.fromSwitch) {
             o.testAbort = in.plus;
             if (!in.value.empty()) {
                 o.testAbortCount = std::max(toInt(in.value), 1);
                 mark(o, "Test_Abort_Count");
             }
         } else {
             o.testAbort = toBool(in);
         }
     },
     FR_WRITE(onOff(o.testAbort)), nullptr},
    FR_HOOK(ShellHook::UserAbort, "User_Abort", "when the run is interrupted (Ctrl-C)"),
    {"Verbose", "V", OptionType::Bool, "on", "Progress and statistics messages.",
     [](RenderOptions& o, const OptionInput& in) { o.verbose = toBool(in); },
     FR_WRITE(onOff(o.verbose)), nullptr},
    {"Version", "MV", OptionType::Float, "3.7", "Language version assumed before any #version.",
     [](RenderOptions& o, const OptionInput& in) {
         o.version = toFloat(in.value);
         o.versionGiven = true;
     },
     FR_WRITE(num(o.version)), nullptr},
    FR_ACCEPTED("Video_Mode", "", String, "",
                "Display hardware mode (no effect: there is no preview window).", acceptLetter,
                kNoPreview),
    FR_ACCEPTED("Vista_Buffer", "UV", Bool, "on",
                "POV-Ray 3.6's vista buffer speed-up (no effect: POV-Ray 3.7 ignores it).",
                acceptBool, kPovrayIgnores),
    FR_STREAM(TextStream::Warning, "Warning", "W", "warning"),
    FR_ACCEPTED("Warning_Level", "WL", Int, "10",
                "Which warnings to show (no effect: POV-Ray 3.7 shows the same warnings at every "
                "level).",
                acceptInt, kPovrayIgnores),
    {"Width", "W", OptionType::Int, "800", "Image width in pixels.",
     [](RenderOptions& o, const OptionInput& in) { o.width = toPositiveInt(in.value); },
     FR_WRITE(num(o.width)), nullptr},
    {"Work_Threads", "WT", OptionType::Int, "cores", "Render threads (default: every core).",
     [](RenderOptions& o, const OptionInput& in) { o.workThreads = toPositiveInt(in.value); },
     FR_WRITE(num(o.workThreads)), nullptr},
    {"Write_Path", "", OptionType::PathList, "",
     "Another folder (with its subfolders) scenes may write to (#fopen write/append); accumulates. "
     "Not from INI "
     "files named on the command line.",
     [](RenderOptions& o, const OptionInput& in) {
         o.writePaths.emplace_back(trimQuotes(in.value));
     },
     [](const RenderOptions& o) {
         Lines lines;
         for (const auto& p : o.writePaths) lines.push_back(quoted(p.string()));
         return lines;
     },
     nullptr},
};

#undef FR_WRITE
#undef FR_STREAM
#undef FR_HOOK
#undef FR_NO_EFFECT
#undef FR_ACCEPTED
#undef FR_OBSOLETE

}  // namespace

std::span<const OptionSpec> optionTable() {
    return kOptions;
}

const OptionSpec* findSwitch(std::string_view body, std::string_view& valueOut) {
    const OptionSpec* best = nullptr;
    for (const OptionSpec& o : kOptions) {
        if (o.switchName.empty() || o.switchName.size() > body.size()) continue;
        if (!iequals(body.substr(0, o.switchName.size()), o.switchName)) continue;
        if (!best || o.switchName.size() > best->switchName.size()) best = &o;
    }
    if (best) valueOut = body.substr(best->switchName.size());
    return best;
}

const OptionSpec* findIniKey(std::string_view key) {
    for (const OptionSpec& o : kOptions)
        if (iequals(o.iniKey, key)) return &o;
    return nullptr;
}

std::string helpText() {
    std::string out =
        "usage: frameray [options] [scene.pov] [file.ini[Section]] ...\n"
        "Options are INI keys (Key=Value, in INI files or on the command line) or switches "
        "(+X/-X).\n"
        "--list-frames prints the frames the options ask for (number, clock, file) without "
        "rendering.\n"
        "--merge-stats DIR writes DIR/sequence.json for a sequence rendered in shards, from "
        "their sequence.shard-I-of-N.json files.\n"
        "--version prints frameray's version and those of its libraries.\n"
        "Read in order: povray.ini ($POVINI, ./povray.ini, ~/.povray/3.7/povray.ini, "
        "/etc/povray/3.7/povray.ini: "
        "the first found), then the arguments.\n\n";
    for (const OptionSpec& o : kOptions) {
        const std::string sw =
            o.switchName.empty() ? std::string() : fmt::format("+{}", o.switchName);
        out += fmt::format("  {:<22} {:<9} {}", o.iniKey, sw, o.help);
        if (!o.defaultText.empty()) out += fmt::format(" [default: {}]", o.defaultText);
        out += '\n';
    }
    return out;
}

std::string optionsMarkdown() {
    std::string out = "| INI key | switch | default | meaning |\n|---|---|---|---|\n";
    for (const OptionSpec& o : kOptions) {
        const std::string sw =
            o.switchName.empty() ? std::string() : fmt::format("`+{}`", o.switchName);
        out += fmt::format("| `{}` | {} | {} | {} |\n", o.iniKey, sw, o.defaultText, o.help);
    }
    return out;
}

std::vector<std::string> optionValues(const OptionSpec& spec, const RenderOptions& options) {
    if (spec.write) return spec.write(options);
    const auto it = options.acceptedValues.find(spec.iniKey);
    if (it == options.acceptedValues.end()) return {};
    return {it->second};
}

std::string createIniText(const RenderOptions& options) {
    std::string out;
    for (const OptionSpec& o : kOptions) {
        if (!options.explicitlySet.count(std::string(o.iniKey))) continue;
        for (const std::string& value : optionValues(o, options))
            out += fmt::format("{}={}\n", o.iniKey, value);
    }
    return out;
}

std::string firstUnsupported(const RenderOptions& options) {
    for (const OptionSpec& o : kOptions) {
        if (!o.unsupported) continue;
        if (const char* what = o.unsupported(options))
            return fmt::format("{} ({})", o.iniKey, what);
    }
    return {};
}

}  // namespace frameray::options
