// Reads options from the command line and INI files, in the order given,
// into RenderOptions. Errors name the option and where it came from.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "options/render_options.h"

namespace frameray::options {

class OptionError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Applies command-line arguments in order: switches (+X/-X), Key=Value
// pairs, INI files (`file.ini` or `file.ini[Section]`) and the scene file.
// Throws OptionError.
void applyArguments(RenderOptions& options, const std::vector<std::string>& args);

// Applies one INI file; `section` empty means the lines before the first
// section header. `origin` names who asked for it, for messages.
void applyIniFile(RenderOptions& options, const std::filesystem::path& path,
                  const std::string& section, const std::string& origin);

}  // namespace frameray::options
