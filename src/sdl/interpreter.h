// The scene-language interpreter: one per frame, owning all parse state
// (DESIGN.md: nothing global, so frames can overlap). It reads tokens from
// the shared TokenCache, executes directives, macros and loops in the token
// stream, evaluates expressions and builds a scene::Scene.
//
// The implementation is split by concern:
//   interpreter.cpp    token stream, directives, scopes, include files
//   expressions.cpp    float/vector/colour/string expressions, built-ins
//   scene_parser.cpp   objects, camera, textures, global settings
//   parse_light.cpp    light sources
#pragma once

#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "scene/scene.h"
#include "scene/ttf_font.h"
#include "sdl/blend_map_value.h"
#include "sdl/diagnostics.h"
#include "sdl/frame_context.h"
#include "sdl/token_cache.h"
#include "sdl/value.h"

namespace frameray::scene {
struct MeshTriangle;
struct MeshCamera;
}
namespace frameray::image {
struct SourceImage;
}

namespace frameray::sdl {

struct MeshParts;       // parse_mesh.cpp
struct VectorFunction;  // function_value.h

// The vector component a dot item names: 0..4 for .x .y .z .t (and .u .v
// .red .green .blue .filter .transmit), kGrayItem for .gray (POV-Ray's
// luminance of the colour), -1 for anything else (expressions.cpp).
inline constexpr int kGrayItem = 5;
int dotItemSlot(Keyword kw);

class Interpreter {
  public:
    Interpreter(const FrameContext& frame, TokenCache& cache, MessageSink& messages);

    // Parses a scene file into a Scene. Throws SdlError on the first error.
    scene::Scene parseFile(const std::filesystem::path& sceneFile);
    // Parses scene text (tests, one-liners); `name` is used in messages.
    scene::Scene parseText(const std::string& name, const std::string& text);

    // Identifier lookup after parsing (tests).
    const Value* lookup(std::string_view name) const;
    // The same for an identifier token, with the lexer's hash.
    const Value* lookup(const Token& name) const {
        return name.nameHash ? lookupKey(HashedName{name.text, name.nameHash})
                             : lookupKey(name.text);
    }

  private:
    friend class FunctionCompiler;  // compiles function bodies from this token stream

    // --- token stream (interpreter.cpp) ---
    enum class CursorKind { File, Macro };
    struct Cursor {
        std::shared_ptr<const TokenizedFile> file;
        size_t pos = 0;
        CursorKind kind = CursorKind::File;
        size_t scopeCount = 0;  // scopes_ size to restore when it ends
        size_t blockCount = 0;  // blocks_ size to restore when it ends
        // True while a directive's own arguments are read from this cursor:
        // a '#' met then ends the argument instead of starting a directive
        // (the expression parser's one-token lookahead must not run the
        // next line's directive before this one is done).
        bool inDirective = false;
        // Where the #include or the macro call that opened this cursor
        // stands, and the macro's name, for the chain in diagnostics.
        SourceLoc callSite{};
        std::string macroName{};
    };
    // Where peek() last resolved the stream to a plain token, so repeated
    // peeks at the same place (every precedence level looks) skip the
    // directive and macro checks.
    struct PeekCache {
        const TokenizedFile* file = nullptr;
        size_t pos = 0;
        size_t depth = 0;
        // For an identifier: what it names (nullptr if undeclared), so the
        // caller that consumes it need not look it up again.
        const Value* identifier = nullptr;
    } peekCache_;
    enum class BlockKind { If, While, For, Switch, Macro };
    struct Block {
        Block() = default;
        Block(BlockKind k, const SourceLoc& l) : kind(k), loc(l) {}
        BlockKind kind = BlockKind::If;
        SourceLoc loc;
        size_t restartPos = 0;  // While: the '#' of the directive; For: after the header
        std::string loopVar;    // For
        double loopEnd = 0, loopStep = 1;
        double switchValue = 0;  // Switch
        bool elseTaken = false;  // If: running its #else branch (a second #else is an error)
    };
    // Heterogeneous lookup: identifiers are looked up by the string_view of
    // their token, without building a std::string each time.
    // A token's identifier with the hash the lexer computed for it.
    struct HashedName {
        std::string_view text;
        uint32_t hash;
    };
    struct NameHash {
        using is_transparent = void;
        size_t operator()(std::string_view s) const { return identifierHash(s); }
        size_t operator()(const HashedName& n) const { return n.hash; }
    };
    struct NameEqual {
        using is_transparent = void;
        bool operator()(std::string_view a, std::string_view b) const { return a == b; }
        bool operator()(const HashedName& a, std::string_view b) const { return a.text == b; }
        bool operator()(std::string_view a, const HashedName& b) const { return a == b.text; }
    };
    using Scope = std::unordered_map<std::string, Value, NameHash, NameEqual>;
    template <typename Key>
    const Value* lookupKey(const Key& key) const;

