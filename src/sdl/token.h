// Tokens of the scene language. A tokenized file is immutable and shared
// between frames through the TokenCache, so tokens refer to text by view.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "sdl/keywords.h"
#include "sdl/source.h"
#include "util/huge_page_allocator.h"

namespace frameray::sdl {

enum class TokenKind : uint8_t { Word, Number, String, Symbol, End };

enum class Sym : uint8_t {
    None,
    LBrace,
    RBrace,
    LParen,
    RParen,
    Less,
    Greater,
    LBracket,
    RBracket,
    Comma,
    Semicolon,
    Dot,
    Plus,
    Minus,
    Star,
    Slash,
    Equal,
    Bang,
    Question,
    Colon,
    Amp,
    Bar,
    Hash,
    LessEq,
    GreaterEq,
    NotEq,
};

// The hash symbol tables use for an identifier's name; never 0.
inline uint32_t identifierHash(std::string_view name) {
    return static_cast<uint32_t>(std::hash<std::string_view>{}(name)) | 1u;
}

// A token's text: a view as a pointer and a 32-bit length, 12 bytes
// without padding (a std::string_view takes 16), so that Token fits in 32
// (issue 23). Reads as a std::string_view.
#pragma pack(push, 1)
class TokenText {
  public:
    TokenText() = default;
    TokenText(std::string_view s)  // NOLINT(google-explicit-constructor)
        : data_(s.data()), size_(static_cast<uint32_t>(s.size())) {}
    operator std::string_view() const { return {data_, size_}; }  // NOLINT
    std::string_view view() const { return {data_, size_}; }

    const char* data() const { return data_; }
    size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    const char* begin() const { return data_; }
    const char* end() const { return data_ + size_; }
    size_t find(std::string_view s, size_t from = 0) const { return view().find(s, from); }
    size_t find(char c, size_t from = 0) const { return view().find(c, from); }
    friend bool operator==(const TokenText& a, std::string_view b) { return a.view() == b; }

  private:
    const char* data_ = nullptr;
    uint32_t size_ = 0;
};
#pragma pack(pop)
static_assert(sizeof(TokenText) == 12);

// 32 bytes: an exported mesh file is tens of millions of tokens, all kept
// (loops and macros jump back), so every byte here is tens of MB there.
struct Token {
    TokenText text;  // Word spelling, String contents (escapes decoded), Number as written
    uint32_t line = 0, column = 0;
    TokenKind kind : 7 = TokenKind::End;
    // String: holds an escape the language does not define ("\\q"). An
    // error in a string expression, as in povray; file names take the
    // string's raw text, where backslashes are no escapes (see rawString).
    bool unknownEscape : 1 = false;
    Sym sym = Sym::None;         // for Symbol
    Keyword kw = Keyword::None;  // for Word: the reserved word, or None for an identifier
    union {
        double number = 0;  // for Number
        // Word identifiers: identifierHash(text), computed once by the
        // lexer so symbol lookups do not hash the name again (0: not
        // computed). A Number's value shares these bytes: read it for
        // Words only (SymbolTable::lookup checks the kind).
        uint32_t nameHash;
    };

    bool is(Sym s) const { return kind == TokenKind::Symbol && sym == s; }
    bool is(Keyword k) const { return kind == TokenKind::Word && kw == k; }
    bool isIdentifier() const { return kind == TokenKind::Word && kw == Keyword::None; }
};
static_assert(sizeof(Token) == 32);

// One lexed file: its source and its tokens, ending with an End token.
//
// A large file (kCompactFrom bytes or more: exported meshes, tens of
// millions of tokens) does not keep every token (issue 23): its tokens are
// counted in chunks of kChunkTokens, and a chunk is kept only when it holds
// a String (whose decoded text has no other home) or the End token. The
// other chunks keep where their lexing starts and are lexed again when
// read (relex; the Reader's TokenWindow holds the last few). Positions are
// the same either way: token `pos` is in chunk pos / kChunkTokens.
struct TokenizedFile {
    static constexpr size_t kChunkTokens = 64;
    static constexpr size_t kCompactFrom = size_t{4} << 20;
    static constexpr uint32_t kNotKept = ~uint32_t{0};

    // Where a chunk's lexing starts (before the space ahead of its first
    // token) and, when kept, the index in `tokens` of its first token.
    struct Chunk {
        size_t offset = 0;
        uint32_t line = 1, column = 1;
        uint32_t kept = kNotKept;
    };

    std::shared_ptr<const SourceFile> source;
    // All the tokens; for a large file, those of its kept chunks only.
    std::vector<Token, HugePageAllocator<Token>> tokens;
    std::deque<std::string> decodedStrings;  // storage for String token text
    std::vector<Chunk> chunks;               // empty: every token is in `tokens`
    size_t tokenCount = 0;                   // End included

    // How many tokens the file has, End included.
    size_t size() const { return chunks.empty() ? tokens.size() : tokenCount; }
    // Lexes chunk `chunk` (one that is not kept) again into `out`, which
    // has room for kChunkTokens; returns how many it wrote.
    size_t relex(size_t chunk, Token* out) const;

    SourceLoc locOf(const Token& t) const { return {source.get(), t.line, t.column}; }
    // A String token's text as written between its quotes, escapes not
    // decoded: povray reads file names (#include, #fopen, image and font
    // files) this way, so "dir\\x.inc" names a file with a backslash.
    std::string rawString(const Token& t) const;
    // The 1-based column of the first escape a String token holds that the
    // language does not define (0 when there is none).
    uint32_t unknownEscapeColumn(const Token& t) const;
};

// Describes a token for messages: "'{'", "identifier 'Foo'", "end of file"...
std::string describeToken(const Token& t);

}  // namespace frameray::sdl
