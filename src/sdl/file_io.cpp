// Text and binary file directives: #fopen, #read, #write, #fclose. Files
// are how frames pass state to each other, so they are closed (flushed) at
// the end of every parse.
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <string_view>
#include <vector>

#include "sdl/reader.h"

namespace frameray::sdl {

namespace fs = std::filesystem;

// A file #fopen opened for writing, through the descriptor the frame's
// FileAccessPolicy checked (never re-opened by name). #write text is
// collected and written out at the end of each #write, so a failing write
// (a full disk, `ulimit -f`) is an error at that #write.
class FileWriter {
  public:
    FileWriter() = default;
    FileWriter(const FileWriter&) = delete;
    FileWriter& operator=(const FileWriter&) = delete;
    ~FileWriter() { close(); }

    void open(int fd) { fd_ = fd; }
    bool isOpen() const { return fd_ >= 0; }
    void put(char c) { pending_ += c; }
    FileWriter& operator<<(std::string_view text) {
        pending_ += text;
        return *this;
    }
    // Writes what was collected; 0 or the errno that stopped it.
    int flush() {
        const char* p = pending_.data();
        size_t left = pending_.size();
        while (left > 0 && fd_ >= 0) {
            const ssize_t n = ::write(fd_, p, left);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                const int error = n < 0 ? errno : ENOSPC;
                pending_.clear();
                return error;
            }
            p += n;
            left -= static_cast<size_t>(n);
        }
        pending_.clear();
        return 0;
    }
    void close() {
        if (fd_ < 0) return;
        flush();
        ::close(fd_);
        fd_ = -1;
    }

  private:
    int fd_ = -1;
    std::string pending_;
};

struct FileHandle {
    std::string name;
    bool writing = false;
    FileWriter out;
    std::string content;  // a read file, whole
    size_t pos = 0;
};

namespace {

// The whole of a regular file's descriptor, up to `limit` bytes (a file
// that grows while read stops there); nullopt-like false on a read error.
bool readDescriptor(int fd, size_t limit, std::string& text, int& error) {
    std::vector<char> chunk(size_t(1) << 16);
    while (text.size() < limit) {
        const ssize_t n = ::read(fd, chunk.data(), std::min(chunk.size(), limit - text.size()));
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            error = errno;
            return false;
        }
        if (n == 0) break;
        text.append(chunk.data(), static_cast<size_t>(n));
    }
    return true;
}

void skipSeparators(const FileHandle& f, size_t& pos) {
    while (pos < f.content.size() &&
           (std::isspace(static_cast<unsigned char>(f.content[pos])) || f.content[pos] == ','))
        ++pos;
}

// One item of a data file: a number, a <vector> or a "string". Returns
// false with a reason when the text there is none of them.
bool readItem(FileHandle& f, Value& out, std::string& error) {
    size_t& p = f.pos;
    const std::string& s = f.content;
    auto readNumber = [&](double& v) {
        while (p < s.size() && std::isspace(static_cast<unsigned char>(s[p]))) ++p;
        const char* begin = s.c_str() + p;
        char* end = nullptr;
        v = std::strtod(begin, &end);
        if (end == begin) return false;
        p += static_cast<size_t>(end - begin);
        return true;
    };
    if (s[p] == '"') {
        const size_t close = s.find('"', p + 1);
        if (close == std::string::npos) {
            error = "unterminated string";
            return false;
        }
        out = s.substr(p + 1, close - p - 1);
        p = close + 1;
        return true;
    }
    if (s[p] == '<') {
        ++p;
        VectorValue v;
        int n = 0;
        for (;;) {
            double c;
            if (n == 5 || !readNumber(c)) {
                error = "malformed vector";
                return false;
            }
            v.v[n++] = c;
            while (p < s.size() && std::isspace(static_cast<unsigned char>(s[p]))) ++p;
            if (p < s.size() && s[p] == ',') {
                ++p;
                continue;
            }
            if (p < s.size() && s[p] == '>') {
                ++p;
                break;
            }
            error = "malformed vector";
            return false;
        }
        v.size = static_cast<uint8_t>(n);
        out = v;
        return true;
    }
    double v;
    if (!readNumber(v)) {
        error = fmt::format("unexpected '{}'", s[p]);
        return false;
    }
    out = v;
    return true;
}

