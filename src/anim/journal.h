// The resume journal (Continue_Trace, +C): a text file beside the images
// that records every finished frame with its image file's size and content
// hash and what the frame was made from: the files its parse read (scene,
// includes, images, fonts, #read data) with their content hashes. The
// options are in the header's settings hash. A resumed run keeps a frame
// only when its image still has exactly that size and hash and every file
// it read still has the same contents, so a truncated or replaced image, or
// an edited scene, include or image, renders the frame again.
//
// Format: a header line `frameray-journal 2 <settings hash>`, then lines
//   file <id> <path>                       a path, numbered
//   inputs <set> <id>:<hash> ...           a set of files and their hashes
//   written <id>                           a file the scene wrote (#fopen)
//   frame <number> <clock> <size> <hash> <set> <image file name>
// (hashes FNV-1a 64, hexadecimal). Lines are appended and flushed to disk
// one at a time, each after the lines it refers to; a line cut short by a
// crash, or one referring to a line that is missing, is ignored.
//
// Files the sequence's own frames wrote (state passed from frame to frame
// through #fopen) are not inputs: their contents are what the frames make
// of them, so they cannot tell a stale frame.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace frameray::util {
class DurableAppendFile;
}

namespace frameray::anim {

// What a frame was made from: files (absolute, '..' and links resolved)
// and their contents' hashes when the frame read them, sorted by path.
using FrameInputs = std::vector<std::pair<std::string, std::uint64_t>>;

struct JournalEntry {
    int number = 0;
    std::string clock;  // as written, %.17g
    std::uintmax_t size = 0;
    std::uint64_t hash = 0;
    std::string fileName;
    std::shared_ptr<const FrameInputs> inputs;
};

// FNV-1a 64 of a file's bytes; nullopt when it cannot be read. Unless
// `followLinks`, a symbolic link in the last part of the name counts as
// unreadable (a link under a frame's name is not that frame).
std::optional<std::uint64_t> hashFile(const std::filesystem::path& path,
                                      std::uintmax_t* sizeOut = nullptr, bool followLinks = false);
std::uint64_t hashText(const std::string& text);

// The current content hashes of files, each read once per run and again
// only when its size or modification time changes. Thread-safe.
class FileHashes {
  public:
    std::optional<std::uint64_t> hash(const std::string& path);

  private:
    struct Known {
        std::uintmax_t size = 0;
        std::int64_t mtime = 0;
        std::uint64_t hash = 0;
    };
    std::mutex mutex_;
    std::unordered_map<std::string, Known> known_;
};

class Journal {
  public:
    // Reads `path` when `resume` is set and its settings hash matches;
    // otherwise starts it afresh. `others` are more journals of the same
    // sequence (a sharded run's) whose frames count too when resuming.
    // Throws std::runtime_error when it cannot be written.
    Journal(std::filesystem::path path, std::uint64_t settingsHash, bool resume,
            const std::vector<std::filesystem::path>& others = {});
    ~Journal();
    Journal(const Journal&) = delete;
    Journal& operator=(const Journal&) = delete;

    // True when the journal records frame `number` with this clock, the
    // file `image` is still exactly what was recorded, and every file the
    // frame read still has the contents it had (`hashes` caches them).
    bool verified(int number, const std::string& clock, const std::filesystem::path& image,
                  FileHashes& hashes) const;
    bool verified(int number, const std::string& clock, const std::filesystem::path& image) const;
    // Records a finished frame (hashing its file) and flushes to disk.
    void record(int number, const std::string& clock, const std::filesystem::path& image);
    // The same with the file's size and hash already known (hashed off the
    // serial stage, from the temporary file before its rename), what the
    // frame read and the files it wrote.
    void record(int number, const std::string& clock, const std::filesystem::path& image,
                std::uintmax_t size, std::uint64_t hash, const FrameInputs& inputs = {},
                const std::vector<std::string>& written = {});

    // The files the sequence's frames wrote, as recorded so far.
    const std::set<std::string>& written() const { return written_; }
    // Whether a resume found an older journal written with other settings.
    bool discardedStale() const { return discardedStale_; }
    const std::filesystem::path& path() const { return path_; }

  private:
    // Reads one journal's entries (later ones win); false when its header
    // is not this run's.
    bool load(const std::filesystem::path& path, const std::string& header);
    // The lines that define `path` / `inputs`, when not written yet; their
    // ids.
    int fileId(const std::string& path, std::string& lines);
    int setId(const FrameInputs& inputs, std::string& lines);

    std::filesystem::path path_;
    std::map<int, JournalEntry> entries_;
    std::set<std::string> written_;
    std::map<std::string, int> fileIds_;
    std::map<FrameInputs, int> setIds_;
    std::unique_ptr<util::DurableAppendFile> file_;
    bool discardedStale_ = false;
};

std::string clockText(double clock);

}  // namespace frameray::anim
