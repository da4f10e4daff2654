// Files that must survive a crash, a full disk or a vanished folder: every
// system call is checked, data is flushed to the device before it counts as
// written, and a failure throws std::runtime_error naming the file and the
// system's reason ("No space left on device", "Permission denied", ...).
// Frames, the resume journal, frame logs and sequence.json go through here,
// so a disk that fills up mid-sequence ends the run with a clear error and
// leaves no truncated file under a final name.
#pragma once

#include <filesystem>
#include <string_view>

namespace frameray::util {

// Creates or truncates `path` (not through a symbolic link in the last
// part of its name), writes `bytes`, flushes them to the device and
// closes it. On failure the partial file is removed before throwing;
// the message names `shownAs` when given (the final name of a temporary).
void writeFileDurably(const std::filesystem::path& path, std::string_view bytes,
                      const std::filesystem::path& shownAs = {});

// Renames `from` to `to` (atomically, same folder) and flushes the folder,
// so the new name survives a power cut. On failure `from` is removed.
void renameDurably(const std::filesystem::path& from, const std::filesystem::path& to);

// writeFileDurably into a hidden temporary beside `path`, then
// renameDurably onto `path`: `path` holds either its old or its new bytes.
void replaceFileDurably(const std::filesystem::path& path, std::string_view bytes);

// Creates or truncates `path` for writing and returns its descriptor,
// never following a symbolic link in the last part of the name: a link
// planted where a file is expected (say debug.out -> ~/.bashrc in a scene
// folder) is an error, not a way to write elsewhere. The file must be a
// regular one. Throws std::runtime_error naming the file and the reason.
// With `append`, the file keeps its contents and every write goes to its
// end.
int createNoFollow(const std::filesystem::path& path, bool append = false);

// Opens a regular file for reading, not through a symbolic link in the
// last part of its name; -1 when it is absent, a link or no regular file.
int openNoFollow(const std::filesystem::path& path);

// An append-only file whose every append() is on the device when it
// returns. A failed append leaves the file as it was before it (cut back
// to its previous length) and throws.
class DurableAppendFile {
  public:
    // Opens `path` for appending (truncating it first when `truncate`), not
    // through a symbolic link in the last part of the name.
    DurableAppendFile(std::filesystem::path path, bool truncate);
    ~DurableAppendFile();
    DurableAppendFile(const DurableAppendFile&) = delete;
    DurableAppendFile& operator=(const DurableAppendFile&) = delete;

    void append(std::string_view bytes);
    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
    int fd_ = -1;
};

}  // namespace frameray::util