// Binary word formats of #write, as data.
struct BinaryFormat {
    Keyword kw;
    int bytes;
    bool isSigned;
    bool bigEndian;
};
constexpr BinaryFormat kBinaryFormats[] = {
    {Keyword::kw_uint8, 1, false, false},   {Keyword::kw_sint8, 1, true, false},
    {Keyword::kw_uint16be, 2, false, true}, {Keyword::kw_uint16le, 2, false, false},
    {Keyword::kw_sint16be, 2, true, true},  {Keyword::kw_sint16le, 2, true, false},
    {Keyword::kw_sint32be, 4, true, true},  {Keyword::kw_sint32le, 4, true, false},
};

void writeBinary(FileWriter& out, const BinaryFormat& f, double value) {
    const double lo = f.isSigned ? -std::ldexp(1.0, f.bytes * 8 - 1) : 0.0;
    const double hi =
        f.isSigned ? std::ldexp(1.0, f.bytes * 8 - 1) - 1 : std::ldexp(1.0, f.bytes * 8) - 1;
    // Rounded as floor(x + 0.5), as povray does (-2.5 -> -2).
    const auto word =
        static_cast<uint32_t>(static_cast<int64_t>(std::clamp(std::floor(value + 0.5), lo, hi)));
    for (int i = 0; i < f.bytes; ++i) {
        const int shift = 8 * (f.bigEndian ? f.bytes - 1 - i : i);
        out.put(static_cast<char>((word >> shift) & 0xFF));
    }
}

}  // namespace

void Reader::checkReadable(const fs::path& path, const std::string& name, const Token& at) {
    if (const std::string refusal = frame_.fileAccess.checkRead(path, name); !refusal.empty())
        fail(at, refusal);
    filesRead_.push_back(path);
    // Scene files, data, images and fonts are read whole: a device or pipe
    // (/dev/zero, a FIFO) could block or never end.
    std::error_code ec;
    if (!fs::is_regular_file(path, ec))
        fail(at,
             fmt::format("cannot read '{}': not a regular file (a folder, device or pipe)", name));
}

void Reader::checkWritable(const fs::path& path, const std::string& name, const Token& at) {
    if (const std::string refusal = frame_.fileAccess.checkWrite(path, name); !refusal.empty())
        fail(at, refusal);
}

fs::path Reader::fileToWrite(const std::string& name, const Token& at) {
    if (!frame_.refuseFileWrites.empty())
        fail(at, fmt::format("'{}' is written: {}", name, frame_.refuseFileWrites));
    checkWritable(name, name, at);
    std::error_code ec;
    const fs::path path = fs::absolute(name, ec);
    if (ec) fail(at, fmt::format("cannot write '{}': {}", name, ec.message()));
    filesWritten_.push_back(name);
    return path;
}

std::string Reader::readWholeFile(const std::string& name, const Token& at, std::string_view what) {
    const fs::path path = findIncludeFile(name);
    if (path.empty())
        fail(at, frame_.refuseFileWrites.empty()
                     ? fmt::format("cannot read the {} '{}': {}", what, name, whyNotFound(name))
                     : fmt::format("cannot read the {} '{}' ({}); if an earlier frame writes it, "
                                   "{}",
                                   what, name, whyNotFound(name), frame_.refuseFileWrites));
    checkReadable(path, name, at);
    const OpenedFile file = frame_.fileAccess.openForReading(path, name);
    if (!file.ok()) fail(at, file.error());
    std::string bytes;
    int error = 0;
    if (!readDescriptor(file.fd(), std::numeric_limits<size_t>::max(), bytes, error))
        fail(at, fmt::format("cannot read the {} '{}': {}", what, name, std::strerror(error)));
    return bytes;
}