    scene::Scene run(std::shared_ptr<const TokenizedFile> file);

    // Current token, no directive processing; the end of an include file
    // or macro body is handled out of line (rawPeekAtEnd).
    const Token& rawPeek() {
        const Cursor& c = cursors_.back();
        const Token& t = c.file->tokens[c.pos];
        if (t.kind != TokenKind::End) [[likely]]
            return t;
        return rawPeekAtEnd();
    }
    const Token& rawPeekAtEnd();
    const Token& peekAfterOperand();
    // Where a #declare's value is being read (cursor depth, -1: none) and
    // how many parentheses, vector brackets or argument lists are open in
    // it: see peekAfterOperand.
    struct DeclareValueState {
        int cursorDepth = -1;
        int grouping = 0;
    };
    DeclareValueState declareValue_;
    struct GroupingGuard {
        explicit GroupingGuard(Interpreter& in) : in_(in) { ++in_.declareValue_.grouping; }
        ~GroupingGuard() { --in_.declareValue_.grouping; }
        GroupingGuard(const GroupingGuard&) = delete;
        GroupingGuard& operator=(const GroupingGuard&) = delete;
        Interpreter& in_;
    };
    // Current token after directives/macros; the fast path answers repeated
    // peeks at the same place.
    const Token& peek() {
        const Cursor& c = cursors_.back();
        if (peekCache_.file == c.file.get() && peekCache_.pos == c.pos &&
            peekCache_.depth == cursors_.size())
            return c.file->tokens[c.pos];
        return resolvePeek();
    }
    const Token& resolvePeek();
    Token next();  // consume peek()
    SourceLoc loc(const Token& t) const;
    SourceLoc here();  // location of peek()
    [[noreturn]] void fail(const Token& at, const std::string& message);
    // --- diagnostics (suggestions.cpp) ---
    // `message` with "; did you mean 'x'?" added when it names `at`, an
    // undeclared identifier that is one or two edits from a keyword or a
    // declared identifier.
    std::string withSpellingSuggestion(const Token& at, const std::string& message) const;
    // The includes and macro calls that lead to `loc`, innermost first,
    // as diagnostic notes.
    std::vector<std::string> includeChain(const SourceLoc& loc) const;
    [[noreturn]] void failHere(const std::string& message);
    void warn(const Token& at, const std::string& message);
    [[noreturn]] void unsupported(const Token& at, const std::string& feature);

    void expect(Sym s, const char* what);
    // expect() whose message names what came before ("'(' after 'sqrt'"),
    // formatted only when the symbol is missing.
    void expectAfter(Sym s, const char* symbol, std::string_view after);
    bool accept(Sym s);
    bool accept(Keyword k);
    std::string expectIdentifier();

    void runDirective();  // at '#'
    void directiveDeclare(bool local);
    Value parseRValue();                    // anything #declare or a macro argument accepts
    void acceptSemicolonBeforeDirective();  // the optional ';' ending a declaration
    void directiveInclude(const Token& at);
    void directiveIf(const Token& at, bool (Interpreter::*condition)());
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
    // #case/#range/#break) of the current nesting level. Returns the
    // directive keyword found, leaving the cursor after it.
    Keyword skipBranch(bool stopAtElse, bool stopAtCase);
    void invokeMacro(const Token& nameToken, const Macro& macro);
    Value bareIdentifierArgument();  // monostate when the argument is not one
    std::filesystem::path findIncludeFile(const std::string& name) const;
    // Fails at `at` when the frame's FileAccessPolicy refuses the file, or
    // when it is no regular file (file_io.cpp); `name` is how the scene
    // named it.
    void checkReadable(const std::filesystem::path& path, const std::string& name, const Token& at);
    void checkWritable(const std::filesystem::path& path, const std::string& name, const Token& at);

