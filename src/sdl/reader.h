// The language core (DESIGN.md "The language core and the builders"): one
// Reader per frame owns the token stream with its include files, macro
// calls and loops, runs the directives, keeps the identifiers and evaluates
// expressions. Statement builders (builders.h) read scene items through its
// public interface; the values they make for #declare it asks of them
// through ValueBuilders (value_builders.h). Implementation: reader.cpp
// (tokens, limits, diagnostics), directives.cpp, expressions.cpp,
// transforms.cpp, arrays.cpp, splines.cpp, functions.cpp, file_io.cpp,
// suggestions.cpp.
#pragma once

#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scene/noise.h"
#include "scene/patterns.h"
#include "sdl/cursor.h"
#include "sdl/diagnostics.h"
#include "sdl/frame_context.h"
#include "sdl/symbol_table.h"
#include "sdl/token_cache.h"
#include "sdl/token_window.h"
#include "sdl/value.h"
#include "util/matrix.h"

namespace frameray::sdl {

struct VectorFunction;  // function_value.h

class ValueBuilders;  // value_builders.h

class Reader {
  public:
    Reader(const FrameContext& frame, TokenCache& cache, MessageSink& messages);
    void setBuilders(ValueBuilders* builders) { builders_ = builders; }

    // A file is read from begin() until atEnd(); end() checks that every
    // directive block is closed and closes the #fopen files.
    void begin(std::shared_ptr<const TokenizedFile> file, std::string inputFileName);
    void end();
    bool atEnd() { return peek().kind == TokenKind::End; }

    // --- tokens ---
    // The current token after directives and macro calls; repeated peeks
    // at the same place are answered from a cache.
    const Token& peek() {
        const Cursor& c = cursors_.back();
        if (peekCache_.file == c.file.get() && peekCache_.pos == c.pos &&
            peekCache_.depth == cursors_.size())
            return window_.at(c.file, c.pos);
        return resolvePeek();
    }
    Token next();  // consumes peek()
    // The current token without running a directive (a #declare's look-ahead).
    const Token& rawPeek() {
        const Cursor& c = cursors_.back();
        const Token& t = window_.at(c.file, c.pos);
        if (t.kind != TokenKind::End) [[likely]]
            return t;
        return rawPeekAtEnd();
    }
    bool accept(Sym s);
    bool accept(Keyword k);
    void expect(Sym s, const char* what);
    // expect() whose message names what came before ("'(' after 'sqrt'").
    void expectAfter(Sym s, const char* symbol, std::string_view after);
    std::string expectIdentifier();

    // --- values ---
    Value parseExpression();  // float, vector, colour or string
    double parseFloat();
    VectorValue parseVector();  // a float promoted to <f,f,f>
    Vec3 parseVec3();
    Color parseColor();  // with optional color/colour keyword
    std::string parseString();
    // A file name: a string whose literals keep their backslashes.
    std::string parsePathname();
    // Whether a float expression follows (povray's optional numbers: `bumps
    // [SIZE]`, `hollow [B]`...): a number, a sign, '(', '<', a numeric
    // built-in, or an identifier of a float, vector, function, spline, array.
    bool floatFollows();
    bool colorFollows();  // a float, vector or colour expression starts here
    double parseOptionalFloat(double absent);
    bool parseOptionalBool();  // after a flag keyword; true when absent
    double toFloat(const Value& v, const Token& at);
    VectorValue toVector(const Value& v, const Token& at, int size = 3);
    // A matrix value: '+' and '-' but no comparison (see parseExpression).
    Value parseAdditive();
    // translate, rotate, scale, matrix or transform; false when the next
    // token is none of them (transforms.cpp).
    bool parseTransformation(Transform& transform);
    Transform parseTransformBlock();  // at `transform`
    // `{ body }` of a function with these parameters.
    Value parseFunctionBody(std::vector<std::string> params);
    // A `function { ... }` of x, y, z that a shape or pattern evaluates;
    // `colourAsGray`: a pigment function gives its colour's gray, as a
    // height_field function does in povray (measured).
    std::shared_ptr<const CompiledFunction> parseXyzFunction(const Token& at,
                                                             bool colourAsGray = false);
    void skipToClosingBrace(const Token& from, int depth);

    // --- identifiers ---
    const Value* lookup(std::string_view name) const { return symbols_.lookup(name); }
    const Value* lookup(const Token& name) const { return symbols_.lookup(name); }
    // The value of the identifier `name` (consumed), indexed, called or
    // completed as an expression would (A[i], F(x), Colour red 1).
    Value identifierValue(const Token& name, const Value* known = nullptr);
    // The identifier at peek() when it holds a T: consumed, else null.
    template <typename T>
    const T* acceptIdentifier() {
        const Value* v = peek().isIdentifier() ? lookup(peek()) : nullptr;
        const T* held = v ? std::get_if<T>(v) : nullptr;
        if (held) next();
        return held;
    }

