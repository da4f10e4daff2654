// The statement builders: free functions that read one scene item through
// the Reader (reader.h) and return what they build. Those a keyword starts
// at the top level or in a #declare are registered in ONE table keyed by
// keyword (kBuilders in builders.cpp); the others are the pieces they
// share, declared here by group.
//
// Adding a builder:
//   1. Write it in its own file (or the file of its group) as a free
//      function `Value buildThing(BuildContext& c)` that starts at its
//      keyword (c.reader.peek()) and returns what it built; an object
//      kind is a ShapeBuilder (the shape after `kind {`) or an ObjectBody
//      (fills the object). Read tokens and values through `Reader& r =
//      c.reader` (peek, next, expect, accept, parseFloat, parseVec3,
//      parseColor, floatFollows, lookup, fail, warn, unsupported...);
//      share state only through BuildContext (build_context.h), never
//      through statics.
//   2. Declare it below if another file calls it.
//   3. Add its row to kBuilders: object(kw, shape|body) for an object
//      kind; value(kw, build [, place]) for what #declare accepts (place:
//      also a top-level statement, putting the value into c.scene);
//      statement(kw, build) for a top-level item only. A row without a
//      function reports `not supported yet: <keyword>`.
//   4. Items inside another item (an object modifier, a light_source or
//      global_settings item, a finish item) are cases of that item's
//      builder: parseObjectModifier (parse_object.cpp), parseLightSource
//      (parse_light.cpp), parseGlobalSettings (parse_global_settings.cpp).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "scene/camera.h"
#include "scene/normals.h"
#include "scene/texture.h"
#include "sdl/blend_map_value.h"
#include "sdl/build_context.h"
#include "sdl/value.h"
#include "sdl/value_builders.h"

namespace frameray::sdl {

// --- the table (builders.cpp) ---
using ShapeBuilder = std::shared_ptr<const scene::Shape> (*)(BuildContext& c, const Token& kind);
using ObjectBody = void (*)(BuildContext& c, const Token& kind, ObjectValue& object);
using ValueBuilder = Value (*)(BuildContext& c);
using Placer = void (*)(BuildContext& c, const Token& keyword, Value value);

enum class BuilderKind : uint8_t { Object, Value, Statement };

struct Builder {
    Keyword keyword = Keyword::None;
    BuilderKind kind = BuilderKind::Statement;
    ShapeBuilder shape = nullptr;  // Object: its shape, after '{'
    ObjectBody body = nullptr;     // Object: anything else it reads after '{'
    ValueBuilder build = nullptr;  // Value, Statement: from the keyword on
    Placer place = nullptr;        // Value: set when it is also a statement
};

// The builder of `kw`, or null.
const Builder* findBuilder(Keyword kw);
// Whether `t` starts an object (sphere, union, object...).
bool isObjectStart(const Token& t);
// One top-level item; false at the end of the scene file.
bool parseStatement(BuildContext& c);

// The reader's hooks (value_builders.h) over the table.
class SceneValueBuilders final : public ValueBuilders {
  public:
    explicit SceneValueBuilders(BuildContext& c) : c_(c) {}
    std::optional<Value> buildValue(const Token& keyword) override;
    void defaultDirective() override;
    Value patternFunction() override;
    bool sceneHasObjects() const override { return !c_.scene.objects.empty(); }