std::string Reader::whyNotFound(const std::string& name) const {
    std::error_code ec;
    const fs::path p(name);
    std::vector<fs::path> dirs;
    if (p.is_absolute()) {
        dirs.emplace_back();
    } else {
        dirs.push_back(fs::current_path(ec));
        for (const auto& lib : frame_.libraryPaths) dirs.push_back(lib);
        dirs.push_back(fs::path(cursors_.back().file->source->path()).parent_path());
    }
    for (const auto& dir : dirs)
        if (fs::is_directory(dir / p, ec)) return fmt::format("'{}' is a folder, not a file", name);
    return p.is_absolute() ? "no such file"
                           : "no such file in the working folder, the library path or the "
                             "scene's folder";
}

void Reader::directiveFopen(const Token& at) {
    const Token idToken = rawPeek();
    const std::string id = expectIdentifier();
    // povray: "Expected 'undeclared identifier', file identifier found".
    // Opening another file under an open file's name would also leave the
    // first open until the end of the parse.
    if (const Value* v = lookup(id); v && std::holds_alternative<FilePtr>(*v))
        fail(idToken, fmt::format("'{}' is an open file identifier: #fclose {} before opening "
                                  "another file with it",
                                  id, id));
    const std::string name = parsePathname();
    const Token mode = next();
    auto handle = std::make_shared<FileHandle>();
    handle->name = name;
    switch (mode.kw) {
        case Keyword::kw_read: {
            const fs::path path = findIncludeFile(name);
            if (path.empty())
                fail(at,
                     frame_.refuseFileWrites.empty()
                         ? fmt::format("cannot open '{}' for reading: {}", name, whyNotFound(name))
                         : fmt::format("cannot open '{}' for reading ({}); if an earlier frame "
                                       "writes it, {}",
                                       name, whyNotFound(name), frame_.refuseFileWrites));
            filesRead_.push_back(path);
            const OpenedFile file = frame_.fileAccess.openForReading(path, name);
            if (!file.ok()) fail(at, file.error());
            int error = 0;
            if (!readDescriptor(file.fd(), frame_.limits.readFileBytes + 1, handle->content, error))
                fail(at, fmt::format("cannot read '{}': {}", name, std::strerror(error)));
            if (handle->content.size() > frame_.limits.readFileBytes)
                fail(at, fmt::format("cannot read '{}': larger than {} MiB, the limit for a file "
                                     "read with #read",
                                     name, frame_.limits.readFileBytes >> 20));
            break;
        }
        case Keyword::kw_write:
        case Keyword::kw_append: {
            if (!frame_.refuseFileWrites.empty())
                fail(at, fmt::format("'{}' is opened for {}: {}", name,
                                     mode.kw == Keyword::kw_append ? "append" : "write",
                                     frame_.refuseFileWrites));
            handle->writing = true;
            filesWritten_.push_back(name);
            OpenedFile file =
                frame_.fileAccess.openForWriting(name, mode.kw == Keyword::kw_append, name);
            if (!file.ok()) fail(at, file.error());
            handle->out.open(file.release());
            break;
        }
        default:
            fail(mode, fmt::format("expected read, write or append after the file name, found {}",
                                   describeToken(mode)));
    }
    openFiles_.push_back(handle);
    symbols_.declare(id, FilePtr(handle), false);
}

void Reader::directiveFclose(const Token& at) {
    (void)at;
    const Token idToken = rawPeek();
    const std::string id = expectIdentifier();
    Value* v = symbols_.find(id);
    // Closing a file that reached its end (and so was undefined) is fine.
    if (!v) return;
    if (!std::holds_alternative<FilePtr>(*v))
        fail(idToken, fmt::format("'{}' is a {}, not a file identifier", id, valueKindName(*v)));
    std::get<FilePtr>(*v)->out.close();
    symbols_.undefine(id);
    std::erase_if(openFiles_, [](const std::weak_ptr<FileHandle>& f) { return f.expired(); });
}

