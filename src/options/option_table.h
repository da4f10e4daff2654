// Every option frameray understands, defined once: its INI key, its
// command-line switch, its type, default and help text, and how it sets
// RenderOptions. The parser, `--help` and the README's option list are all
// generated from this table.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "options/render_options.h"

namespace frameray::options {

enum class OptionType { Bool, Int, Float, String, Path, PathList, Declare, FileType };

// How a value reached the option: from an INI key (`Key=value`) or a
// switch (`+Xvalue` / `-Xvalue`), where the sign matters for booleans.
struct OptionInput {
    std::string_view value;
    bool fromSwitch = false;
    bool plus = true;
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
};

std::span<const OptionSpec> optionTable();

// The option a switch body (text after +/-) names: the longest switch name
// that prefixes it, case-insensitively. Returns nullptr when none does.
const OptionSpec* findSwitch(std::string_view body, std::string_view& valueOut);
const OptionSpec* findIniKey(std::string_view key);

// `frameray --help` text, generated from the table.
std::string helpText();
// The option table as a markdown table, for the README
// (`frameray --options-markdown`).
std::string optionsMarkdown();

}  // namespace frameray::options
