#include "sdl/file_access.h"

#include <fmt/format.h>

#include <algorithm>

namespace frameray::sdl {

namespace fs = std::filesystem;

fs::path resolvedPath(const fs::path& path) {
    std::error_code ec;
    fs::path absolute = fs::absolute(path.empty() ? fs::path(".") : path, ec);
    if (ec) absolute = path;
    fs::path canonical = fs::weakly_canonical(absolute, ec);
    if (ec) canonical = absolute.lexically_normal();
    // "dir/" and "dir" name the same folder.
    if (!canonical.has_filename() && canonical.has_parent_path() &&
        canonical != canonical.root_path())
        canonical = canonical.parent_path();
    return canonical;
}

bool isInsideFolder(const fs::path& path, const fs::path& folder) {
    auto p = path.begin();
    for (auto f = folder.begin(); f != folder.end(); ++f, ++p) {
        // A trailing empty element is what "dir/" leaves; it matches anything.
        if (f->empty() && std::next(f) == folder.end()) return true;
        if (p == path.end() || *p != *f) return false;
    }
    return true;
}

namespace {

// Absolute, with '.' and '..' resolved by name only.
fs::path lexicalPath(const fs::path& path) {
    std::error_code ec;
    fs::path p = fs::absolute(path.empty() ? fs::path(".") : path, ec).lexically_normal();
    if (!p.has_filename() && p.has_parent_path() && p != p.root_path()) p = p.parent_path();
    return p;
}

void addFolder(std::vector<fs::path>& folders, const fs::path& folder) {
    if (folder.empty()) return;
    const fs::path resolved = resolvedPath(folder);
    if (std::find(folders.begin(), folders.end(), resolved) == folders.end())
        folders.push_back(resolved);
}

bool insideAny(const fs::path& resolved, const std::vector<fs::path>& folders) {
    return std::any_of(folders.begin(), folders.end(),
                       [&](const fs::path& folder) { return isInsideFolder(resolved, folder); });
}

// "'../x' (/home/u/x)" when the scene's name differs from the resolved one.
std::string describe(const fs::path& resolved, const std::string& shownAs) {
    if (shownAs.empty() || shownAs == resolved.string())
        return fmt::format("'{}'", resolved.string());
    return fmt::format("'{}' ({})", shownAs, resolved.string());
}

}  // namespace

FileAccessPolicy FileAccessPolicy::restrictedTo(const FileAccessFolders& f) {
    FileAccessPolicy p;
    p.restricted_ = true;
    for (const fs::path* dir : {&f.working, &f.scene, &f.output}) addFolder(p.writeFolders_, *dir);
    for (const fs::path& dir : f.extraWrite) addFolder(p.writeFolders_, dir);
    // What a scene may write it may read back (state passed between frames).
    p.readFolders_ = p.writeFolders_;
    for (const auto* list : {&f.library, &f.extraRead})
        for (const fs::path& dir : *list) {
            addFolder(p.readFolders_, dir);
            if (!dir.empty()) p.linkTrustedFolders_.push_back(lexicalPath(dir));
        }
    return p;
}

std::string FileAccessPolicy::checkRead(const fs::path& file, const std::string& shownAs) const {
    if (!restricted_) return {};
    const fs::path resolved = resolvedPath(file);
    if (insideAny(resolved, readFolders_) || insideAny(lexicalPath(file), linkTrustedFolders_))
        return {};
    return fmt::format(
        "reading {} is not allowed: scenes may read only in the working folder, the scene's "
        "folder, the "
        "library paths and Read_Path/Write_Path folders; allow it with Read_Path={} (or "
        "File_Restrictions=off)",
        describe(resolved, shownAs), resolved.parent_path().string());
}

std::string FileAccessPolicy::checkWrite(const fs::path& file, const std::string& shownAs) const {
    if (!restricted_) return {};
    const fs::path resolved = resolvedPath(file);
    if (insideAny(resolved, writeFolders_)) return {};
    return fmt::format(
        "writing {} is not allowed: scenes may write only in the working folder, the scene's "
        "folder, the "
        "output folder and Write_Path folders; allow it with Write_Path={} (or "
        "File_Restrictions=off)",
        describe(resolved, shownAs), resolved.parent_path().string());
}

}  // namespace frameray::sdl
