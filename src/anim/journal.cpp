#include "anim/journal.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
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
    return fmt::format("frameray-journal 2 {:016x}", settingsHash);
}

bool parseHex(std::string_view text, std::uint64_t& out) {
    return text.size() == 16 &&
           std::from_chars(text.data(), text.data() + text.size(), out, 16).ptr ==
               text.data() + text.size();
}

bool parseInt(std::string_view text, int& out) {
    return !text.empty() && std::from_chars(text.data(), text.data() + text.size(), out).ptr ==
                                text.data() + text.size();
}

// The file's text, not through a symbolic link; empty when absent.
std::string readJournalText(const fs::path& path) {
    const int fd = util::openNoFollow(path);
    if (fd < 0) return {};
    std::string text;
    std::vector<char> buf(1 << 16);
    for (;;) {
        const ssize_t n = ::read(fd, buf.data(), buf.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        text.append(buf.data(), static_cast<size_t>(n));
    }
    ::close(fd);
    return text;
}

// The first `count` blank-separated words of `line`, and the rest of it
// (a path or file name, which may hold blanks) in words[count].
bool splitWords(std::string_view line, size_t count, std::vector<std::string_view>& words) {
    words.clear();
    for (size_t i = 0; i < count; ++i) {
        const size_t end = line.find(' ');
        if (end == std::string_view::npos) {
            if (i + 1 != count) return false;
            words.push_back(line);
            line = {};
            break;
        }
        words.push_back(line.substr(0, end));
        line.remove_prefix(end + 1);
    }
    words.push_back(line);
    return words.size() == count + 1;
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

std::optional<std::uint64_t> hashFile(const fs::path& path, std::uintmax_t* sizeOut,
                                      bool followLinks) {
    const int fd = followLinks ? ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK)
                               : util::openNoFollow(path);
    if (fd < 0) return std::nullopt;
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        return std::nullopt;
    }
    std::uint64_t h = kFnvOffset;
    std::uintmax_t size = 0;
    std::vector<char> buf(1 << 16);
    for (;;) {
        const ssize_t n = ::read(fd, buf.data(), buf.size());
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            ::close(fd);
            return std::nullopt;
        }
        if (n == 0) break;
        fnv(h, buf.data(), static_cast<size_t>(n));
        size += static_cast<std::uintmax_t>(n);
    }
    ::close(fd);
    if (sizeOut) *sizeOut = size;
    return h;
}

std::optional<std::uint64_t> FileHashes::hash(const std::string& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
    const std::int64_t mtime =
        static_cast<std::int64_t>(st.st_mtim.tv_sec) * 1'000'000'000 + st.st_mtim.tv_nsec;
    const auto size = static_cast<std::uintmax_t>(st.st_size);
    {
        std::lock_guard lock(mutex_);
        const auto it = known_.find(path);
        if (it != known_.end() && it->second.size == size && it->second.mtime == mtime)
            return it->second.hash;
    }
    const auto h = hashFile(path, nullptr, true);
    if (!h) return std::nullopt;
    std::lock_guard lock(mutex_);
    known_[path] = {size, mtime, *h};
    return h;
}

Journal::Journal(fs::path path, std::uint64_t settingsHash, bool resume,
                 const std::vector<fs::path>& others)
    : path_(std::move(path)) {
    const std::string head = header(settingsHash);
    if (resume) {
        // The other journals first: this one's own entries win.
        for (const fs::path& other : others) load(other, head);
        discardedStale_ = !load(path_, head) && !readJournalText(path_).empty();
    }
    // Written afresh with the entries kept (none unless resuming), so a
    // cut-off last line does not glue itself to the next record; replaced
    // rather than truncated, so a symbolic link planted under the
    // journal's name is replaced, not followed.
    std::string text = head + "\n";
    for (const std::string& w : written_) {
        const int id = fileId(w, text);
        text += fmt::format("written {}\n", id);
    }
    for (const auto& [n, e] : entries_) {
        const int set = setId(e.inputs ? *e.inputs : FrameInputs{}, text);
        text += fmt::format("frame {} {} {} {:016x} {} {}\n", e.number, e.clock, e.size, e.hash,
                            set, e.fileName);
    }
    util::replaceFileDurably(path_, text);
    file_ = std::make_unique<util::DurableAppendFile>(path_, false);
}

Journal::~Journal() = default;

