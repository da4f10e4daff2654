// The reader's token stream, resource limits and diagnostics (reader.h).
#include "sdl/reader.h"

#include <fmt/format.h>
#include <pthread.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace frameray::sdl {

namespace fs = std::filesystem;

namespace {
// Stack kept free below the deepest NestingGuard: enough for the deepest
// call chain between two guards (sanitizer builds have much larger frames).
constexpr size_t kStackReserve = size_t(512) << 10;

// The lowest address of the calling thread's stack plus the reserve, or
// null when the thread cannot tell.
const char* stackFloor() {
    pthread_attr_t attr;
    if (pthread_getattr_np(pthread_self(), &attr) != 0) return nullptr;
    void* base = nullptr;
    size_t size = 0;
    const bool known = pthread_attr_getstack(&attr, &base, &size) == 0;
    pthread_attr_destroy(&attr);
    if (!known || size < 2 * kStackReserve) return nullptr;
    return static_cast<const char*>(base) + kStackReserve;
}
}  // namespace

Reader::Reader(const FrameContext& frame, TokenCache& cache, MessageSink& messages)
    : frame_(frame), cache_(cache), messages_(messages) {
    version_ = frame.version;
    versionSeen_ = frame.versionGiven;
    endToken_.kind = TokenKind::End;
}

void Reader::begin(std::shared_ptr<const TokenizedFile> file, std::string inputFileName) {
    inputFileName_ = std::move(inputFileName);
    symbols_.reset();
    stackFloor_ = stackFloor();
    // Declare=Name=Value options become global identifiers before parsing.
    for (const auto& [name, value] : frame_.declares) {
        char* end = nullptr;
        const double number = std::strtod(value.c_str(), &end);
        if (end && *end == '\0' && !value.empty()) {
            // povray keeps six significant digits of the value (measured:
            // Declare=V=0.123456789 reads back as 0.123457).
            char rounded[32];
            std::snprintf(rounded, sizeof rounded, "%g", number);
            symbols_.global()[name] = std::strtod(rounded, nullptr);
        } else {
            symbols_.global()[name] = value;
        }
    }
    cursors_.push_back({file, 0, CursorKind::File, 1, 0, false});
    // Include_Header (+HI): read before the scene's first line, as an
    // #include there (povray: its declarations precede the scene's
    // #version; a missing one stops the parse).
    if (const std::string& name = frame_.includeHeader; !name.empty()) {
        const fs::path path = findIncludeFile(name);
        if (path.empty())
            throw SdlError(
                {}, fmt::format("cannot open include header file '{}' (Include_Header)", name));
        if (const std::string refusal = frame_.fileAccess.checkRead(path, name); !refusal.empty())
            throw SdlError({}, refusal);
        filesRead_.push_back(path);
        auto header = cache_.get(path);
        if (!header)
            throw SdlError({}, fmt::format("cannot read include header file '{}'", path.string()));
        symbols_.push();
        cursors_.push_back(
            {std::move(header), 0, CursorKind::File, symbols_.size() - 1, blocks_.size(), false});
        ++includeDepth_;
    }
}

void Reader::end() {
    closeAllFiles();
    if (!blocks_.empty()) {
        const Block& open = blocks_.back();
        throw SdlError(open.loc, "missing #end: this directive is never closed");
    }
}

// --- resource limits -----------------------------------------------------------

void Reader::enterNesting(const Token& at) {
    ++nesting_;
    if (nesting_ > frame_.limits.nesting)
        fail(at, fmt::format("nested too deeply: more than {} levels of expressions, objects, "
                             "textures or directives",
                             frame_.limits.nesting));
    // The depth limit is sized for the usual stack; a smaller one (or a
    // heavier path between guards) still stops cleanly here.
    const char probe = 0;
    if (stackFloor_ && &probe < stackFloor_)
        fail(at, fmt::format("nested too deeply: the parser's stack is exhausted after {} levels",
                             nesting_));
}

void Reader::countIteration(const SourceLoc& where) {
    const size_t limit = frame_.limits.parseIterations;
    if (limit != 0 && ++iterations_ > limit)
        throw SdlError(where, fmt::format("parse stopped after {} loop iterations and macro calls "
                                          "(Max_Parse_Iterations); is this loop making progress?",
                                          limit));
}