    // --- resource limits (interpreter.cpp; FrameContext::Limits) ---
    // Held while one nesting level (expression, object, texture, directive)
    // is parsed: past the limit, or close to the end of the thread's stack,
    // it throws an SdlError instead of letting the recursion overflow.
    class NestingGuard {
      public:
        NestingGuard(Interpreter& in, const Token& at) : in_(in) { in_.enterNesting(at); }
        ~NestingGuard() { --in_.nesting_; }
        NestingGuard(const NestingGuard&) = delete;
        NestingGuard& operator=(const NestingGuard&) = delete;

      private:
        Interpreter& in_;
    };
    void enterNesting(const Token& at);
    void countIteration(const SourceLoc& where);  // a loop iteration or macro call
    void chargeArrayElements(size_t count, const Token& at);
    void checkStringLength(size_t length, const Token& at);

    // --- identifiers ---
    Value* find(std::string_view name);
    // Binds name in the innermost of the first scopeCount scopes (#local) or
    // assigns or creates it as #declare does. `hash`: the name's
    // identifierHash when known (0: computed here).
    void declare(const std::string& name, Value value, bool local,
                 size_t scopeCount = std::numeric_limits<size_t>::max(), uint32_t hash = 0);

    // --- arrays (arrays.cpp) ---
    Value parseArrayDeclaration();
    void parseArrayInitializer(ArrayValue& array, size_t dim, size_t& next);
    size_t parseArrayIndex(const ArrayValue& array, const Token& at);  // reads [i][j]...
    void setArrayElement(ArrayValue& array, size_t index, Value value, const Token& at);

    // --- file I/O (file_io.cpp) ---
    void directiveFopen(const Token& at);
    void directiveFclose(const Token& at);
    void directiveRead(const Token& at);
    void directiveWrite(const Token& at);
    void closeAllFiles();

    // --- splines and user functions (splines.cpp, functions.cpp) ---
    Value parseSpline();
    Value parseFunctionDeclaration();
    // `{ body }` of a function with these parameters (also height_field's).
    Value parseFunctionBody(std::vector<std::string> params);
    Value parseInternalFunctionBody();
    Value parsePatternFunctionBody();
    // `colourAsGray`: a pigment function gives its colour's gray, as a
    // height_field function does in povray (measured).
    std::shared_ptr<const CompiledFunction> parseXyzFunction(const Token& at,
                                                             bool colourAsGray = false);
    void skipToClosingBrace(const Token& from, int depth);
    Value callSpline(const SplineValue& spline, const Token& at);
    Value callFunction(const FunctionValue& function, const Token& at);
    Value callVectorFunction(const VectorFunction& function, const Token& at);
    // After `function {`: a pigment, transform or spline body.
    std::shared_ptr<const VectorFunction> parseVectorFunctionBody();

    // --- expressions (expressions.cpp) ---
    Value parseExpression();  // float, vector, colour or string
    double parseFloat();
    double parseParenthesizedFloat();  // ( full expression ): #if, #while, #switch, #case
    VectorValue parseVector();         // float promoted to <f,f,f>
    Vec3 parseVec3();
    Color parseColor();  // with optional color/colour keyword
    // Fails at `at` when one evaluation of `function` would run more than
    // the frame's limit of operations (functions.cpp).
    void checkFunctionCost(const CompiledFunction& function, const Token& at);
    std::string parseString();
    // A file name (#include, #fopen, image, height-field and font files): a
    // string expression whose literals keep their backslashes, as povray
    // reads them ("dir\\x.inc" is not an escape there).
    std::string parsePathname();
    bool pathnameMode_ = false;
    bool startsStringExpression(const Token& t);
    Value parseTernary();
    Value parseLogical();
    Value parseRelational();
    Value parseAdditive();
    Value parseMultiplicative();
    Value parseUnary();
    Value parsePostfix();
    Value parsePrimary();
    Value parseVectorLiteral();
    Value parseColorKeywords(const Token& first);
    Value parseBuiltinFunction(const Token& name);
    // `known` is what the identifier names when the caller already has it
    // (see PeekCache); looked up otherwise.
    Value identifierValue(const Token& name, const Value* known = nullptr);
    std::vector<Value> parseArguments(size_t min, size_t max, const Token& fn);
    double toFloat(const Value& v, const Token& at);
    VectorValue toVector(const Value& v, const Token& at, int size = 3);