  private:
    BuildContext& c_;
};

// --- objects (parse_object.cpp) ---
ObjectValue parseObject(BuildContext& c);  // sphere { }, box { }, object { }...
// One object modifier into `object` and the texture its modifiers build;
// false when the next token is none.
bool parseObjectModifier(BuildContext& c, ObjectValue& object,
                         std::optional<scene::Texture>& texture);
// Puts a top-level object into the scene: the #default texture, what its
// CSG children inherit, and the lights written inside it.
void placeObject(BuildContext& c, const ObjectValue& object);
// The object kinds the table names (shapes: parse_basic_shapes.cpp,
// parse_polynomial_shapes.cpp, parse_sweep_shapes.cpp).
void parseCsgBody(BuildContext& c, const Token& kind, ObjectValue& csg);
void parseLightGroupBody(BuildContext& c, const Token& kind, ObjectValue& group);
void parseObjectCopyBody(BuildContext& c, const Token& kind, ObjectValue& object);
std::shared_ptr<const scene::Shape> parseSphere(BuildContext& c, const Token& kind);
std::shared_ptr<const scene::Shape> parseBox(BuildContext& c, const Token& kind);
std::shared_ptr<const scene::Shape> parsePlane(BuildContext& c, const Token& kind);
std::shared_ptr<const scene::Shape> parseCylinder(BuildContext& c, const Token& kind);
std::shared_ptr<const scene::Shape> parseCone(BuildContext& c, const Token& kind);
std::shared_ptr<const scene::Shape> parseDisc(BuildContext& c, const Token& kind);
std::shared_ptr<const scene::Shape> parseTriangle(BuildContext& c, const Token& kind);
std::shared_ptr<const scene::Shape> parseSmoothTriangle(BuildContext& c, const Token& kind);
std::shared_ptr<const scene::Shape> parseQuadric(BuildContext& c, const Token& kind);
std::shared_ptr<const scene::Shape> parsePolygon(BuildContext& c, const Token& kind);
std::shared_ptr<const scene::Shape> parseJuliaFractal(BuildContext& c, const Token& kind);
std::shared_ptr<const scene::Shape> parsePolynomialShape(BuildContext& c, const Token& kind);
void parseBlobBody(BuildContext& c, const Token& kind, ObjectValue& blob);
void applySturm(BuildContext& c, scene::Object& obj, const Token& at);  // after `sturm`
std::shared_ptr<const scene::Shape> parseSuperellipsoid(BuildContext& c, const Token& kind);
std::shared_ptr<const scene::Shape> parseIsosurface(BuildContext& c, const Token& kind);
std::shared_ptr<const scene::Shape> parseParametric(BuildContext& c, const Token& kind);
std::shared_ptr<const scene::Shape> parseSphereSweep(BuildContext& c, const Token& kind);
std::shared_ptr<const scene::Shape> parseLathe(BuildContext& c, const Token& kind);
std::shared_ptr<const scene::Shape> parseSor(BuildContext& c, const Token& kind);
std::shared_ptr<const scene::Shape> parsePrism(BuildContext& c, const Token& kind);
// text, mesh, mesh2, height_field (parse_text.cpp, parse_mesh.cpp).
void parseTextBody(BuildContext& c, const Token& kind, ObjectValue& text);
void parseMeshBody(BuildContext& c, const Token& kind, ObjectValue& mesh);
void parseMesh2Body(BuildContext& c, const Token& kind, ObjectValue& mesh);
void parseHeightFieldBody(BuildContext& c, const Token& kind, ObjectValue& field);
std::shared_ptr<const scene::Shape> parseBicubicPatch(BuildContext& c, const Token& kind);

// --- lights, camera, atmosphere, global settings ---
scene::Light parseLightSource(BuildContext& c);  // parse_light.cpp
void placeLight(BuildContext& c, scene::Light light);
scene::Camera parseCamera(BuildContext& c);  // parse_camera.cpp
// After 'mesh_camera': its block (parse_mesh_camera.cpp).
std::shared_ptr<scene::MeshCamera> parseMeshCamera(BuildContext& c, const Token& at);
void parseBackground(BuildContext& c);  // parse_atmosphere.cpp
scene::Fog parseFog(BuildContext& c);
scene::SkySphere parseSkySphere(BuildContext& c);
void parseRainbow(BuildContext& c);
void parseGlobalSettings(BuildContext& c);  // parse_global_settings.cpp
// radiosity (parse_radiosity.cpp): the global_settings block, after the
// keyword (`start`), and an object's radiosity { importance }, at the keyword.
void parseRadiositySettings(BuildContext& c, const Token& start);
void parseObjectRadiosity(BuildContext& c, scene::Object& obj);
// photons blocks (parse_photons.cpp), each after 'photons': global_settings',
// an object's (`keyword`: where it stands) and a light's.
void parseGlobalPhotons(BuildContext& c, scene::PhotonSettings& settings);
void parseObjectPhotons(BuildContext& c, scene::ObjectPhotons& photons, const Token& keyword);
void parseLightPhotons(BuildContext& c, scene::LightPhotons& photons);

// --- textures (parse_texture_maps.cpp, parse_finish.cpp, parse_material.cpp) ---
TexturePtr parseTexture(BuildContext& c, const scene::Texture* base);
// texture { } texture { }...: one layered texture, the first block
// starting from `base` when given.
scene::Texture parseLayeredTextures(BuildContext& c, const scene::Texture* base = nullptr,
                                    bool inDeclaration = false);
Value parseBlendMapValue(BuildContext& c);  // a declared map
// An entry's value, ending before a '<'; 1 when an average map's entry
// leaves its weight out (`weightMayBeOmitted`: pigment, normal, texture maps).
double parseMapValue(BuildContext& c, bool weightMayBeOmitted = false);
// After a map's '{': a declared map of that kind (consumed), or null.
const BlendMapValue* blendMapIdentifier(BuildContext& c, BlendMapValue::Kind kind);
std::vector<scene::Normal::MapEntry> parseNormalMap(BuildContext& c);
std::vector<scene::Normal::SlopeEntry> parseSlopeMap(BuildContext& c);
void parseDefaultDirective(BuildContext& c);  // #default { }, after `#default`
FinishPtr parseFinish(BuildContext& c, const scene::Finish* base);
InteriorPtr parseInterior(BuildContext& c, const scene::Interior* base);
MaterialPtr parseMaterial(BuildContext& c);
// media { } and density { } (parse_media.cpp), each at its keyword.
MediaPtr parseMedia(BuildContext& c);
DensityPtr parseDensity(BuildContext& c);

// --- pigments, patterns, normals (pattern_parser.cpp, parse_image_map.cpp) ---
// pigment { }; inside a texture or object it edits the pigment there (base).
PigmentPtr parsePigment(BuildContext& c, const scene::Pigment* base = nullptr);
// pigment { } and normal { } editing those of `tex`, in the space the
// texture's transformations lead to (texture_items.cpp).
PigmentPtr parseTexturePigment(BuildContext& c, const scene::Texture& tex);
std::shared_ptr<const scene::Normal> parseTextureNormal(BuildContext& c, const scene::Texture& tex);
// Pattern keywords and their modifiers inside pigment { }; false when
// the next token is none of them.
bool parsePigmentPatternItem(BuildContext& c, scene::Pigment& pigment);
scene::ColorMap parseColorMap(BuildContext& c);
std::vector<scene::Pigment::MapEntry> parsePigmentMap(BuildContext& c);
// A pattern keyword and its arguments (gradient's vector...), without a
// colour list; `inNormal`: the pattern belongs to a normal (facets).
bool isPatternKeyword(const Token& t);
void parsePatternKeyword(BuildContext& c, scene::Pattern& pattern, bool inNormal = false);
// The object pattern's list entries sit inside its braces: callers call
// this after reading a list pattern's entries.
void closeListPattern(BuildContext& c, const scene::Pattern& pattern);
// After 'noise_generator': its number (1 or 2; 3 stops as not supported).
scene::NoiseGenerator parseNoiseGenerator(BuildContext& c, const Token& at);
bool parseTurbulenceItem(BuildContext& c, scene::Turbulence& turb);  // turbulence, octaves...
// One modifier of a pattern (waves, frequency, phase, turbulence, warps,
// the settings of brick, crackle, facets, fractals, pavement...), the same
// wherever the pattern is used; false when the next token is none.
bool parsePatternModifier(BuildContext& c, scene::Pattern& pattern);
// normal { }; `settings` (when given) receives the block's settings even
// when it names no pattern (#default { normal { bump_size 2 } }).
std::shared_ptr<const scene::Normal> parseNormal(BuildContext& c, const scene::Normal* base,
                                                 scene::Normal* settings = nullptr);
std::shared_ptr<const scene::Normal> parseNormalBody(BuildContext& c, const scene::Normal* base,
                                                     Sym closing,
                                                     scene::Normal* settings = nullptr);
Value parsePatternFunction(BuildContext& c);  // function { pattern { } }, at `pattern`
// image_map / image_pattern in a pigment; false when the next token is
// neither.
bool parseImagePigmentItem(BuildContext& c, scene::Pigment& pigment);
// image_pattern into `pattern` (a pigment's, a normal's, a texture
// map's); false when the next token is not image_pattern.
bool parseImagePatternItem(BuildContext& c, scene::Pattern& pattern);
// bump_map into `normal`, or image_pattern into the pattern of a normal
// being parsed; false when the next token is neither.
bool parseImageNormalItem(BuildContext& c, scene::Normal& normal, scene::Pattern& pattern);
// The block after image_map, image_pattern, bump_map or material_map
// (`keyword`); bump_size is stored through `bumpSize` when given, a
// material_map's textures are appended to `materials`.
std::shared_ptr<const scene::ImageMap> parseImageBlock(
    BuildContext& c, const Token& keyword, double* bumpSize,
    std::vector<std::shared_ptr<const scene::Texture>>* materials = nullptr);
// An image file found like an include file, read once per frame.
const image::SourceImage& loadSourceImage(BuildContext& c, const std::string& name,
                                          const Token& at);

}  // namespace frameray::sdl
