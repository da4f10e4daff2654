#include "util/durable_file.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace frameray::util {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const char* what, const fs::path& path, int error) {
    // O_NOFOLLOW's refusal reads "Too many levels of symbolic links".
    throw std::runtime_error(
        fmt::format("cannot {} '{}': {}", what, path.string(),
                    error == ELOOP ? "it is a symbolic link" : std::strerror(error)));
}

// write(2) until every byte is out; returns 0 or the errno that stopped it.
// A short write with no errno (a full disk reports one as a short count
// first) is retried, and the retry then reports ENOSPC.
int writeAll(int fd, std::string_view bytes) {
    const char* p = bytes.data();
    size_t left = bytes.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, p, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        if (n == 0) return ENOSPC;
        p += n;
        left -= static_cast<size_t>(n);
    }
    return 0;
}

// fsync of the folder holding `path`: makes a rename or a new name durable.
// Some file systems cannot sync a folder (EINVAL); that is not an error.
int syncFolder(const fs::path& path) {
    const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return errno;
    int error = 0;
    if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) error = errno;
    ::close(fd);
    return error;
}

}  // namespace

void writeFileDurably(const fs::path& path, std::string_view bytes, const fs::path& shownAs) {
    const fs::path& named = shownAs.empty() ? path : shownAs;
    const int fd =
        ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0666);
    if (fd < 0) fail("write", named, errno);
    int error = writeAll(fd, bytes);
    if (error == 0 && ::fsync(fd) != 0) error = errno;
    if (::close(fd) != 0 && error == 0) error = errno;
    if (error != 0) {
        ::unlink(path.c_str());
        fail("write", named, error);
    }
}

void renameDurably(const fs::path& from, const fs::path& to) {
    if (::rename(from.c_str(), to.c_str()) != 0) {
        const int error = errno;
        ::unlink(from.c_str());
        fail("move a finished file to", to, error);
    }
    if (const int error = syncFolder(to); error != 0) fail("flush the folder of", to, error);
}

void replaceFileDurably(const fs::path& path, std::string_view bytes) {
    const fs::path temporary =
        path.parent_path() /
        fmt::format(".{}.{}.tmp", path.filename().string(), static_cast<long>(::getpid()));
    writeFileDurably(temporary, bytes, path);
    renameDurably(temporary, path);
}

int createNoFollow(const fs::path& path, bool append) {
    // Not truncated before the check: a FIFO or device keeps its contents.
    const int fd =
        ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK, 0666);
    if (fd < 0) fail("write", path, errno);
    struct stat st {};
    int error = ::fstat(fd, &st) != 0 ? errno : !S_ISREG(st.st_mode) ? EINVAL : 0;
    if (error == 0 && !append && ::ftruncate(fd, 0) != 0) error = errno;
    if (error == 0 && ::fcntl(fd, F_SETFL, append ? O_APPEND : 0) != 0) error = errno;
    if (error != 0) {
        ::close(fd);
        if (error == EINVAL)
            throw std::runtime_error(
                fmt::format("cannot write '{}': not a regular file", path.string()));
        fail("write", path, error);
    }
    return fd;
}

int openNoFollow(const fs::path& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) return -1;
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || ::fcntl(fd, F_SETFL, 0) != 0) {
        ::close(fd);
        return -1;
    }
    return fd;
}

DurableAppendFile::DurableAppendFile(fs::path path, bool truncate) : path_(std::move(path)) {
    fd_ = ::open(path_.c_str(),
                 O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | O_NOFOLLOW | (truncate ? O_TRUNC : 0),
                 0666);
    if (fd_ < 0) fail("write", path_, errno);
}

DurableAppendFile::~DurableAppendFile() {
    if (fd_ >= 0) ::close(fd_);
}

void DurableAppendFile::append(std::string_view bytes) {
    struct stat st {};
    if (::fstat(fd_, &st) != 0) fail("write", path_, errno);
    int error = writeAll(fd_, bytes);
    if (error == 0 && ::fsync(fd_) != 0) error = errno;
    if (error != 0) {
        // Cut back a partly written record so the file stays a sequence
        // of whole records (best effort: the disk may refuse this too).
        [[maybe_unused]] const int ignored = ::ftruncate(fd_, st.st_size);
        fail("write", path_, error);
    }
}

}  // namespace frameray::util