    // --- files ---
    std::filesystem::path findIncludeFile(const std::string& name) const;
    // Fails at `at` when the frame's FileAccessPolicy refuses the file.
    void checkReadable(const std::filesystem::path& path, const std::string& name, const Token& at);
    // Why findIncludeFile found nothing: a folder of that name, or where
    // it looked (file_io.cpp).
    std::string whyNotFound(const std::string& name) const;
    // The files this parse read (the scene, includes, images, fonts, #read
    // data: checkReadable records them) and wrote (#fopen write/append).
    void noteFileRead(const std::filesystem::path& path) { filesRead_.push_back(path); }
    // A file the renderer writes after the parse (photons save_file):
    // refused at `at` as #fopen write would be (a folder the policy
    // closes, a sharded run), else recorded with the files written. Its
    // absolute path.
    std::filesystem::path fileToWrite(const std::string& name, const Token& at);
    // A whole file a setting reads (photons load_file, `what` in
    // messages), found and opened as #fopen read does; fails at `at`.
    std::string readWholeFile(const std::string& name, const Token& at, std::string_view what);
    const std::vector<std::filesystem::path>& filesRead() const { return filesRead_; }
    const std::vector<std::filesystem::path>& filesWritten() const { return filesWritten_; }

    // --- diagnostics ---
    SourceLoc loc(const Token& t) const;
    SourceLoc here();  // location of peek()
    [[noreturn]] void fail(const Token& at, const std::string& message);
    [[noreturn]] void failHere(const std::string& message);
    void warn(const Token& at, const std::string& message);
    [[noreturn]] void unsupported(const Token& at, const std::string& feature);
    // The includes and macro calls that lead to `loc`, as notes.
    std::vector<std::string> includeChain(const SourceLoc& loc) const;

    // Held while one nesting level (expression, object, texture, directive)
    // is parsed: past the limit, or close to the end of the thread's stack,
    // it throws an SdlError instead of letting the recursion overflow.
    class NestingGuard {
      public:
        NestingGuard(Reader& r, const Token& at) : r_(r) { r_.enterNesting(at); }
        ~NestingGuard() { --r_.nesting_; }
        NestingGuard(const NestingGuard&) = delete;
        NestingGuard& operator=(const NestingGuard&) = delete;

      private:
        Reader& r_;
    };

    // --- the frame ---
    const FrameContext& frame() const { return frame_; }
    MessageSink& messages() { return messages_; }
    double version() const { return version_; }
    bool versionSeen() const { return versionSeen_; }
    bool declarationBeforeVersion() const { return declarationBeforeVersion_; }
    // assumed_gamma, which sRGB colours need (global_settings sets it).
    void setAssumedGamma(double gamma) { assumedGamma_ = gamma; }
    // global_settings' noise_generator, which patterns and f_noise3d take
    // as they are read. povray applies it to every pattern whatever the
    // order, so once one has taken it (noteNoiseGeneratorUse) a change
    // stops as not supported (setNoiseGenerator, at `at`).
    scene::NoiseGenerator noiseGenerator() const { return noiseGenerator_; }
    void noteNoiseGeneratorUse() { noiseGeneratorUsed_ = true; }
    void setNoiseGenerator(scene::NoiseGenerator g, const Token& at);
    // The sources of ripples and waves. povray applies global_settings'
    // number_of_waves to every such pattern whatever the order (measured),
    // so every pattern read shares this one set, which setNumberOfWaves
    // refills while the scene parses; frozen with the scene.
    std::shared_ptr<const scene::WaveSources> waveSources() const { return waveSources_; }
    void setNumberOfWaves(int count);
    // `function` as the scene uses it: every f_noise3d it calls bound to
    // the noise_generator in force now, which is then fixed.
    std::shared_ptr<const CompiledFunction> boundToNoise(
        const std::shared_ptr<const CompiledFunction>& function);

  private:
    friend class FunctionCompiler;  // compiles function bodies from this token stream

    // --- token stream (reader.cpp) ---
    const Token& rawPeekAtEnd();  // the end of an include file or macro body
    const Token& resolvePeek();
    const Token& peekAfterOperand();
    std::string withSpellingSuggestion(const Token& at, const std::string& message) const;
    void enterNesting(const Token& at);
    void countIteration(const SourceLoc& where);  // a loop iteration or macro call
    void chargeArrayElements(size_t count, const Token& at);
    void checkStringLength(size_t length, const Token& at);

