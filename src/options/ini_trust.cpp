#include "options/ini_trust.h"

#include <fmt/format.h>

#include <algorithm>

#include "util/file_paths.h"

namespace frameray::options {

namespace fs = std::filesystem;

namespace {

// The stream file options, in the order of TextStream.
constexpr std::string_view kStreamFileKeys[kTextStreams] = {
    "Debug_File", "Fatal_File", "Render_File", "Statistic_File", "Warning_File", "All_File"};

}  // namespace

std::vector<NamedPath> namedPaths(const RenderOptions& o) {
    std::vector<NamedPath> out;
    const auto add = [&](std::string_view key, const std::string& path) {
        if (!path.empty()) out.push_back({key, path});
    };
    add("Input_File_Name", o.inputFile);
    // "-" is standard output, not a file.
    if (o.outputFile != "-") add("Output_File_Name", o.outputFile);
    add("Include_Header", o.includeHeader);
    add("Create_Ini", o.createIni);
    for (const fs::path& p : o.libraryPaths) add("Library_Path", p.string());
    for (int i = 0; i < kTextStreams; ++i)
        add(kStreamFileKeys[i], o.streams[static_cast<size_t>(i)].file);
    return out;
}

std::vector<fs::path> trustRoots(const fs::path& iniFolder) {
    std::error_code ec;
    std::vector<fs::path> roots{resolvedPath(fs::current_path(ec))};
    const fs::path folder = resolvedPath(iniFolder.empty() ? fs::path(".") : iniFolder);
    if (std::find(roots.begin(), roots.end(), folder) == roots.end()) roots.push_back(folder);
    return roots;
}

bool insideTrustRoots(const fs::path& path, const std::vector<fs::path>& roots) {
    return std::any_of(roots.begin(), roots.end(),
                       [&](const fs::path& root) { return isInsideFolder(path, root); });
}

std::string untrustedPathRefusal(const std::vector<NamedPath>& before,
                                 const std::vector<NamedPath>& after,
                                 const std::vector<fs::path>& roots, const std::string& where) {
    for (const NamedPath& named : after) {
        if (std::find(before.begin(), before.end(), named) != before.end()) continue;
        const fs::path resolved = resolvedPath(named.path);
        if (insideTrustRoots(resolved, roots)) continue;
        // Every scene may read the standard include files anyway.
        if (named.key == "Library_Path" &&
            insideTrustRoots(resolved, {resolvedPath(kStandardIncludeFolder)}))
            continue;
        const std::string what =
            named.key == "INI file" ? fmt::format("the INI file '{}':", named.path)
                                    : fmt::format("option '{}' names '{}':", named.key, named.path);
        return fmt::format(
            "{}: {} not allowed outside the INI file's folder and the working folder (an INI file "
            "named on the command line, or ./povray.ini, may name files only there); give it on "
            "the command line instead",
            where, what);
    }
    return {};
}

}  // namespace frameray::options
