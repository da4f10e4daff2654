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

// 40 bytes: an exported mesh file is tens of millions of tokens, all kept
// (loops and macros jump back), so every byte here is tens of MB there.
struct Token {
    TokenKind kind : 7 = TokenKind::End;
    // String: holds an escape the language does not define ("\\q"). An
    // error in a string expression, as in povray; file names take the
    // string's raw text, where backslashes are no escapes (see rawString).
    bool unknownEscape : 1 = false;
    Sym sym = Sym::None;         // for Symbol
    Keyword kw = Keyword::None;  // for Word: the reserved word, or None for an identifier
    uint32_t line = 0, column = 0;
    // Word identifiers: identifierHash(text), computed once by the lexer so
    // symbol lookups do not hash the name again (0: not computed).
    uint32_t nameHash = 0;
    std::string_view text;  // Word spelling, String contents (escapes decoded)
    double number = 0;      // for Number

    bool is(Sym s) const { return kind == TokenKind::Symbol && sym == s; }
    bool is(Keyword k) const { return kind == TokenKind::Word && kw == k; }
    bool isIdentifier() const { return kind == TokenKind::Word && kw == Keyword::None; }
};

static_assert(sizeof(Token) == 40);

// One lexed file: its source and its tokens, ending with an End token.

struct TokenizedFile {
    std::shared_ptr<const SourceFile> source;
    std::vector<Token, HugePageAllocator<Token>> tokens;
    std::deque<std::string> decodedStrings;  // storage for String token text

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
