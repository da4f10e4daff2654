// What an INI file that may have come with a scene is allowed to set (the
// trust rule of the README's Restrictions section). Such INI files - those
// named on the command line, the INI files they name, and ./povray.ini -
// are as untrusted as the scene itself: they may set anything about the
// image (size, animation, quality, output type...), but every file or
// folder they name (scene, output, library path, stream files, Create_Ini,
// Include_Header, other INI files) must lie inside the INI file's own
// folder or the working folder, where the scene may read and write anyway.
// The options that widen the restrictions (Read_Path, Write_Path,
// File_Restrictions, Allow_Shell_Commands) they may not set at all.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "options/render_options.h"

namespace frameray::options {

// A file or folder an option names, by the option's INI key.
struct NamedPath {
    std::string_view key;
    std::string path;
    bool operator==(const NamedPath&) const = default;
};

// Every path the options name (empty ones left out).
std::vector<NamedPath> namedPaths(const RenderOptions& options);

// The folders an untrusted INI file may name paths in: the working folder
// and `iniFolder`, resolved.
std::vector<std::filesystem::path> trustRoots(const std::filesystem::path& iniFolder);

// Whether `path` (resolved with util/file_paths.h's resolvedPath) lies inside one of
// `roots` (or is one).
bool insideTrustRoots(const std::filesystem::path& path,
                      const std::vector<std::filesystem::path>& roots);

// Empty when every path in `after` that is not in `before` lies inside
// `roots`; otherwise the refusal (naming the option and the path) for the
// first that does not. `where` is the INI file and line.
std::string untrustedPathRefusal(const std::vector<NamedPath>& before,
                                 const std::vector<NamedPath>& after,
                                 const std::vector<std::filesystem::path>& roots,
                                 const std::string& where);

}  // namespace frameray::options
