// Reads options from the command line, INI files, povray.ini and
// POVRAYOPT, in POV-Ray's order, into RenderOptions. Errors name the
// option and where it came from (file:line).
#pragma once

#include <filesystem>
#include <functional>
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
// Throws OptionError. Returns warnings (e.g. an INI section that does not
// exist, which POV-Ray skips silently).
std::vector<std::string> applyArguments(RenderOptions& options,
                                        const std::vector<std::string>& args);

// Applies one INI file; `section` empty means the lines before the first
// section header. `origin` names who asked for it, for messages.
std::vector<std::string> applyIniFile(RenderOptions& options, const std::filesystem::path& path,
                                      const std::string& section, const std::string& origin);

// The scene file Input_File_Name names, found as povray 3.7 finds it: in
// the working folder, then in each Library_Path folder in order; in each,
// the name as given, then with ".pov" appended. The name as given when it
// is in the working folder; empty when it is nowhere.
std::filesystem::path findSceneFile(const RenderOptions& options);

// Splits an option string (POVRAYOPT, a line of switches) into arguments
// at blanks outside double quotes.
std::vector<std::string> splitOptionString(const std::string& text);

// Where the startup options come from: an environment lookup (getenv by
// default) and the working and home folders.
struct StartupEnvironment {
    std::function<const char*(const char*)> getenv;
    std::filesystem::path workingDir;
    std::filesystem::path systemIni = "/etc/povray/3.7/povray.ini";
};
StartupEnvironment processEnvironment();

// The povray.ini POV-Ray 3.7 for Unix reads: the first that exists of
// $POVINI, ./povray.ini, $HOME/.povray/3.7/povray.ini,
// /etc/povray/3.7/povray.ini (then the pre-3.6 $HOME/.povrayrc).
// Empty when there is none.
std::filesystem::path findStartupIni(const StartupEnvironment& env);

// frameray's own configuration file, INI syntax (sdl/file_access.h's
// restrictions are usually widened there): $XDG_CONFIG_HOME/frameray/
// frameray.conf, else ~/.config/frameray/frameray.conf. Empty when absent.
std::filesystem::path findConfigFile(const StartupEnvironment& env);

// Applies the startup sources that come before the command line:
// frameray.conf,
// POVRAYOPT (switches, as in POV-Ray 2.0 - povray 3.7 for Unix ignores it)
// and then the povray.ini found above.
std::vector<std::string> applyStartupOptions(RenderOptions& options, const StartupEnvironment& env);

}  // namespace frameray::options
