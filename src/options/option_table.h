// Every option frameray understands, defined once: its INI key, its
// command-line switch, its type, default and help text, how it sets
// RenderOptions, how Create_Ini writes it back, and when its value needs a
// feature frameray does not have yet. The parser, `--help`, the README's
// option list, Create_Ini and the "not supported yet" check are all
// driven by this table.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "options/render_options.h"

namespace frameray::options {

enum class OptionType {
    Bool,
    Int,
    Float,
    String,
    Path,
    PathList,
    Declare,
    FileType,
    Command,
    Return,
    Window,
    IniFile  // Include_Ini: reads another INI file there and then
};

// How a value reached the option: from an INI key (`Key=value`) or a
// switch (`+Xvalue` / `-Xvalue`), where the sign matters for booleans.
struct OptionInput {
    std::string_view value;
    bool fromSwitch = false;
    bool plus = true;
    std::string_view key;  // the table's INI key of the option being set
};

struct OptionSpec {
    std::string_view iniKey;      // e.g. "Width"
    std::string_view switchName;  // e.g. "W" (used as +W / -W); empty if none
    OptionType type;
    std::string_view defaultText;
    std::string_view help;
    // Sets the option; throws std::invalid_argument with a reason when the
    // value is malformed.
    void (*apply)(RenderOptions&, const OptionInput&);
    // The INI values Create_Ini writes for this key (several lines for
    // accumulating options), already formatted as POV-Ray writes them.
    // Null: the value kept in RenderOptions::acceptedValues (options
    // frameray reads but that change nothing in its output).
    std::vector<std::string> (*write)(const RenderOptions&);
    // Non-null when the current value would change the output in a way
    // frameray cannot render yet: a short description of the missing
    // feature. Null function: always supported.
    const char* (*unsupported)(const RenderOptions&) = nullptr;
    // Non-null for options read but without effect in frameray (old
    // POV-Ray options, preview-window settings): why, said once per run
    // when the input sets the option. Null result: this input has effect.
    const char* (*noEffect)(const OptionInput&) = nullptr;
};

std::span<const OptionSpec> optionTable();

// The option a switch body (text after +/-) names: the longest switch name
// that prefixes it, case-insensitively. Returns nullptr when none does.
const OptionSpec* findSwitch(std::string_view body, std::string_view& valueOut);
const OptionSpec* findIniKey(std::string_view key);

// The INI values Create_Ini writes for `spec` (spec.write, or the kept
// value of an option without effect).
std::vector<std::string> optionValues(const OptionSpec& spec, const RenderOptions& options);

// `frameray --help` text, generated from the table.
std::string helpText();
// The option table as a markdown table, for the README
// (`frameray --options-markdown`).
std::string optionsMarkdown();

// The INI text Create_Ini writes: every option set by any source, one
// `Key=Value` line each, in table order.
std::string createIniText(const RenderOptions& options);

// The first option whose value needs a feature not built yet, as
// "Key (feature)"; empty when everything asked for is supported.
std::string firstUnsupported(const RenderOptions& options);

}  // namespace frameray::options