void Reader::directiveRead(const Token& at) {
    expect(Sym::LParen, "'('");
    const Token idToken = rawPeek();
    const std::string id = expectIdentifier();
    Value* v = symbols_.find(id);
    if (!v)
        fail(idToken,
             fmt::format(
                 "'{}' is not an open file: a file read to its end is closed and its identifier "
                 "undefined (test defined({}) before #read)",
                 id, id));
    if (!std::holds_alternative<FilePtr>(*v))
        fail(idToken, fmt::format("expected a file identifier opened for reading, found '{}'", id));
    const FilePtr file = std::get<FilePtr>(*v);
    if (file->writing)
        fail(idToken, fmt::format("file '{}' was opened for writing, not reading", file->name));
    while (accept(Sym::Comma)) {
        const Token target = rawPeek();
        const std::string name = expectIdentifier();
        ArrayPtr array;
        size_t index = 0;
        if (peek().is(Sym::LBracket)) {
            Value* a = symbols_.find(name);
            if (!a || !std::holds_alternative<ArrayPtr>(*a))
                fail(target, fmt::format("'{}' is not an array", name));
            array = std::get<ArrayPtr>(*a);
            index = parseArrayIndex(*array, target);
        }
        skipSeparators(*file, file->pos);
        if (file->pos >= file->content.size()) break;  // end of file: leave the rest unset
        Value item;
        std::string error;
        if (!readItem(*file, item, error))
            fail(at, fmt::format("cannot read from '{}': {}", file->name, error));
        if (array)
            setArrayElement(*array, index, std::move(item), target);
        else
            symbols_.declare(name, std::move(item), false);
    }
    expect(Sym::RParen, "')'");
    // At the end of the data the file identifier becomes undefined, which
    // is how scenes loop: #while (defined(F)) #read (F, X) ... #end
    skipSeparators(*file, file->pos);
    if (file->pos >= file->content.size()) symbols_.undefine(id);
}

void Reader::directiveWrite(const Token& at) {
    expect(Sym::LParen, "'('");
    // Inside the parentheses directives run as anywhere else.
    cursors_.back().inDirective = false;
    const Token idToken = rawPeek();
    const std::string id = expectIdentifier();
    Value* v = symbols_.find(id);
    if (!v || !std::holds_alternative<FilePtr>(*v))
        fail(idToken, fmt::format("expected a file identifier opened for writing, found '{}'", id));
    const FilePtr file = std::get<FilePtr>(*v);
    if (!file->writing)
        fail(idToken, fmt::format("file '{}' was opened for reading, not writing", file->name));
    // povray takes the commas between the items as optional, the one after
    // the file identifier too (`#write(F Header)` in the portfolio), silently.
    for (accept(Sym::Comma); !peek().is(Sym::RParen); accept(Sym::Comma)) {
        const BinaryFormat* binary = nullptr;
        for (const auto& f : kBinaryFormats)
            if (peek().is(f.kw)) binary = &f;
        if (binary) next();
        const Token itemToken = peek();
        const Value item = parseExpression();
        if (binary) {
            if (const double* f = std::get_if<double>(&item)) {
                writeBinary(file->out, *binary, *f);
            } else if (const auto* vec = std::get_if<VectorValue>(&item)) {
                for (int i = 0; i < vec->size; ++i) writeBinary(file->out, *binary, vec->v[i]);
            } else {
                fail(itemToken, "binary #write needs floats or vectors");
            }
            continue;
        }
        if (const auto* s = std::get_if<std::string>(&item)) {
            file->out << *s;
        } else if (const double* f = std::get_if<double>(&item)) {
            file->out << fmt::format("{:g}", *f);
        } else if (const auto* vec = std::get_if<VectorValue>(&item); vec && !vec->isColor) {
            // povray writes "<1,2,3> " - the trailing space is its format.
            std::string text = "<";
            for (int i = 0; i < vec->size; ++i) {
                if (i) text += ',';
                text += fmt::format("{:g}", vec->v[i]);
            }
            file->out << text << "> ";
        } else {
            fail(itemToken, fmt::format("#write cannot write a {}", valueKindName(item)));
        }
    }
    expect(Sym::RParen, "')'");
    if (const int error = file->out.flush(); error != 0)
        fail(at, fmt::format("cannot write to '{}': {}", file->name, std::strerror(error)));
}

void Reader::closeAllFiles() {
    for (const auto& weak : openFiles_)
        if (const FilePtr f = weak.lock()) f->out.close();
    openFiles_.clear();
}

}  // namespace frameray::sdl
