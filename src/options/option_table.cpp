#include "options/option_table.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <stdexcept>

namespace frameray::options {

namespace {

bool iequals(std::string_view a, std::string_view b) {
    return a.size() == b.size() &&
           std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

std::string trimQuotes(std::string_view v) {
    if (v.size() >= 2 && ((v.front() == '"' && v.back() == '"') || (v.front() == '\'' && v.back() == '\'')))
        v = v.substr(1, v.size() - 2);
    return std::string(v);
}

bool toBool(const OptionInput& in) {
    if (in.fromSwitch && in.value.empty()) return in.plus;
    static constexpr std::pair<std::string_view, bool> kWords[] = {
        {"on", true}, {"true", true}, {"yes", true}, {"1", true},
        {"off", false}, {"false", false}, {"no", false}, {"0", false},
    };
    for (const auto& [word, value] : kWords)
        if (iequals(in.value, word)) return in.fromSwitch ? (in.plus && value) : value;
    throw std::invalid_argument(fmt::format("'{}' is not a boolean (use on/off, true/false, yes/no, 1/0)", in.value));
}

double toFloat(std::string_view text) {
    const std::string s(text);
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0') throw std::invalid_argument(fmt::format("'{}' is not a number", text));
    return v;
}

int toInt(std::string_view text) {
    const double v = toFloat(text);
    if (v != static_cast<int>(v)) throw std::invalid_argument(fmt::format("'{}' is not a whole number", text));
    return static_cast<int>(v);
}

int toPositiveInt(std::string_view text) {
    const int v = toInt(text);
    if (v < 1) throw std::invalid_argument(fmt::format("'{}' must be at least 1", text));
    return v;
}

// Output_File_Type letters of POV-Ray 3.7 and an optional bit depth: "N",
// "N16", "E".
void applyFileType(RenderOptions& o, std::string_view v) {
    if (v.empty()) return;
    const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(v[0])));
    if (std::string_view("NPTCEHJBS").find(c) == std::string_view::npos)
        throw std::invalid_argument(fmt::format("unknown output file type '{}' (use N P T C E H J B)", v));
    if (c == 'S') throw std::invalid_argument("output file type 'S' (system format) is not available");
    o.outputType = c;
    if (v.size() > 1) {
        const int depth = toInt(v.substr(1));
        if (depth < 5 || depth > 16) throw std::invalid_argument(fmt::format("bit depth {} is out of range 5..16", depth));
        o.bitDepth = depth;
    }
}

constexpr OptionSpec kOptions[] = {
    {"Input_File_Name", "I", OptionType::Path, "", "Scene file to render.",
     [](RenderOptions& o, const OptionInput& in) { o.inputFile = trimQuotes(in.value); }},
    {"Output_File_Name", "O", OptionType::Path, "scene name",
     "Output image file, or a folder (ending in /) to put it in. Frame numbers are appended in animations.",
     [](RenderOptions& o, const OptionInput& in) { o.outputFile = trimQuotes(in.value); }},
    {"Output_To_File", "", OptionType::Bool, "on", "Write the image to a file.",
     [](RenderOptions& o, const OptionInput& in) { o.outputToFile = toBool(in); }},
    {"Output_File_Type", "F", OptionType::FileType, "N",
     "File type: N png, P ppm, T tga, C compressed tga, E exr, H hdr, J jpeg, B bmp; optional bit depth (+FN16). "
     "As a switch, +F[type] also turns file output on and -F off.",
     [](RenderOptions& o, const OptionInput& in) {
         if (in.fromSwitch) o.outputToFile = in.plus;
         applyFileType(o, trimQuotes(in.value));
     }},
    {"Width", "W", OptionType::Int, "800", "Image width in pixels.",
     [](RenderOptions& o, const OptionInput& in) { o.width = toPositiveInt(in.value); }},
    {"Height", "H", OptionType::Int, "600", "Image height in pixels.",
     [](RenderOptions& o, const OptionInput& in) { o.height = toPositiveInt(in.value); }},
    {"Antialias", "A", OptionType::Bool, "off", "Anti-aliasing; +A0.3 also sets the threshold.",
     [](RenderOptions& o, const OptionInput& in) {
         if (in.fromSwitch) {
             o.antialias = in.plus;
             if (!in.value.empty()) o.antialiasThreshold = toFloat(in.value);
         } else {
             o.antialias = toBool(in);
         }
     }},
    {"Antialias_Threshold", "", OptionType::Float, "0.3", "Colour difference that triggers super-sampling.",
     [](RenderOptions& o, const OptionInput& in) { o.antialiasThreshold = toFloat(in.value); }},
    {"Quality", "Q", OptionType::Int, "9", "Render quality 0..11.",
     [](RenderOptions& o, const OptionInput& in) { o.quality = std::clamp(toInt(in.value), 0, 11); }},
    {"Clock", "K", OptionType::Float, "0", "Clock value for a single frame.",
     [](RenderOptions& o, const OptionInput& in) { o.clock = toFloat(in.value); o.clockSet = true; }},
    {"Initial_Frame", "KFI", OptionType::Int, "1", "First frame number of an animation.",
     [](RenderOptions& o, const OptionInput& in) { o.initialFrame = toInt(in.value); }},
    {"Final_Frame", "KFF", OptionType::Int, "1", "Last frame number of an animation.",
     [](RenderOptions& o, const OptionInput& in) { o.finalFrame = toInt(in.value); }},
    {"Initial_Clock", "KI", OptionType::Float, "0", "Clock value of the first frame.",
     [](RenderOptions& o, const OptionInput& in) { o.initialClock = toFloat(in.value); }},
    {"Final_Clock", "KF", OptionType::Float, "1", "Clock value of the last frame.",
     [](RenderOptions& o, const OptionInput& in) { o.finalClock = toFloat(in.value); }},
    {"Cyclic_Animation", "KC", OptionType::Bool, "off", "The last frame leads back to the first: clock stops one step short.",
     [](RenderOptions& o, const OptionInput& in) { o.cyclicAnimation = toBool(in); }},
    {"Subset_Start_Frame", "SF", OptionType::Int, "initial frame", "Render only frames from this one.",
     [](RenderOptions& o, const OptionInput& in) { o.subsetStartFrame = toInt(in.value); }},
    {"Subset_End_Frame", "EF", OptionType::Int, "final frame", "Render only frames up to this one.",
     [](RenderOptions& o, const OptionInput& in) { o.subsetEndFrame = toInt(in.value); }},
    {"Version", "MV", OptionType::Float, "3.7", "Language version assumed before any #version.",
     [](RenderOptions& o, const OptionInput& in) { o.version = toFloat(in.value); }},
    {"Library_Path", "L", OptionType::PathList, "/usr/share/povray-3.7/include",
     "Folder searched for include files, fonts and images; accumulates.",
     [](RenderOptions& o, const OptionInput& in) { o.libraryPaths.emplace_back(trimQuotes(in.value)); }},
    {"Declare", "", OptionType::Declare, "", "Declare=Name=Value: a float or string identifier set before parsing.",
     [](RenderOptions& o, const OptionInput& in) {
         const std::string v = trimQuotes(in.value);
         const auto eq = v.find('=');
         if (eq == std::string::npos || eq == 0) throw std::invalid_argument(fmt::format("'{}' is not Name=Value", v));
         o.declares.emplace_back(v.substr(0, eq), trimQuotes(std::string_view(v).substr(eq + 1)));
     }},
    {"File_Gamma", "", OptionType::Float, "sRGB", "Gamma of the output file: a number or sRGB.",
     [](RenderOptions& o, const OptionInput& in) {
         o.fileGamma = iequals(trimQuotes(in.value), "srgb") ? 0 : toFloat(in.value);
     }},
    {"Display_Gamma", "", OptionType::Float, "2.2", "Gamma of the display (accepted; there is no display window).",
     [](RenderOptions& o, const OptionInput& in) {
         o.displayGamma = iequals(trimQuotes(in.value), "srgb") ? 2.2 : toFloat(in.value);
     }},
    {"Work_Threads", "WT", OptionType::Int, "cores", "Render threads (default: every core).",
     [](RenderOptions& o, const OptionInput& in) { o.workThreads = toPositiveInt(in.value); }},
    {"Verbose", "V", OptionType::Bool, "on", "Progress and statistics messages.",
     [](RenderOptions& o, const OptionInput& in) { o.verbose = toBool(in); }},
    {"Display", "D", OptionType::Bool, "off", "Preview window (accepted; frameray renders in batch, without a window).",
     [](RenderOptions& o, const OptionInput& in) { o.display = toBool(in); }},
    {"Pause_When_Done", "P", OptionType::Bool, "off", "Wait for a key at the end (accepted; no effect in batch).",
     [](RenderOptions& o, const OptionInput& in) { o.pauseWhenDone = toBool(in); }},
};

}  // namespace

std::span<const OptionSpec> optionTable() { return kOptions; }

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
        "Options are INI keys (Key=Value, in INI files) or switches (+X/-X on the command line or in INI files).\n\n";
    for (const OptionSpec& o : kOptions) {
        const std::string sw = o.switchName.empty() ? std::string() : fmt::format("+{}", o.switchName);
        out += fmt::format("  {:<22} {:<9} {}", o.iniKey, sw, o.help);
        if (!o.defaultText.empty()) out += fmt::format(" [default: {}]", o.defaultText);
        out += '\n';
    }
    return out;
}

std::string optionsMarkdown() {
    std::string out = "| INI key | switch | default | meaning |\n|---|---|---|---|\n";
    for (const OptionSpec& o : kOptions) {
        const std::string sw = o.switchName.empty() ? std::string() : fmt::format("`+{}`", o.switchName);
        out += fmt::format("| `{}` | {} | {} | {} |\n", o.iniKey, sw, o.defaultText, o.help);
    }
    return out;
}

}  // namespace frameray::options
