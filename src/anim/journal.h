// The resume journal (Continue_Trace, +C): a text file beside the images
// that records every finished frame with its file's size and content hash.
// A resumed run keeps a frame only when its file still has exactly that
// size and hash, so a truncated or replaced file is rendered again.
//
// Format: a header line `frameray-journal 1 <settings hash>`, then one line
// per finished frame: `frame <number> <clock> <size> <fnv1a-64 hex> <file name>`.
// Lines are appended and flushed to disk one at a time; a line cut short by
// a crash does not parse and is ignored.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace frameray::util {
class DurableAppendFile;
}

namespace frameray::anim {

struct JournalEntry {
    int number = 0;
    std::string clock;  // as written, %.17g
    std::uintmax_t size = 0;
    std::uint64_t hash = 0;
    std::string fileName;
};

// FNV-1a 64 of a file's bytes; nullopt when it cannot be read.
std::optional<std::uint64_t> hashFile(const std::filesystem::path& path,
                                      std::uintmax_t* sizeOut = nullptr);
std::uint64_t hashText(const std::string& text);

class Journal {
  public:
    // Reads `path` when `resume` is set and its settings hash matches;
    // otherwise starts it afresh. Throws std::runtime_error when it cannot
    // be written.
    Journal(std::filesystem::path path, std::uint64_t settingsHash, bool resume);
    ~Journal();
    Journal(const Journal&) = delete;
    Journal& operator=(const Journal&) = delete;

    // True when the journal records frame `number` with this clock and the
    // file `image` is still exactly what was recorded.
    bool verified(int number, const std::string& clock, const std::filesystem::path& image) const;
    // Records a finished frame (hashing its file) and flushes to disk.
    void record(int number, const std::string& clock, const std::filesystem::path& image);
    // The same with the file's size and hash already known (hashed off the
    // serial stage, from the temporary file before its rename).
    void record(int number, const std::string& clock, const std::filesystem::path& image,
                std::uintmax_t size, std::uint64_t hash);

    // Whether a resume found an older journal written with other settings.
    bool discardedStale() const { return discardedStale_; }
    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
    std::map<int, JournalEntry> entries_;
    std::unique_ptr<util::DurableAppendFile> file_;
    bool discardedStale_ = false;
};

std::string clockText(double clock);

}  // namespace frameray::anim
