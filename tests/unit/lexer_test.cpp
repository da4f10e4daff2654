#include <gtest/gtest.h>

#include "sdl/diagnostics.h"
#include "sdl/lexer.h"

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
        EXPECT_NE(std::string(e.what()).find("t.pov:2:3: error: unterminated comment"), std::string::npos);
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