void Reader::chargeArrayElements(size_t count, const Token& at) {
    if (count > frame_.limits.arrayElements)
        fail(at, fmt::format("array of more than {} elements", frame_.limits.arrayElements));
    arrayElementsMade_ += count;
    if (arrayElementsMade_ > frame_.limits.totalArrayElements)
        fail(at, fmt::format("arrays made in this frame hold more than {} elements in all",
                             frame_.limits.totalArrayElements));
}

void Reader::checkStringLength(size_t length, const Token& at) {
    if (length > frame_.limits.stringLength)
        fail(at, fmt::format("string of {} bytes is longer than the limit of {}", length,
                             frame_.limits.stringLength));
}

// --- token stream ------------------------------------------------------------

const Token& Reader::rawPeekAtEnd() {
    for (;;) {
        Cursor& c = cursors_.back();
        const Token& t = window_.at(c.file, c.pos);
        if (t.kind != TokenKind::End) return t;
        if (cursors_.size() == 1) return t;
        if (c.kind == CursorKind::Macro) fail(t, "macro body ends without #end");
        // End of an include file: its #local identifiers go with it.
        if (blocks_.size() > c.blockCount)
            throw SdlError(blocks_.back().loc, "missing #end before the end of the include file");
        symbols_.resize(c.scopeCount);
        cursors_.pop_back();
        --includeDepth_;
    }
}

const Token& Reader::resolvePeek() {
    for (;;) {
        const Token& t = rawPeek();
        if (t.is(Sym::Hash) && !cursors_.back().inDirective) {
            runDirective();
            continue;
        }
        const Value* named = nullptr;
        if (t.isIdentifier()) {
            const Value* v = lookup(t);
            named = v;
            if (v && std::holds_alternative<MacroPtr>(*v)) {
                const Token nameToken = t;
                const MacroPtr macro = std::get<MacroPtr>(*v);
                ++cursors_.back().pos;
                invokeMacro(nameToken, *macro);
                continue;
            }
        }
        // A '#' handed out raw (directive arguments end there) must be
        // looked at again once the directive is done.
        if (!t.is(Sym::Hash)) {
            const Cursor& c = cursors_.back();
            peekCache_ = {c.file.get(), c.pos, cursors_.size(), named};
        }
        return t;
    }
}

Token Reader::next() {
    Token t = peek();
    if (t.kind != TokenKind::End) ++cursors_.back().pos;
    return t;
}

SourceLoc Reader::loc(const Token& t) const {
    // Tokens handed around are copies; they belong to the file of the top
    // cursor except after a file boundary, where callers pass locations.
    return cursors_.back().file->locOf(t);
}

SourceLoc Reader::here() {
    return loc(peek());
}

void Reader::fail(const Token& at, const std::string& message) {
    throw SdlError(loc(at), withSpellingSuggestion(at, message));
}

void Reader::failHere(const std::string& message) {
    const Token t = peek();
    fail(t, message);
}

void Reader::warn(const Token& at, const std::string& message) {
    messages_.message(Stream::Warning, formatDiagnostic(Severity::Warning, loc(at), message));
}

void Reader::unsupported(const Token& at, const std::string& feature) {
    fail(at, fmt::format("not supported yet: {}", feature));
}

void Reader::expect(Sym s, const char* what) {
    const Token& t = peek();
    if (!t.is(s)) fail(t, fmt::format("expected {}, found {}", what, describeToken(t)));
    next();
}

void Reader::expectAfter(Sym s, const char* symbol, std::string_view after) {
    const Token& t = peek();
    if (!t.is(s))
        fail(t, fmt::format("expected {} after '{}', found {}", symbol, after, describeToken(t)));
    next();
}

bool Reader::accept(Sym s) {
    if (!peek().is(s)) return false;
    next();
    return true;
}

bool Reader::accept(Keyword k) {
    if (!peek().is(k)) return false;
    next();
    return true;
}

std::string Reader::expectIdentifier() {
    const Token t = rawPeek();
    if (t.kind != TokenKind::Word)
        fail(t, fmt::format("expected an identifier, found {}", describeToken(t)));
    if (t.kw != Keyword::None)
        fail(t, fmt::format("'{}' is a reserved word and cannot be used as an identifier", t.text));
    ++cursors_.back().pos;
    return std::string(t.text);
}

}  // namespace frameray::sdl
