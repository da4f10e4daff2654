#include "util/file_paths.h"

namespace frameray {

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

}  // namespace frameray
