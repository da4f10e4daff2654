#include "sdl/lexer.h"

#include <gtest/gtest.h>

#include "sdl/diagnostics.h"
#include "sdl/symbol_table.h"

using namespace frameray::sdl;

namespace {
std::shared_ptr<const TokenizedFile> lex(const std::string& text) {
    return tokenize(std::make_shared<SourceFile>("t.pov", text));
}
}  // namespace

TEST(Lexer, WordsNumbersSymbols) {
    auto f = lex("sphere { <0, 1.5e1, .25>, Radius } // comment\n");
    const auto& t = f->tokens;
    ASSERT_EQ(t.size(), 13u);
    EXPECT_TRUE(t[0].is(Keyword::kw_sphere));
    EXPECT_TRUE(t[1].is(Sym::LBrace));
    EXPECT_TRUE(t[2].is(Sym::Less));
    EXPECT_EQ(t[5].number, 15.0);
    EXPECT_EQ(t[7].number, 0.25);
    EXPECT_TRUE(t[10].isIdentifier());
    EXPECT_EQ(t[10].text, "Radius");
    EXPECT_EQ(t[10].line, 1u);
    EXPECT_EQ(t[10].column, 27u);
    EXPECT_EQ(t.back().kind, TokenKind::End);
}

// 32 bytes a token (issue 23: a 1M-triangle mesh2 is ~17M of them, all
// kept): the text is a 12-byte view, a number and an identifier's hash
// share their bytes.
TEST(Lexer, CompactTokensKeepTextNumberAndHash) {
    static_assert(sizeof(Token) == 32);
    auto f = lex("1.25e3 Radius \"str\" pigment");
    const auto& t = f->tokens;
    ASSERT_EQ(t.size(), 5u);
    EXPECT_EQ(t[0].number, 1250.0);
    EXPECT_EQ(t[0].text, "1.25e3");
    EXPECT_EQ(t[1].nameHash, identifierHash("Radius"));
    EXPECT_EQ(t[1].text, "Radius");
    EXPECT_EQ(std::string_view(t[1].text).size(), 6u);
    EXPECT_EQ(t[2].text, "str");
    EXPECT_EQ(t[3].nameHash, 0u);  // a reserved word: no hash
}

// A number is never found as an identifier, whatever its value's bytes
// read as a hash.
TEST(Lexer, NumbersAreNoIdentifiersInLookups) {
    SymbolTable symbols;
    symbols.reset();  // the global scope
    // 0.1's low 32 bits are not 0: read as a hash they would miss.
    auto f = lex("0.1");
    symbols.declare("0.1", Value(1.0), false);
    ASSERT_NE(symbols.lookup(std::string_view("0.1")), nullptr);
    EXPECT_EQ(symbols.lookup(f->tokens[0]), symbols.lookup(std::string_view("0.1")));
}

TEST(Lexer, TwoCharacterOperators) {
    auto f = lex("a<=b>=c!=d");
    EXPECT_TRUE(f->tokens[1].is(Sym::LessEq));
    EXPECT_TRUE(f->tokens[3].is(Sym::GreaterEq));
    EXPECT_TRUE(f->tokens[5].is(Sym::NotEq));
}

TEST(Lexer, StringEscapes) {
    auto f = lex(R"("a\tb\n\"q\"\\\u00e9")");
    ASSERT_EQ(f->tokens[0].kind, TokenKind::String);
    EXPECT_EQ(f->tokens[0].text, "a\tb\n\"q\"\\\xC3\xA9");
}

TEST(Lexer, NestedBlockComments) {
    auto f = lex("/* outer /* inner */ still comment */ box");
    ASSERT_EQ(f->tokens.size(), 2u);
    EXPECT_TRUE(f->tokens[0].is(Keyword::kw_box));
}

TEST(Lexer, UnterminatedCommentReportsItsStart) {
    try {
        lex("box\n  /* never closed\n\n");
        FAIL() << "expected an error";
    } catch (const SdlError& e) {
        EXPECT_EQ(e.loc().line, 2u);
        EXPECT_EQ(e.loc().column, 3u);
        EXPECT_NE(std::string(e.what()).find("t.pov:2:3: error: unterminated comment"),
                  std::string::npos);
        EXPECT_NE(std::string(e.what()).find("^"), std::string::npos);
    }
}

TEST(Lexer, UnterminatedString) {
    EXPECT_THROW(lex("#debug \"abc\n"), SdlError);
}

TEST(Keywords, LookupIsExactAndSorted) {
    EXPECT_EQ(lookupKeyword("sphere"), Keyword::kw_sphere);
    EXPECT_EQ(lookupKeyword("Sphere"), Keyword::None);
    EXPECT_EQ(keywordName(Keyword::kw_look_at), "look_at");
}