    // --- scene statements (scene_parser.cpp) ---
    bool parseStatement();  // a top-level item; false at end of file
    bool isObjectStart(const Token& t) const;
    ObjectValue parseObject();  // sphere { }, box { }, object { }...
    bool parseObjectModifier(ObjectValue& obj, std::optional<scene::Texture>& texture);
    std::shared_ptr<const scene::Shape> parseShape(const Token& kind);  // after '{'
    // union/merge/... objects, and the lights among them.
    std::shared_ptr<const ObjectLights> parseCsgChildren(const Token& kind, scene::Object& csg);
    // light_group's lights and objects.
    std::shared_ptr<const ObjectLights> parseLightGroupMembers(scene::Object& group);
    // torus, poly, cubic, quartic, blob (parse_polynomial_shapes.cpp).
    std::shared_ptr<const scene::Shape> parsePolynomialShape(const Token& kind);
    std::shared_ptr<const scene::Shape> parseBlob();
    std::shared_ptr<const scene::Shape> parsePolygon(const Token& kind);  // parse_polygon.cpp
    // parse_julia_fractal.cpp
    std::shared_ptr<const scene::Shape> parseJuliaFractal(const Token& kind);
    std::vector<double> parseCoefficientVector(int count, const Token& kind);
    void applySturm(scene::Object& obj, const Token& at);  // after `sturm`
    // clipped_by { objects } / bounded_by { objects }, or the other list
    // when the block names `alternative`.
    std::vector<scene::ObjectRef> parseObjectList(
        const Token& modifier, Keyword alternative,
        const std::vector<scene::ObjectRef>& alternativeList);
    bool parseTransformation(Transform& transform);
    Transform parseTransformBlock();
    scene::Camera parseCamera();      // parse_camera.cpp
    // After 'mesh_camera': its block (parse_mesh_camera.cpp).
    std::shared_ptr<scene::MeshCamera> parseMeshCamera(const Token& at);
    scene::Light parseLightSource();  // parse_light.cpp
    void placeLight(scene::Light light);
    // Hands the light sources written inside a placed object's CSG nodes
    // to the scene, and a light_group's to the primitives of its group
    // (scene::LightGroup); returns the object with them settled.
    scene::ObjectRef placeObjectLights(const scene::ObjectRef& obj, const ObjectLights* lights,
                                       const std::shared_ptr<const scene::LightGroup>& group,
                                       const std::optional<bool>& outermostGlobal);
    TexturePtr parseTexture(const scene::Texture* base);
    PigmentPtr parsePigment();
    // Pattern keywords and their modifiers inside pigment { }; false when
    // the next token is none of them.
    bool parsePigmentPatternItem(scene::Pigment& pigment);
    PigmentPtr parsePigmentListEntry();  // a colour, pigment { } or pigment identifier
    scene::ColorMap parseColorMap();
    // --- patterns (pattern_parser.cpp) ---
    std::shared_ptr<const scene::Normal> parseNormal(const scene::Normal* base);  // normal { }
    void directiveDefault();
    void parseFractalHead(const Token& kind, scene::FractalSettings& f);
    void parseFractalItem(const Token& item, scene::FractalSettings& f);
    scene::NoiseGenerator parseNoiseGenerator(const Token& at);
    bool parseTurbulenceItem(scene::Turbulence& turb);  // turbulence, octaves, omega, lambda
    scene::Warp parseWarp();                            // after the warp keyword
    std::vector<scene::Pigment::MapEntry> parsePigmentMap();
    // Pigment items up to `closing` (not consumed): pigment { } and map entries.
    void parsePigmentBody(scene::Pigment& pigment, Sym closing);
    // A pattern keyword and its arguments (gradient's vector...), without
    // a colour list; isPatternKeyword tells whether `t` is one.
    bool isPatternKeyword(const Token& t) const;
    // `inNormal`: the pattern belongs to a normal (facets is allowed).
    void parsePatternKeyword(scene::Pigment& holder, bool inNormal = false);
    // The object pattern's list entries sit inside its braces: callers
    // call this after reading a list pattern's entries.
    void closeListPattern(const scene::Pattern& pattern);
    void parseSlopeArguments(scene::Pattern& pattern);   // after 'slope'
    void parsePavementItem(scene::PavementSettings& s);  // pavement modifiers
    void checkPavement(const scene::Pattern& pattern, const Token& at);
    std::shared_ptr<const scene::Normal> parseNormalBody(const scene::Normal* base, Sym closing);
    // --- texture bodies and maps (parse_texture_maps.cpp) ---
    void parseTextureBody(scene::Texture& tex, Sym closing);  // items up to `closing`
    // texture { } texture { }...: one layered texture, the first block
    // starting from `base` when given.
    scene::Texture parseLayeredTextures(const scene::Texture* base = nullptr,
                                        bool inDeclaration = false);
    bool parseTexturePatternItem(scene::Texture& tex, std::shared_ptr<scene::TextureMap>& draft);
    std::vector<scene::TextureMap::Entry> parseTextureMap();
    std::vector<scene::Normal::MapEntry> parseNormalMap();
    std::vector<scene::Normal::SlopeEntry> parseSlopeMap();
    Value parseBlendMapValue();  // a declared map
    // An entry's value, ending before a '<'; 1 when an average map's entry
    // leaves its weight out (`weightMayBeOmitted`: pigment, normal, texture maps).
    double parseMapValue(bool weightMayBeOmitted = false);