    // --- directives (directives.cpp) ---
    void runDirective();  // at '#'
    void directiveDeclare(bool local);
    Value parseRValue();  // anything #declare or a macro argument accepts
    void acceptSemicolonBeforeDirective();
    void directiveInclude(const Token& at);
    void directiveIf(const Token& at, bool (Reader::*condition)());
    void directiveElse(const Token& at);
    void directiveEnd(const Token& at);
    void directiveWhile(const Token& at, size_t hashPos);
    void directiveFor(const Token& at);
    void directiveSwitch(const Token& at);
    void directiveBreak(const Token& at);
    void directiveMacro(const Token& at);
    void directiveMessage(Stream stream);
    bool conditionExpression();
    bool conditionIfdef();
    bool conditionIfndef();
    // Skips raw tokens to the matching #else/#elseif/#end (or, in a switch,
    // #case/#range/#break) of the current nesting level; returns the
    // directive found, leaving the cursor after it.
    Keyword skipBranch(bool stopAtElse, bool stopAtCase);
    void invokeMacro(const Token& nameToken, const Macro& macro);
    Value bareIdentifierArgument();  // monostate when the argument is not one
    void checkWritable(const std::filesystem::path& path, const std::string& name, const Token& at);
    void directiveFopen(const Token& at);  // file_io.cpp
    void directiveFclose(const Token& at);
    void directiveRead(const Token& at);
    void directiveWrite(const Token& at);
    void closeAllFiles();

    // --- expressions (expressions.cpp, arrays.cpp, splines.cpp, functions.cpp) ---
    double parseParenthesizedFloat();  // ( full expression ): #if, #while, #switch
    bool startsStringExpression(const Token& t);
    Value parseTernary();
    Value parseLogical();
    Value parseRelational();
    Value parseMultiplicative();
    Value parseUnary();
    Value parsePostfix();
    Value parsePrimary();
    Value parseVectorLiteral();
    Value parseColorKeywords(const Token& first);
    Value parseBuiltinFunction(const Token& name);
    double checkedArgument(const Token& fn, double a);            // povray's domain checks
    std::optional<Value> parseNumericBuiltin(const Token& name);  // nullopt: not one of them
    std::optional<Value> parseStringBuiltin(const Token& name);
    std::optional<Value> parseQueryBuiltin(const Token& name);
    std::vector<Value> parseArguments(size_t min, size_t max, const Token& fn);
    Value parseArrayDeclaration();
    void parseArrayInitializer(ArrayValue& array, size_t dim, size_t& next);
    size_t parseArrayIndex(const ArrayValue& array, const Token& at);  // reads [i][j]...
    void setArrayElement(ArrayValue& array, size_t index, Value value, const Token& at);
    Value parseSpline();
    Value callSpline(const SplineValue& spline, const Token& at);
    Value parseFunctionDeclaration();
    Value parseInternalFunctionBody();
    Value callFunction(const FunctionValue& function, const Token& at);
    Value callVectorFunction(const VectorFunction& function, const Token& at);
    std::shared_ptr<const VectorFunction> parseVectorFunctionBody();  // pigment, transform, spline
    void checkFunctionCost(const CompiledFunction& function, const Token& at);

    FrameContext frame_;
    TokenCache& cache_;
    MessageSink& messages_;
    ValueBuilders* builders_ = nullptr;
    std::vector<Cursor> cursors_;
    TokenWindow window_;  // the tokens of large files that are not kept
    std::vector<Block> blocks_;
    PeekCache peekCache_;
    DeclareValueState declareValue_;
    SymbolTable symbols_;
    Token endToken_;
    double version_ = 3.7;
    bool versionSeen_ = false;
    bool declarationBeforeVersion_ = false;
    std::optional<double> assumedGamma_;  // null until global_settings gives it
    scene::NoiseGenerator noiseGenerator_ = scene::NoiseGenerator::RangeCorrected;
    bool noiseGeneratorUsed_ = false;
    std::shared_ptr<scene::WaveSources> waveSources_ =
        std::make_shared<scene::WaveSources>(*scene::makeWaveSources(scene::kDefaultWaveCount));
    bool pathnameMode_ = false;  // string literals keep their backslashes
    int includeDepth_ = 0;
    int nesting_ = 0;                      // NestingGuard levels held
    size_t iterations_ = 0;                // loop iterations and macro calls so far
    size_t arrayElementsMade_ = 0;         // elements of every array made so far
    const char* stackFloor_ = nullptr;     // lowest usable stack address (null: unknown)
    std::vector<uint32_t> randomStreams_;  // seed()'s streams, by the number it returns
    // Files #fopen opened: closed at the end of the parse, or as soon as
    // no identifier holds them.
    std::vector<std::weak_ptr<FileHandle>> openFiles_;
    std::string inputFileName_;  // the scene file as named to the interpreter
    std::vector<std::filesystem::path> filesRead_, filesWritten_;
};

}  // namespace frameray::sdl