bool Journal::load(const fs::path& path, const std::string& head) {
    std::istringstream in(readJournalText(path));
    std::string line;
    if (!std::getline(in, line) || line != head) return false;
    std::map<int, std::string> files;
    std::map<int, std::shared_ptr<const FrameInputs>> sets;
    std::vector<std::string_view> w;
    while (std::getline(in, line)) {
        // Only complete lines count: a crash may cut the last one.
        if (in.eof()) break;
        const std::string_view l(line);
        int id = 0;
        if (l.starts_with("file ") && splitWords(l.substr(5), 1, w) && parseInt(w[0], id) &&
            !w[1].empty()) {
            files[id] = std::string(w[1]);
        } else if (l.starts_with("written ") && parseInt(l.substr(8), id) && files.count(id)) {
            written_.insert(files[id]);
        } else if (l.starts_with("inputs ")) {
            std::istringstream words{std::string(l.substr(7))};
            std::string word;
            if (!(words >> word) || !parseInt(word, id)) continue;
            auto inputs = std::make_shared<FrameInputs>();
            bool ok = true;
            while (ok && words >> word) {
                const auto colon = word.find(':');
                int file = 0;
                std::uint64_t h = 0;
                ok = colon != std::string::npos &&
                     parseInt(std::string_view(word).substr(0, colon), file) &&
                     parseHex(std::string_view(word).substr(colon + 1), h) && files.count(file);
                if (ok) inputs->emplace_back(files[file], h);
            }
            if (ok) sets[id] = std::move(inputs);
        } else if (l.starts_with("frame ") && splitWords(l.substr(6), 5, w)) {
            JournalEntry e;
            int set = 0;
            if (!parseInt(w[0], e.number) || w[1].empty() ||
                std::from_chars(w[2].data(), w[2].data() + w[2].size(), e.size).ptr !=
                    w[2].data() + w[2].size() ||
                !parseHex(w[3], e.hash) || !parseInt(w[4], set) || !sets.count(set) || w[5].empty())
                continue;
            e.clock = std::string(w[1]);
            e.inputs = sets[set];
            e.fileName = std::string(w[5]);
            entries_[e.number] = std::move(e);
        }
    }
    return true;
}

int Journal::fileId(const std::string& path, std::string& lines) {
    const auto [it, added] = fileIds_.emplace(path, static_cast<int>(fileIds_.size()));
    if (added) lines += fmt::format("file {} {}\n", it->second, path);
    return it->second;
}

int Journal::setId(const FrameInputs& inputs, std::string& lines) {
    if (const auto it = setIds_.find(inputs); it != setIds_.end()) return it->second;
    std::string pairs;
    for (const auto& [path, h] : inputs) {
        const int id = fileId(path, lines);  // may add its "file" line first
        pairs += fmt::format(" {}:{:016x}", id, h);
    }
    const int id = static_cast<int>(setIds_.size());
    setIds_.emplace(inputs, id);
    lines += fmt::format("inputs {}{}\n", id, pairs);
    return id;
}

bool Journal::verified(int number, const std::string& clock, const fs::path& image,
                       FileHashes& hashes) const {
    const auto it = entries_.find(number);
    if (it == entries_.end()) return false;
    const JournalEntry& e = it->second;
    if (e.clock != clock || e.fileName != image.filename().string()) return false;
    std::error_code ec;
    const auto size = fs::file_size(image, ec);
    if (ec || size != e.size) return false;  // cheap check first
    std::uintmax_t hashedSize = 0;
    const auto h = hashFile(image, &hashedSize);
    if (!h || *h != e.hash || hashedSize != e.size) return false;
    // What the frame was made from is unchanged.
    if (e.inputs)
        for (const auto& [path, recorded] : *e.inputs) {
            const auto now = hashes.hash(path);
            if (!now || *now != recorded) return false;
        }
    return true;
}

bool Journal::verified(int number, const std::string& clock, const fs::path& image) const {
    FileHashes hashes;
    return verified(number, clock, image, hashes);
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
                     std::uintmax_t size, std::uint64_t hash, const FrameInputs& inputs,
                     const std::vector<std::string>& written) {
    std::string lines;
    for (const std::string& w : written) {
        if (!written_.insert(w).second) continue;
        const int id = fileId(w, lines);  // may add its "file" line first
        lines += fmt::format("written {}\n", id);
    }
    const int set = setId(inputs, lines);
    JournalEntry e{number,
                   clock,
                   size,
                   hash,
                   image.filename().string(),
                   std::make_shared<const FrameInputs>(inputs)};
    lines += fmt::format("frame {} {} {} {:016x} {} {}\n", e.number, e.clock, e.size, e.hash, set,
                         e.fileName);
    // One append: the frame line after the lines it refers to.
    file_->append(lines);
    entries_[number] = std::move(e);
}

}  // namespace frameray::anim