    // After a map's '{': a declared map of that kind (consumed), or null.
    const BlendMapValue* blendMapIdentifier(BlendMapValue::Kind kind);
    // --- finish and interior (parse_finish.cpp) ---
    FinishPtr parseFinish(const scene::Finish* base);
    void parseFinishItems(scene::Finish& finish);
    void parseReflectionBlock(scene::Finish& finish);
    void parseIridescence(scene::Finish& finish);
    InteriorPtr parseInterior(const scene::Interior* base);
    // media { } and density { } (parse_media.cpp).
    MediaPtr parseMedia();
    DensityPtr parseDensity();
    DensityPtr parseDensityBody(Sym closing);
    std::vector<scene::Pigment::MapEntry> parseDensityMap();
    // --- material (parse_material.cpp) ---
    MaterialPtr parseMaterial();
    // Whether the next token can start a float expression (for items whose
    // value is optional, such as `metallic` or `fresnel`).
    bool floatFollows();
    double parseOptionalFloat(double absent);
    void parseGlobalSettings();
    // --- radiosity (parse_radiosity.cpp), each at 'radiosity' ---
    void parseRadiositySettings(const Token& start);  // in global_settings, after the keyword
    void parseObjectRadiosity(scene::Object& obj);    // radiosity { importance } in an object
    // --- photons blocks (parse_photons.cpp), each after 'photons' ---
    void parseGlobalPhotons(scene::PhotonSettings& settings);
    void parseObjectPhotons(scene::ObjectPhotons& photons, const Token& keyword);
    void parseLightPhotons(scene::LightPhotons& photons);
    // --- atmosphere (parse_atmosphere.cpp) ---
    void parseBackground();
    scene::Fog parseFog();              // fog { }, also as a declared value
    scene::SkySphere parseSkySphere();  // sky_sphere { }, also as a declared value
    void parseRainbow();
    void addTransform(ObjectValue& obj, scene::Texture* texture, const Transform& t) const;

    // --- text objects (parse_text.cpp) ---
    void parseTextObject(scene::Object& obj);  // after 'text {'
    std::shared_ptr<scene::TtfFont> openFont(const std::string& name, const Token& at);
    std::u32string decodeTextString(const std::string& bytes, const Token& at);

    // --- meshes, height fields, bicubic patches (parse_mesh.cpp) ---
    void parseMesh(scene::Object& obj);                       // after 'mesh {'
    void parseMesh2(scene::Object& obj);                      // after 'mesh2 {'
    void parseHeightField(scene::Object& obj);                // after 'height_field {'
    std::shared_ptr<const scene::Shape> parseBicubicPatch();  // after 'bicubic_patch {'
    void parseMeshTriangleItems(MeshParts& parts, scene::MeshTriangle& tri);
    bool parseMeshSetting(MeshParts& parts);  // inside_vector, hierarchy
    void buildMeshObject(scene::Object& obj, MeshParts& parts);
    template <typename ReadItem>
    size_t parseMesh2List(const Token& kw, ReadItem readItem);
    bool parseOptionalBool();  // an optional boolean after a flag keyword; true when absent

