// Large files keep only the token chunks that hold a string or the end and
// lex the others again when read (issue 23: a 1M-triangle mesh2 is ~17M
// tokens). Reading them through a TokenWindow must give every token as a
// file that keeps them all does, and a parse the same messages.
#include "sdl/token_window.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "parse_support.h"
#include "sdl/lexer.h"

using namespace frameray;
using namespace frameray::sdl;

namespace {

// Numbers, words, strings, comments, symbols and line breaks of every
// kind, over many chunks.
std::string mixedText() {
    std::string s = "\xEF\xBB\xBF#version 3.7;\n";
    for (int i = 0; i < 400; ++i) {
        s += "<";
        s += std::to_string(i);
        s += ".5e-1,-";
        s += std::to_string(i * 7);
        s += ",.25>, Name_";
        s += std::to_string(i % 13);
        s += " /* c /* nested */ */ sphere";
        if (i % 37 == 0) {
            s += " \"str\\t";
            s += std::to_string(i);
            s += "\"\r\n";
        } else {
            s += i % 5 ? "\n" : "\r";
        }
        if (i % 11 == 0) s += "// line comment\n#if (1 <= 2 != 0) #end";
    }
    return s;
}

bool sameToken(const Token& a, const Token& b) {
    return a.kind == b.kind && a.text.view() == b.text.view() && a.line == b.line &&
           a.column == b.column && a.sym == b.sym && a.kw == b.kw &&
           a.unknownEscape == b.unknownEscape && std::memcmp(&a.number, &b.number, 8) == 0;
}

}  // namespace

TEST(TokenWindow, ChunksLexedAgainGiveEveryTokenAsAFileKeepingThemAll) {
    auto source = std::make_shared<SourceFile>("t.pov", mixedText());
    auto all = tokenize(source);  // small: every token kept
    auto compact = tokenize(source, 0);
    ASSERT_TRUE(all->chunks.empty());
    ASSERT_FALSE(compact->chunks.empty());
    ASSERT_EQ(compact->size(), all->tokens.size());
    // Most chunks are not kept; those with a string or the end are.
    EXPECT_LT(compact->tokens.size(), all->tokens.size() / 2);
    EXPECT_GT(compact->tokens.size(), 0u);
    EXPECT_EQ(compact->tokens.back().kind, TokenKind::End);

    TokenWindow window;
    // In order, backwards, and jumping across more chunks than the window holds.
    for (size_t i = 0; i < all->tokens.size(); ++i)
        ASSERT_TRUE(sameToken(window.at(compact, i), all->tokens[i])) << "token " << i;
    for (size_t i = all->tokens.size(); i-- > 0;)
        ASSERT_TRUE(sameToken(window.at(compact, i), all->tokens[i])) << "token " << i;
    for (size_t step = 0, i = 0; step < 5000; ++step, i = (i * 7919 + 13) % all->tokens.size())
        ASSERT_TRUE(sameToken(window.at(compact, i), all->tokens[i])) << "token " << i;
    // A reference survives reading from other chunks up to the window's size.
    const size_t chunk = TokenizedFile::kChunkTokens;
    const Token& first = window.at(compact, 1);
    const Token copy = first;
    for (size_t k = 1; k < TokenWindow::kSlots; ++k) window.at(compact, k * chunk + 1);
    EXPECT_TRUE(sameToken(first, copy));
}

namespace {

// A scene whose loops, macros and #if branches jump across chunks and
// whose warnings show values and positions.
std::string sceneText(bool padded, const std::string& tail = "") {
    std::string s =
        "#version 3.7;\n#declare Sum = 0;\n#macro Add(V) #declare Sum = Sum + V; #end\n";
    s += "#declare Data = array[300] {";
    for (int i = 0; i < 300; ++i) {
        if (i) s += ",";
        s += std::to_string(i);
        s += ".25";
    }
    s += "}\n";
    s += "#declare I = 0;\n#while (I < 300)\n  Add(Data[I] * <1, -2, 3>.y)\n";
    s += "  #if (mod(I, 97) = 0) #warning concat(\"at \", str(Sum, 0, 3)) #else #declare J = I; "
         "#end\n  #declare I = I + 1;\n#end\n";
    s += "#for (K, 0, 3) sphere { <K, -K, 1e1>, 0.5 translate x * Sum } #end\n";
    s += "#warning concat(\"sum \", str(Sum, 0, 6))\n" + tail;
    // After the scene, so that lines and columns stay the same.
    if (padded) s += "// " + std::string(TokenizedFile::kCompactFrom, 'x') + "\n";
    return s;
}

}  // namespace

TEST(TokenWindow, ALargeFileParsesAsTheSameSmallOne) {
    test_support::ParsedScene small(sceneText(false));
    test_support::ParsedScene large(sceneText(true));
    EXPECT_NE(small.sink.warnings.find("sum "), std::string::npos);
    EXPECT_EQ(large.sink.warnings, small.sink.warnings);
    EXPECT_EQ(large.scene.objects.size(), small.scene.objects.size());
    // An error inside a chunk lexed again names the same place.
    const std::string bad = "#declare Z = <1, 2, 3> + ;\n";
    const std::string error = test_support::parseErrorOf(sceneText(false, bad));
    EXPECT_NE(error.find("t.pov:"), std::string::npos) << error;
    EXPECT_EQ(test_support::parseErrorOf(sceneText(true, bad)), error);
}
