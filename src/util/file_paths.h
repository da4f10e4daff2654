// Path questions that file-access policies ask: where a path really leads,
// and whether it stays inside a folder. The scene's file policy
// (sdl/file_access) and the INI trust check (options/ini_trust) both use
// them, so a path is judged the same way wherever it comes from.
#pragma once

#include <filesystem>

namespace frameray {

// `path` made absolute (from the working folder) with '..', '.' and
// symbolic links of its existing part resolved; "dir/" and "dir" give the
// same result.
std::filesystem::path resolvedPath(const std::filesystem::path& path);

// Whether `path` is `folder` or inside it; both already resolved.
bool isInsideFolder(const std::filesystem::path& path, const std::filesystem::path& folder);

}  // namespace frameray
