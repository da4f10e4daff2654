#include "anim/journal.h"

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "util/durable_file.h"

namespace frameray::anim {

namespace fs = std::filesystem;

namespace {

constexpr std::uint64_t kFnvOffset = 1469598103934665603ULL;
constexpr std::uint64_t kFnvPrime = 1099511628211ULL;

void fnv(std::uint64_t& h, const char* data, size_t n) {
    for (size_t i = 0; i < n; ++i) {
        h ^= static_cast<unsigned char>(data[i]);
        h *= kFnvPrime;
    }
}

std::string header(std::uint64_t settingsHash) {
    return fmt::format("frameray-journal 1 {:016x}", settingsHash);
}

std::string entryLine(const JournalEntry& e) {
    return fmt::format("frame {} {} {} {:016x} {}\n", e.number, e.clock, e.size, e.hash,
                       e.fileName);
}

}  // namespace

std::string clockText(double clock) {
    return fmt::format("{:.17g}", clock);
}

std::uint64_t hashText(const std::string& text) {
    std::uint64_t h = kFnvOffset;
    fnv(h, text.data(), text.size());
    return h;
}

std::optional<std::uint64_t> hashFile(const fs::path& path, std::uintmax_t* sizeOut) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::uint64_t h = kFnvOffset;
    std::uintmax_t size = 0;
    std::vector<char> buf(1 << 16);
    while (in) {
        in.read(buf.data(), static_cast<std::streamsize>(buf.size()));
        const auto n = static_cast<size_t>(in.gcount());
        fnv(h, buf.data(), n);
        size += n;
    }
    if (in.bad()) return std::nullopt;
    if (sizeOut) *sizeOut = size;
    return h;
}

Journal::Journal(fs::path path, std::uint64_t settingsHash, bool resume) : path_(std::move(path)) {
    bool keep = false;
    if (resume) {
        std::ifstream in(path_);
        std::string line;
        if (in && std::getline(in, line)) {
            if (line == header(settingsHash)) {
                keep = true;
                while (std::getline(in, line)) {
                    // Only complete lines count: a crash may cut the last one.
                    if (in.eof()) break;
                    std::istringstream ls(line);
                    std::string word, hashHex;
                    JournalEntry e;
                    if (!(ls >> word >> e.number >> e.clock >> e.size >> hashHex) ||
                        word != "frame")
                        continue;
                    ls >> std::ws;
                    std::getline(ls, e.fileName);
                    if (hashHex.size() != 16 || e.fileName.empty()) continue;
                    try {
                        e.hash = std::stoull(hashHex, nullptr, 16);
                    } catch (const std::exception&) {
                        continue;
                    }
                    entries_[e.number] = e;
                }
            } else {
                discardedStale_ = true;
            }
        }
    }
    if (keep) {
        // Rewrite the journal with the entries kept, so a cut-off last line
        // does not glue itself to the next record.
        std::string text = header(settingsHash) + "\n";
        for (const auto& [n, e] : entries_) text += entryLine(e);
        util::replaceFileDurably(path_, text);
        file_ = std::make_unique<util::DurableAppendFile>(path_, false);
    } else {
        // Replaced rather than truncated: a symbolic link planted under the
        // journal's name is replaced, not followed.
        util::replaceFileDurably(path_, header(settingsHash) + "\n");
        file_ = std::make_unique<util::DurableAppendFile>(path_, false);
    }
}

Journal::~Journal() = default;

bool Journal::verified(int number, const std::string& clock, const fs::path& image) const {
    const auto it = entries_.find(number);
    if (it == entries_.end()) return false;
    const JournalEntry& e = it->second;
    if (e.clock != clock || e.fileName != image.filename().string()) return false;
    std::error_code ec;
    const auto size = fs::file_size(image, ec);
    if (ec || size != e.size) return false;  // cheap check first
    std::uintmax_t hashedSize = 0;
    const auto h = hashFile(image, &hashedSize);
    return h && *h == e.hash && hashedSize == e.size;
}

void Journal::record(int number, const std::string& clock, const fs::path& image) {
    std::uintmax_t size = 0;
    const auto h = hashFile(image, &size);
    if (!h)
        throw std::runtime_error(
            fmt::format("cannot read back '{}' for the journal", image.string()));
    record(number, clock, image, size, *h);
}

void Journal::record(int number, const std::string& clock, const fs::path& image,
                     std::uintmax_t size, std::uint64_t hash) {
    const JournalEntry e{number, clock, size, hash, image.filename().string()};
    file_->append(entryLine(e));
    entries_[number] = e;
}

}  // namespace frameray::anim
