#include "sdl/file_access.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace frameray::sdl {

namespace fs = std::filesystem;

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

OpenedFile& OpenedFile::operator=(OpenedFile&& o) noexcept {
    if (this != &o) {
        if (fd_ >= 0) ::close(fd_);
        fd_ = o.release();
        error_ = std::move(o.error_);
    }
    return *this;
}

OpenedFile::~OpenedFile() {
    if (fd_ >= 0) ::close(fd_);
}

namespace {

// Where an open descriptor really leads, every link resolved (Linux's
// /proc/self/fd); empty when that cannot be told.
fs::path descriptorPath(int fd) {
    std::error_code ec;
    const fs::path target = fs::read_symlink(fmt::format("/proc/self/fd/{}", fd), ec);
    return ec ? fs::path() : target;
}

// Why the system would not open `file`, as a whole message.
std::string systemFailure(const char* how, const std::string& file, int error) {
    const std::string why = error == ELOOP    ? "it is a symbolic link"
                            : error == EISDIR ? "it is a folder"
                                              : std::strerror(error);
    return fmt::format("cannot open '{}' for {}: {}", file, how, why);
}

// The descriptor must be a regular file: a folder, device or pipe could
// block or never end. Empty when it is one; otherwise the message.
std::string notRegular(const char* how, const std::string& file, int fd) {
    struct stat st {};
    if (::fstat(fd, &st) != 0) return systemFailure(how, file, errno);
    if (S_ISDIR(st.st_mode)) return systemFailure(how, file, EISDIR);
    if (!S_ISREG(st.st_mode))
        return fmt::format("cannot open '{}' for {}: not a regular file (a device or pipe)", file,
                           how);
    return {};
}

}  // namespace

bool FileAccessPolicy::linkTrusted(const fs::path& file) const {
    return insideAny(lexicalPath(file), linkTrustedFolders_);
}

OpenedFile FileAccessPolicy::openForReading(const fs::path& file,
                                            const std::string& shownAs) const {
    if (std::string refusal = checkRead(file, shownAs); !refusal.empty())
        return OpenedFile(refusal);
    // O_NONBLOCK: opening a FIFO must not wait for a writer.
    OpenedFile f(::open(file.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK));
    if (!f.ok()) return OpenedFile(systemFailure("reading", shownAs, errno));
    if (std::string why = notRegular("reading", shownAs, f.fd()); !why.empty())
        return OpenedFile(why);
    ::fcntl(f.fd(), F_SETFL, 0);
    if (restricted_ && !linkTrusted(file)) {
        const fs::path opened = descriptorPath(f.fd());
        if (opened.empty() || !insideAny(opened, readFolders_))
            return OpenedFile(
                checkRead(opened.empty() ? fs::path("/proc/self/fd") : opened, shownAs));
    }
    return f;
}

OpenedFile FileAccessPolicy::openForWriting(const fs::path& file, bool append,
                                            const std::string& shownAs) const {
    if (std::string refusal = checkWrite(file, shownAs); !refusal.empty())
        return OpenedFile(refusal);
    const int flags = O_WRONLY | O_CREAT | O_CLOEXEC | O_NOCTTY | O_NONBLOCK |
                      (append ? O_APPEND : 0) | (restricted_ ? O_NOFOLLOW : 0);
    OpenedFile f(::open(file.c_str(), flags, 0666));
    if (!f.ok()) return OpenedFile(systemFailure("writing", shownAs, errno));
    if (std::string why = notRegular("writing", shownAs, f.fd()); !why.empty())
        return OpenedFile(why);
    ::fcntl(f.fd(), F_SETFL, append ? O_APPEND : 0);
    if (restricted_) {
        // A folder on the way may have been swapped for a link.
        const fs::path opened = descriptorPath(f.fd());
        if (opened.empty() || !insideAny(opened, writeFolders_))
            return OpenedFile(
                checkWrite(opened.empty() ? fs::path("/proc/self/fd") : opened, shownAs));
    }
    if (!append && ::ftruncate(f.fd(), 0) != 0)
        return OpenedFile(systemFailure("writing", shownAs, errno));
    return f;
}

}  // namespace frameray::sdl
