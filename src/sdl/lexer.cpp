#include "sdl/lexer.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdlib>

#include "sdl/diagnostics.h"

namespace frameray::sdl {

std::string describeToken(const Token& t) {
    switch (t.kind) {
        case TokenKind::End:
            return "end of file";
        case TokenKind::Number:
            return fmt::format("number {}", t.number);
        case TokenKind::String:
            return fmt::format("string \"{}\"", t.text);
        case TokenKind::Word:
            return t.kw == Keyword::None ? fmt::format("identifier '{}'", t.text)
                                         : fmt::format("keyword '{}'", t.text);
        case TokenKind::Symbol:
            return fmt::format("'{}'", t.text);
    }
    return "token";
}

namespace {

bool isIdentStart(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool isIdentChar(char c) {
    return isIdentStart(c) || (c >= '0' && c <= '9');
}
bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

void appendUtf8(std::string& out, uint32_t cp) {
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xC0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
        out += static_cast<char>(0xE0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    }
}

// Symbols: two-character ones are listed first so they win.
struct SymbolSpelling {
    std::string_view text;
    Sym sym;
};
constexpr SymbolSpelling kSymbols[] = {
    {"<=", Sym::LessEq},   {">=", Sym::GreaterEq}, {"!=", Sym::NotEq},   {"{", Sym::LBrace},
    {"}", Sym::RBrace},    {"(", Sym::LParen},     {")", Sym::RParen},   {"<", Sym::Less},
    {">", Sym::Greater},   {"[", Sym::LBracket},   {"]", Sym::RBracket}, {",", Sym::Comma},
    {";", Sym::Semicolon}, {".", Sym::Dot},        {"+", Sym::Plus},     {"-", Sym::Minus},
    {"*", Sym::Star},      {"/", Sym::Slash},      {"=", Sym::Equal},    {"!", Sym::Bang},
    {"?", Sym::Question},  {":", Sym::Colon},      {"&", Sym::Amp},      {"|", Sym::Bar},
    {"#", Sym::Hash},
};

class Lexer {
  public:
    explicit Lexer(const SourceFile* source) : source_(source), text_(source->text()) {}

    // The whole file.
    std::shared_ptr<const TokenizedFile> run(std::shared_ptr<const SourceFile> file,
                                             size_t compactFrom) {
        auto out = std::make_shared<TokenizedFile>();
        out->source = std::move(file);
        strings_ = &out->decodedStrings;
        // A UTF-8 byte order mark at the very start is not part of the scene.
        if (text_.substr(0, 3) == "\xEF\xBB\xBF") advance(3);
        if (text_.size() < compactFrom) {
            // Big data files (exported meshes) hold about one token per 3-4
            // bytes (a minus sign is a token of its own). Reserving for one per 2
            // avoids re-copying a vector of hundreds of MB while it grows; pages
            // never written cost nothing.
            out->tokens.reserve(text_.size() / 2 + 16);
            while (lexNext(out->tokens.emplace_back())) {
            }
            return out;
        }
        // Large: lexed a chunk at a time, kept only where it must be.
        constexpr size_t kChunk = TokenizedFile::kChunkTokens;
        std::array<Token, kChunk> chunk;
        for (bool more = true; more;) {
            TokenizedFile::Chunk where{pos_, line_, column_};
            size_t n = 0;
            bool keep = false;
            while (more && n < kChunk) {
                more = lexNext(chunk[n]);
                keep = keep || chunk[n].kind == TokenKind::String || !more;
                ++n;
            }
            if (keep) {
                where.kept = static_cast<uint32_t>(out->tokens.size());
                out->tokens.insert(out->tokens.end(), chunk.begin(), chunk.begin() + n);
            }
            out->chunks.push_back(where);
            out->tokenCount += n;
        }
        out->tokens.shrink_to_fit();
        out->chunks.shrink_to_fit();
        return out;
    }

    // `count` tokens from `where` (none of them a String or the End: no
    // decoded text to store).
    void relex(const TokenizedFile::Chunk& where, Token* out, size_t count) {
        pos_ = where.offset;
        line_ = where.line;
        column_ = where.column;
        for (size_t i = 0; i < count; ++i) lexNext(out[i]);
    }

  private:
    // The next token into `t`; false when it is the End.
    bool lexNext(Token& t) {
        skipSpaceAndComments();
        t = Token{};
        t.line = line_;
        t.column = column_;
        if (pos_ >= text_.size()) {
            t.kind = TokenKind::End;
            // "found end of file" points just after the last token,
            // on a line that shows what is unfinished.
            if (anyToken_) {
                t.line = lastEndLine_;
                t.column = lastEndColumn_;
            }
            return false;
        }
        lexOne(t);
        anyToken_ = true;
        lastEndLine_ = line_;
        lastEndColumn_ = column_;
        return true;
    }

  private:
    [[noreturn]] void fail(uint32_t line, uint32_t column, const std::string& message) {
        throw SdlError({source_, line, column}, message);
    }

    void advance(size_t n = 1) {
        for (size_t i = 0; i < n && pos_ < text_.size(); ++i) {
            const char c = text_[pos_++];
            if (c == '\n' || (c == '\r' && (pos_ >= text_.size() || text_[pos_] != '\n'))) {
                ++line_;
                column_ = 1;
            } else if (c != '\r') {
                ++column_;
            }
        }
    }

    char peek(size_t ahead = 0) const {
        return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
    }

    void skipSpaceAndComments() {
        for (;;) {
            const char c = peek();
            if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v' ||
                c == '\x1a') {
                advance();
            } else if (c == '/' && peek(1) == '/') {
                while (pos_ < text_.size() && peek() != '\n' && peek() != '\r') advance();
            } else if (c == '/' && peek(1) == '*') {
                skipBlockComment();
            } else {
                return;
            }
        }
    }

    // Block comments nest, as in POV-Ray.
    void skipBlockComment() {
        const uint32_t line = line_, column = column_;
        int depth = 0;
        do {
            if (pos_ >= text_.size())
                fail(line, column, "unterminated comment: '/*' has no matching '*/'");
            if (peek() == '/' && peek(1) == '*') {
                ++depth;
                advance(2);
            } else if (peek() == '*' && peek(1) == '/') {
                --depth;
                advance(2);
            } else {
                advance();
            }
        } while (depth > 0);
    }

    void lexOne(Token& t) {
        const char c = peek();
        if (isIdentStart(c)) {
            const size_t begin = pos_;
            while (isIdentChar(peek())) advance();
            t.kind = TokenKind::Word;
            t.text = std::string_view(text_).substr(begin, pos_ - begin);
            t.kw = lookupKeyword(t.text);
            if (t.kw == Keyword::None) t.nameHash = identifierHash(t.text);
        } else if (isDigit(c) || (c == '.' && isDigit(peek(1)))) {
            lexNumber(t);
        } else if (c == '"') {
            lexString(t);
        } else {
            for (const auto& s : kSymbols) {
                if (text_.compare(pos_, s.text.size(), s.text) == 0) {
                    t.kind = TokenKind::Symbol;
                    t.sym = s.sym;
                    t.text = s.text;
                    advance(s.text.size());
                    return;
                }
            }
            fail(t.line, t.column,
                 fmt::format("unexpected character '{}'",
                             std::isprint(static_cast<unsigned char>(c))
                                 ? std::string(1, c)
                                 : fmt::format("\\x{:02x}", static_cast<unsigned char>(c))));
        }
    }

    void lexNumber(Token& t) {
        const size_t begin = pos_;
        while (isDigit(peek())) advance();
        if (peek() == '.' && !isIdentStart(peek(1))) {
            advance();
            while (isDigit(peek())) advance();
        }
        if ((peek() == 'e' || peek() == 'E') &&
            (isDigit(peek(1)) || ((peek(1) == '+' || peek(1) == '-') && isDigit(peek(2))))) {
            advance(2);
            while (isDigit(peek())) advance();
        }
        // "1.2.3" is a typo, not the number 1.2 followed by .3.
        if (peek() == '.' && isDigit(peek(1)) &&
            text_.substr(begin, pos_ - begin).find('.') != std::string_view::npos) {
            size_t end = pos_;
            while (end < text_.size() && (isDigit(text_[end]) || text_[end] == '.')) ++end;
            fail(t.line, t.column,
                 fmt::format("malformed number '{}': a second '.'",
                             text_.substr(begin, end - begin)));
        }
        t.kind = TokenKind::Number;
        t.text = std::string_view(text_).substr(begin, pos_ - begin);
        // Out of double's range: povray reads 1e400 as inf and 1e-400 as 0
        // (from_chars would leave the value unset).
        if (std::from_chars(t.text.data(), t.text.data() + t.text.size(), t.number).ec ==
            std::errc::result_out_of_range)
            t.number = std::strtod(std::string(t.text).c_str(), nullptr);
    }

    void lexString(Token& t) {
        const uint32_t line = line_, column = column_;
        advance();  // opening quote
        std::string value;
        for (;;) {
            // povray keeps a line break inside a string literal (shapes3.inc
            // has a #warning message over three lines): only the end of the
            // file leaves a string unclosed.
            if (pos_ >= text_.size())
                fail(line, column, "unterminated string: missing closing '\"'");
            const char c = peek();
            if (c == '"') {
                advance();
                break;
            }
            if (c != '\\') {
                value += c;
                advance();
                continue;
            }
            const char e = peek(1);
            advance(2);
            switch (e) {
                case 'a':
                    value += '\a';
                    break;
                case 'b':
                    value += '\b';
                    break;
                case 'f':
                    value += '\f';
                    break;
                case 'n':
                    value += '\n';
                    break;
                case 'r':
                    value += '\r';
                    break;
                case 't':
                    value += '\t';
                    break;
                case 'v':
                    value += '\v';
                    break;
                case '0':
                    value += '\0';
                    break;
                case '\\':
                    value += '\\';
                    break;
                case '\'':
                    value += '\'';
                    break;
                case '"':
                    value += '"';
                    break;
                case 'u': {
                    uint32_t cp = 0;
                    for (int i = 0; i < 4; ++i) {
                        const char h = peek();
                        int d = isDigit(h)               ? h - '0'
                                : (h >= 'a' && h <= 'f') ? h - 'a' + 10
                                : (h >= 'A' && h <= 'F') ? h - 'A' + 10
                                                         : -1;
                        if (d < 0) fail(line_, column_, "\\u escape needs four hexadecimal digits");
                        cp = cp * 16 + static_cast<uint32_t>(d);
                        advance();
                    }
                    appendUtf8(value, cp);
                    break;
                }
                default:
                    // Both characters kept; the interpreter reports the
                    // escape where the string is used as a string (file
                    // names take the raw text instead).
                    value += '\\';
                    value += e;
                    t.unknownEscape = true;
                    break;
            }
        }
        t.kind = TokenKind::String;
        strings_->push_back(std::move(value));
        t.text = std::string_view(strings_->back());
    }

    const SourceFile* source_;
    std::deque<std::string>* strings_ = nullptr;  // where String tokens' text goes
    std::string_view text_;
    size_t pos_ = 0;
    uint32_t line_ = 1, column_ = 1;
    uint32_t lastEndLine_ = 1, lastEndColumn_ = 1;  // just after the last token
    bool anyToken_ = false;
};

}  // namespace

namespace {

// The characters after a backslash that form an escape (lexString).
bool isKnownEscape(char e) {
    return std::string_view("abfnrtv0\\'\"u").find(e) != std::string_view::npos;
}

// The raw text of the string starting at the opening quote `open` of `line`.
std::string_view rawBetweenQuotes(std::string_view line, uint32_t open) {
    if (open == 0 || open > line.size()) return {};
    size_t end = open;  // index just after the opening quote
    while (end < line.size() && line[end] != '"') end += line[end] == '\\' ? 2 : 1;
    return line.substr(open, std::min(end, line.size()) - open);
}

}  // namespace

std::string TokenizedFile::rawString(const Token& t) const {
    if (t.kind != TokenKind::String) return std::string(t.text);
    return std::string(rawBetweenQuotes(source->lineText(static_cast<int>(t.line)), t.column));
}

uint32_t TokenizedFile::unknownEscapeColumn(const Token& t) const {
    if (t.kind != TokenKind::String || !t.unknownEscape) return 0;
    const std::string_view raw =
        rawBetweenQuotes(source->lineText(static_cast<int>(t.line)), t.column);
    for (size_t i = 0; i + 1 < raw.size(); ++i) {
        if (raw[i] != '\\') continue;
        if (!isKnownEscape(raw[i + 1])) return t.column + 1 + static_cast<uint32_t>(i);
        ++i;
    }
    return t.column;
}

size_t TokenizedFile::relex(size_t chunk, Token* out) const {
    const size_t count = std::min(kChunkTokens, tokenCount - chunk * kChunkTokens);
    Lexer(source.get()).relex(chunks[chunk], out, count);
    return count;
}

std::shared_ptr<const TokenizedFile> tokenize(std::shared_ptr<const SourceFile> source,
                                              size_t compactFrom) {
    const SourceFile* file = source.get();
    return Lexer(file).run(std::move(source), compactFrom);
}

}  // namespace frameray::sdl
