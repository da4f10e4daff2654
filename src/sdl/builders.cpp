// The table of statement builders (builders.h): every keyword that starts
// an object, a value #declare accepts, or a top-level statement, with the
// free function that reads it. parseStatement and the reader's hooks
// (SceneValueBuilders) dispatch through it.
#include "sdl/builders.h"

#include <fmt/format.h>

#include <array>

namespace frameray::sdl {

namespace {

constexpr Builder object(Keyword kw, ShapeBuilder shape) {
    return {kw, BuilderKind::Object, shape, nullptr, nullptr, nullptr};
}
constexpr Builder object(Keyword kw, ObjectBody body) {
    return {kw, BuilderKind::Object, nullptr, body, nullptr, nullptr};
}
constexpr Builder value(Keyword kw, ValueBuilder build, Placer place = nullptr) {
    return {kw, BuilderKind::Value, nullptr, nullptr, build, place};
}
constexpr Builder statement(Keyword kw, ValueBuilder build) {
    return {kw, BuilderKind::Statement, nullptr, nullptr, build, nullptr};
}
// A keyword povray has and frameray does not build yet: `not supported yet`.
constexpr Builder unsupportedObject(Keyword kw) {
    return {kw, BuilderKind::Object, nullptr, nullptr, nullptr, nullptr};
}
constexpr Builder unsupportedStatement(Keyword kw) {
    return statement(kw, nullptr);
}

// Statements that change the scene themselves give back nothing.
template <void (*Parse)(BuildContext&)>
Value sceneStatement(BuildContext& c) {
    Parse(c);
    return {};
}

Value buildDefault(BuildContext& c) {
    c.reader.next();  // default
    parseDefaultDirective(c);
    return {};
}
Value buildPigment(BuildContext& c) {
    return parsePigment(c);
}
Value buildFinish(BuildContext& c) {
    return parseFinish(c, nullptr);
}
Value buildInterior(BuildContext& c) {
    return parseInterior(c, nullptr);
}
Value buildMaterial(BuildContext& c) {
    return parseMaterial(c);
}
Value buildTexture(BuildContext& c) {
    // In a #declare the layers' look-ahead must not run the next directive.
    return std::make_shared<const scene::Texture>(parseLayeredTextures(c, nullptr, true));
}
Value buildNormal(BuildContext& c) {
    return NormalPtr(parseNormal(c, nullptr));
}
Value buildMedia(BuildContext& c) {
    return parseMedia(c);
}
Value buildDensity(BuildContext& c) {
    return parseDensity(c);
}
Value buildCamera(BuildContext& c) {
    return std::make_shared<const scene::Camera>(parseCamera(c));
}
Value buildLight(BuildContext& c) {
    return std::make_shared<const scene::Light>(parseLightSource(c));
}
Value buildFog(BuildContext& c) {
    return std::make_shared<const scene::Fog>(parseFog(c));
}
Value buildSkySphere(BuildContext& c) {
    return std::make_shared<const scene::SkySphere>(parseSkySphere(c));
}

void placeCamera(BuildContext& c, const Token&, Value v) {
    c.scene.camera = *std::get<CameraPtr>(v);
}
void placeLightValue(BuildContext& c, const Token&, Value v) {
    placeLight(c, *std::get<LightPtr>(v));
}
void placeFog(BuildContext& c, const Token&, Value v) {
    c.scene.atmosphere.fogs.push_back(*std::get<FogPtr>(v));
}
void placeMedia(BuildContext& c, const Token&, Value v) {
    c.scene.atmosphere.media.push_back(std::get<MediaPtr>(v));
}
void placeSkySphere(BuildContext& c, const Token& keyword, Value v) {
    if (c.scene.atmosphere.skySphere)
        c.reader.warn(keyword, "Only one sky-sphere allowed (last one will be used).");
    c.scene.atmosphere.skySphere = *std::get<SkySpherePtr>(v);
}

using K = Keyword;
// One row a line (clang-format would pack them).
// clang-format off
constexpr Builder kBuilders[] = {
    // Objects: the shape or body after '{' (the modifiers: parseObject).
    object(K::kw_sphere, parseSphere),
    object(K::kw_box, parseBox),
    object(K::kw_plane, parsePlane),
    object(K::kw_cylinder, parseCylinder),
    object(K::kw_cone, parseCone),
    object(K::kw_disc, parseDisc),
    object(K::kw_triangle, parseTriangle),
    object(K::kw_smooth_triangle, parseSmoothTriangle),
    object(K::kw_quadric, parseQuadric),
    object(K::kw_polygon, parsePolygon),  // parse_polygon.cpp
    object(K::kw_julia_fractal, parseJuliaFractal),  // parse_julia_fractal.cpp
    object(K::kw_torus, parsePolynomialShape),
    object(K::kw_poly, parsePolynomialShape),
    object(K::kw_cubic, parsePolynomialShape),
    object(K::kw_quartic, parsePolynomialShape),
    object(K::kw_blob, parseBlobBody),
    object(K::kw_lathe, parseLathe),
    object(K::kw_sor, parseSor),
    object(K::kw_prism, parsePrism),
    object(K::kw_superellipsoid, parseSuperellipsoid),
    object(K::kw_sphere_sweep, parseSphereSweep),
    object(K::kw_isosurface, parseIsosurface),
    object(K::kw_parametric, parseParametric),
    object(K::kw_mesh, parseMeshBody),
    object(K::kw_mesh2, parseMesh2Body),
    object(K::kw_height_field, parseHeightFieldBody),
    object(K::kw_bicubic_patch, parseBicubicPatch),
    object(K::kw_text, parseTextBody),
    object(K::kw_object, parseObjectCopyBody),
    object(K::kw_union, parseCsgBody),
    object(K::kw_merge, parseCsgBody),
    object(K::kw_intersection, parseCsgBody),
    object(K::kw_difference, parseCsgBody),
    object(K::kw_light_group, parseLightGroupBody),
    unsupportedObject(K::kw_ovus),
    // Values #declare accepts; those with a place function are also
    // top-level statements.
    value(K::kw_pigment, buildPigment),
    value(K::kw_finish, buildFinish),
    value(K::kw_interior, buildInterior),
    value(K::kw_material, buildMaterial),
    value(K::kw_texture, buildTexture),
    value(K::kw_normal, buildNormal),
    value(K::kw_color_map, parseBlendMapValue),
    value(K::kw_colour_map, parseBlendMapValue),
    value(K::kw_pigment_map, parseBlendMapValue),
    value(K::kw_normal_map, parseBlendMapValue),
    value(K::kw_slope_map, parseBlendMapValue),
    value(K::kw_texture_map, parseBlendMapValue),
    value(K::kw_camera, buildCamera, placeCamera),
    value(K::kw_light_source, buildLight, placeLightValue),
    value(K::kw_fog, buildFog, placeFog),
    value(K::kw_sky_sphere, buildSkySphere, placeSkySphere),
    value(K::kw_media, buildMedia, placeMedia),
    value(K::kw_density, buildDensity),
    // Top-level statements only.
    statement(K::kw_global_settings, sceneStatement<parseGlobalSettings>),
    statement(K::kw_background, sceneStatement<parseBackground>),
    statement(K::kw_rainbow, sceneStatement<parseRainbow>),
    statement(K::kw_default, buildDefault),  // povray takes `default { }` without '#'
    unsupportedStatement(K::kw_photons),
    unsupportedStatement(K::kw_radiosity),  // only in global_settings
};
// clang-format on

// The table by keyword, for constant-time look-up.
struct BuilderIndex {
    std::array<const Builder*, static_cast<size_t>(Keyword::Count)> byKeyword{};
    BuilderIndex() {
        for (const Builder& b : kBuilders) byKeyword[static_cast<size_t>(b.keyword)] = &b;
    }
};

}  // namespace

const Builder* findBuilder(Keyword kw) {
    static const BuilderIndex index;  // immutable once built
    return index.byKeyword[static_cast<size_t>(kw)];
}

bool isObjectStart(const Token& t) {
    if (t.kind != TokenKind::Word) return false;
    const Builder* b = findBuilder(t.kw);
    return b && b->kind == BuilderKind::Object;
}

bool parseStatement(BuildContext& c) {
    Reader& r = c.reader;
    const Token t = r.peek();
    if (t.kind == TokenKind::End) return false;
    const Builder* b = t.kind == TokenKind::Word ? findBuilder(t.kw) : nullptr;
    if (b && b->kind == BuilderKind::Object) {
        placeObject(c, parseObject(c));
        return true;
    }
    if (b && (b->kind == BuilderKind::Statement || b->place)) {
        if (!b->build) r.unsupported(t, std::string(t.text));
        Value built = b->build(c);
        if (b->place) b->place(c, t, std::move(built));
        return true;
    }
    if (t.is(Sym::Semicolon)) {  // stray semicolons are harmless
        r.next();
        return true;
    }
    r.fail(t, fmt::format("expected an object, camera, light_source or directive, found {}",
                          describeToken(t)));
}

std::optional<Value> SceneValueBuilders::buildValue(const Token& keyword) {
    const Builder* b = findBuilder(keyword.kw);
    if (!b || b->kind == BuilderKind::Statement) return std::nullopt;
    if (b->kind == BuilderKind::Object) return std::make_shared<const ObjectValue>(parseObject(c_));
    return b->build(c_);
}

void SceneValueBuilders::defaultDirective() {
    parseDefaultDirective(c_);
}

Value SceneValueBuilders::patternFunction() {
    return parsePatternFunction(c_);
}

}  // namespace frameray::sdl