    // --- superellipsoid, isosurface, lathe, sor, prism, sphere_sweep
    // (parse_sweep_shapes.cpp), each after its '{' ---
    std::shared_ptr<const scene::Shape> parseSuperellipsoid(const Token& kind);
    std::shared_ptr<const scene::Shape> parseIsosurface(const Token& kind);
    std::shared_ptr<const scene::Shape> parseParametric(const Token& kind);
    // contained_by { box { A, B } | sphere { C, R } } after 'contained_by'.
    void parseContainedBy(bool& sphere, Vec3& boxLo, Vec3& boxHi, Vec3& center, double& radius);
    std::shared_ptr<const scene::Shape> parseSphereSweep(const Token& kind);
    std::shared_ptr<const scene::Shape> parseLathe(const Token& kind);
    std::shared_ptr<const scene::Shape> parseSor(const Token& kind);
    std::shared_ptr<const scene::Shape> parsePrism(const Token& kind);
    // --- image maps (parse_image_map.cpp) ---
    // image_map / image_pattern in a pigment; false when the next token is
    // neither.
    bool parseImagePigmentItem(scene::Pigment& pigment);
    // bump_map into `normal`, or image_pattern into the pattern holder of
    // a normal being parsed; false when the next token is neither.
    bool parseImageNormalItem(scene::Normal& normal, scene::Pigment& holder);
    // The block after image_map, image_pattern, bump_map or material_map
    // (`keyword`); bump_size is stored through `bumpSize` when given, a
    // material_map's textures are appended to `materials`.
    std::shared_ptr<const scene::ImageMap> parseImageBlock(
        const Token& keyword, double* bumpSize,
        std::vector<std::shared_ptr<const scene::Texture>>* materials = nullptr);
    // `function W, H { f(x, y, z) }` in an image block: the samples as an
    // image.
    image::SourceImage functionSourceImage(const Token& at);
    // An image file found like an include file, read once per frame.
    const image::SourceImage& loadSourceImage(const std::string& name, const Token& at);

    FrameContext frame_;
    TokenCache& cache_;
    MessageSink& messages_;
    std::vector<Cursor> cursors_;
    std::vector<Scope> scopes_;
    std::vector<Block> blocks_;
    Token endToken_;
    scene::Scene scene_;
    double version_ = 3.7;
    bool versionSeen_ = false;
    // #default { texture | pigment | normal | finish }: where new textures,
    // pigments and finishes start, and what objects without a texture get.
    scene::Texture defaultTexture_;
    bool defaultTextureSet_ = false;
    // The component textures of the blob parseBlob just read, for
    // parseObject to attach (empty when no component has one).
    std::vector<std::shared_ptr<const scene::Texture>> blobComponentTextures_;
    bool declarationBeforeVersion_ = false;
    int includeDepth_ = 0;
    int nesting_ = 0;                   // NestingGuard levels held
    size_t iterations_ = 0;             // loop iterations and macro calls so far
    size_t arrayElementsMade_ = 0;      // elements of every array made so far
    const char* stackFloor_ = nullptr;  // lowest usable stack address (null: unknown)
    // Random number streams made by seed(); the float seed() returns is
    // the stream's index, as in POV-Ray.
    std::vector<uint32_t> randomStreams_;
    struct Deprecation {
        std::string message;
        bool once = false;
        bool warned = false;
    };
    std::unordered_map<std::string, Deprecation, NameHash, NameEqual> deprecated_;
    std::vector<FilePtr> openFiles_;  // closed at the end of the parse
    std::string inputFileName_;       // the scene file as named to the interpreter
    // Text objects: the global_settings charset in force, and the fonts
    // read so far, by the name the scene gave (this frame's only).
    scene::TextCharset textCharset_ = scene::TextCharset::Ascii;
    std::map<std::string, std::shared_ptr<scene::TtfFont>> fonts_;
    // Images read so far by their resolved path (this frame's only).
    std::map<std::string, std::shared_ptr<const image::SourceImage>> images_;
};

}  // namespace frameray::sdl
