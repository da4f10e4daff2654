// Which files a scene may read and write, like povray.conf's permitted
// paths: a scene from a stranger must not read ~/.ssh or overwrite files
// outside its own folders. One immutable policy per frame (it travels in
// the FrameContext), built by the frame loop from the options; every
// scene-side open asks it first.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "util/file_paths.h"

namespace frameray::sdl {

// The folders a restricted policy opens, as the options give them.
struct FileAccessFolders {
    std::filesystem::path working;                  // the working folder
    std::filesystem::path scene;                    // the scene file's folder
    std::filesystem::path output;                   // the output images' folder
    std::vector<std::filesystem::path> library;     // Library_Path and the standard includes
    std::vector<std::filesystem::path> extraRead;   // Read_Path
    std::vector<std::filesystem::path> extraWrite;  // Write_Path
};

// A file a scene opened: its descriptor (owned, closed on destruction),
// or -1 and the whole message saying why not (the refusal, or "cannot open
// 'NAME' for reading: REASON").
class OpenedFile {
  public:
    OpenedFile() = default;
    explicit OpenedFile(std::string error) : error_(std::move(error)) {}
    explicit OpenedFile(int fd) : fd_(fd) {}
    OpenedFile(OpenedFile&& o) noexcept : fd_(o.release()), error_(std::move(o.error_)) {}
    OpenedFile& operator=(OpenedFile&& o) noexcept;
    OpenedFile(const OpenedFile&) = delete;
    OpenedFile& operator=(const OpenedFile&) = delete;
    ~OpenedFile();

    bool ok() const { return fd_ >= 0; }
    int fd() const { return fd_; }
    const std::string& error() const { return error_; }
    // Hands the descriptor over to the caller.
    int release() {
        const int fd = fd_;
        fd_ = -1;
        return fd;
    }

  private:
    int fd_ = -1;
    std::string error_;
};

class FileAccessPolicy {
  public:
    // Unrestricted: every path is allowed (File_Restrictions=off, and
    // parsing outside the frame loop, as in unit tests).
    FileAccessPolicy() = default;

    // Reads limited to the working, scene, library, Read_Path and write
    // folders; writes to the working, scene, output and Write_Path folders.
    // Subfolders count; paths are compared after resolving '..' and
    // symbolic links (a link in the scene's folder cannot lead out of it),
    // except that links inside library and Read_Path folders are followed
    // by name.
    static FileAccessPolicy restrictedTo(const FileAccessFolders& folders);

    bool restricted() const { return restricted_; }

    // Empty when `file` (relative names are taken from the working folder)
    // may be read / written; otherwise the refusal, naming the file and the
    // option that would allow it. `shownAs` is the name the scene used.
    std::string checkRead(const std::filesystem::path& file, const std::string& shownAs) const;
    std::string checkWrite(const std::filesystem::path& file, const std::string& shownAs) const;

    // Open `file` for a scene as checkRead / checkWrite allow, then check
    // the descriptor itself, so that a name swapped for a symbolic link
    // between the check and the open cannot lead elsewhere: it must be a
    // regular file and, after every link, lie in the allowed folders
    // (links inside library and Read_Path folders are followed by name
    // when reading). Writing never follows a link in the last part of the
    // name while restricted, and truncates only after the check. The error
    // gives the refusal or the system's reason.
    OpenedFile openForReading(const std::filesystem::path& file, const std::string& shownAs) const;
    OpenedFile openForWriting(const std::filesystem::path& file, bool append,
                              const std::string& shownAs) const;

  private:
    bool linkTrusted(const std::filesystem::path& file) const;

    bool restricted_ = false;
    // Canonical (symbolic links resolved) folders.
    std::vector<std::filesystem::path> readFolders_;
    // The library and Read_Path folders as given, made absolute: the
    // user's or the system's own, so links inside them may point anywhere
    // (povray's include folder links its fonts from /usr/share/fonts).
    std::vector<std::filesystem::path> linkTrustedFolders_;
    std::vector<std::filesystem::path> writeFolders_;
};

// resolvedPath and isInsideFolder (util/file_paths.h) judge the paths.
using frameray::isInsideFolder;
using frameray::resolvedPath;

}  // namespace frameray::sdl
