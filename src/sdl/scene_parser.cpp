// Scene statements: objects and their modifiers, camera, lights, textures,
// global settings. Builds scene:: values from the token stream.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "scene/csg.h"
#include "scene/flat_shapes.h"
#include "scene/quadric.h"
#include "scene/revolved_shapes.h"
#include "sdl/interpreter.h"

namespace frameray::sdl {

namespace {

// Keywords that start a shape or CSG object, and whether it is built yet.
struct ObjectKeyword {
    Keyword kw;
    bool supported;
};
constexpr ObjectKeyword kObjectKeywords[] = {
    {Keyword::kw_sphere, true},         {Keyword::kw_box, true},
    {Keyword::kw_plane, true},          {Keyword::kw_object, true},
    {Keyword::kw_cylinder, true},       {Keyword::kw_cone, true},
    {Keyword::kw_torus, false},         {Keyword::kw_disc, true},
    {Keyword::kw_triangle, true},       {Keyword::kw_smooth_triangle, true},
    {Keyword::kw_quadric, true},        {Keyword::kw_quartic, false},
    {Keyword::kw_cubic, false},         {Keyword::kw_poly, false},
    {Keyword::kw_union, true},          {Keyword::kw_merge, true},
    {Keyword::kw_intersection, true},   {Keyword::kw_difference, true},
    {Keyword::kw_blob, false},          {Keyword::kw_lathe, false},
    {Keyword::kw_sor, false},           {Keyword::kw_prism, false},
    {Keyword::kw_superellipsoid, false}, {Keyword::kw_sphere_sweep, false},
    {Keyword::kw_isosurface, false},    {Keyword::kw_parametric, false},
    {Keyword::kw_mesh, true},           {Keyword::kw_mesh2, true},
    {Keyword::kw_height_field, true},   {Keyword::kw_bicubic_patch, true},
    {Keyword::kw_text, true},          {Keyword::kw_julia_fractal, false},
    {Keyword::kw_polygon, false},       {Keyword::kw_ovus, false},
};

const ObjectKeyword* findObjectKeyword(Keyword kw) {
    for (const auto& o : kObjectKeywords)
        if (o.kw == kw) return &o;
    return nullptr;
}

}  // namespace

bool Interpreter::isObjectStart(const Token& t) const {
    return t.kind == TokenKind::Word && findObjectKeyword(t.kw) != nullptr;
}

bool Interpreter::parseStatement() {
    const Token t = peek();
    if (t.kind == TokenKind::End) return false;
    if (isObjectStart(t)) {
        // Placing the object settles what its CSG children inherit.
        scene_.objects.push_back(scene::csg::resolveInheritance(parseObject()));
        return true;
    }
    switch (t.kw) {
        case Keyword::kw_camera: scene_.camera = parseCamera(); return true;
        case Keyword::kw_light_source: scene_.lights.push_back(parseLightSource()); return true;
        case Keyword::kw_global_settings: parseGlobalSettings(); return true;
        case Keyword::kw_background: parseBackground(); return true;
        case Keyword::kw_fog: scene_.atmosphere.fogs.push_back(parseFog()); return true;
        case Keyword::kw_sky_sphere: {
            scene::SkySphere sky = parseSkySphere();
            if (scene_.atmosphere.skySphere) warn(t, "Only one sky-sphere allowed (last one will be used).");
            scene_.atmosphere.skySphere = std::move(sky);
            return true;
        }
        case Keyword::kw_rainbow: parseRainbow(); return true;
        case Keyword::kw_media: case Keyword::kw_photons: case Keyword::kw_radiosity:
            unsupported(t, std::string(t.text));
        default: break;
    }
    if (t.is(Sym::Semicolon)) {  // stray semicolons are harmless
        next();
        return true;
    }
    fail(t, fmt::format("expected an object, camera, light_source or directive, found {}",
                        describeToken(t)));
}

// --- objects -----------------------------------------------------------------

ObjectPtr Interpreter::parseObject() {
    const Token kind = next();
    const ObjectKeyword* ok = findObjectKeyword(kind.kw);
    if (!ok || !ok->supported) unsupported(kind, std::string(kind.text));
    expect(Sym::LBrace, fmt::format("'{{' after '{}'", kind.text).c_str());

    auto obj = std::make_shared<scene::Object>();
    // The texture being built by this object's modifiers; it becomes
    // obj->texture when the object is closed.
    std::optional<scene::Texture> texture;
    switch (kind.kw) {
        case Keyword::kw_object: {
            const Token id = next();
            if (!id.isIdentifier()) fail(id, fmt::format("expected an object identifier, found {}", describeToken(id)));
            const Value v = identifierValue(id);
            const auto* src = std::get_if<ObjectPtr>(&v);
            if (!src) fail(id, fmt::format("'{}' is a {}, not an object", id.text, valueKindName(v)));
            *obj = **src;
            if (obj->texture) texture = *obj->texture;
            obj->texture.reset();
            break;
        }
        case Keyword::kw_union: case Keyword::kw_merge: case Keyword::kw_intersection:
        case Keyword::kw_difference:
            parseCsgChildren(kind, *obj);
            break;
        case Keyword::kw_text: parseTextObject(*obj); break;
        case Keyword::kw_mesh: parseMesh(*obj); break;
        case Keyword::kw_mesh2: parseMesh2(*obj); break;
        case Keyword::kw_height_field: parseHeightField(*obj); break;
        case Keyword::kw_bicubic_patch: obj->shape = parseBicubicPatch(); break;
        default: obj->shape = parseShape(kind); break;
    }

    for (;;) {
        if (accept(Sym::RBrace)) break;
        if (!parseObjectModifier(*obj, texture)) {
            const Token t = peek();
            // povray reads a CSG's objects before its modifiers.
            if (obj->isCsg() && isObjectStart(t))
                fail(t, fmt::format("No matching }} in '{}', {} found instead: a CSG's objects come before "
                                    "its modifiers",
                                    kind.text, t.text));
            if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                unsupported(t, fmt::format("'{}' in {}", t.text, kind.text));
            fail(t, fmt::format("expected an object modifier or '}}', found {}", describeToken(t)));
        }
    }
    if (texture) obj->texture = std::make_shared<const scene::Texture>(*texture);
    return obj;
}

void Interpreter::parseCsgChildren(const Token& kind, scene::Object& csg) {
    switch (kind.kw) {
        case Keyword::kw_merge: csg.op = scene::CsgOp::Merge; break;
        case Keyword::kw_intersection: csg.op = scene::CsgOp::Intersection; break;
        case Keyword::kw_difference: csg.op = scene::CsgOp::Difference; break;
        default: csg.op = scene::CsgOp::Union; break;
    }
    while (isObjectStart(peek())) {
        const Token at = peek();
        csg.children.push_back(parseObject());
        // povray's warning (its wording, for difference too); the triangle
        // still takes part, enclosing nothing.
        if (csg.op != scene::CsgOp::Union && csg.op != scene::CsgOp::Merge && csg.children.back()->isPatch())
            warn(at, "Patch objects not allowed in intersection.");
    }
    if (csg.children.size() < 2) warn(kind, "Should have at least 2 objects in csg.");
}

std::shared_ptr<const scene::Shape> Interpreter::parseShape(const Token& kind) {
    // Reads "<first>, <second>" style arguments with povray's commas.
    auto comma = [&](const char* what) { expect(Sym::Comma, what); };
    // `open` follows a cylinder's or cone's numbers, before any modifier.
    auto parseOpen = [&]() { return accept(Keyword::kw_open); };
    switch (kind.kw) {
        case Keyword::kw_sphere: {
            const Vec3 c = parseVec3();
            comma("',' between the centre and the radius");
            return std::make_shared<scene::Sphere>(c, parseFloat());
        }
        case Keyword::kw_box: {
            const Vec3 a = parseVec3();
            comma("',' between the corners");
            return std::make_shared<scene::Box>(a, parseVec3());
        }
        case Keyword::kw_plane: {
            const Token at = peek();
            const Vec3 n = parseVec3();
            if (length(n) == 0) fail(at, "the normal of a plane must not be zero");
            comma("',' between the normal and the distance");
            return std::make_shared<scene::Plane>(n, parseFloat());
        }
        case Keyword::kw_cylinder: {
            const Vec3 base = parseVec3();
            comma("',' between the base and the cap");
            const Vec3 cap = parseVec3();
            comma("',' between the cap and the radius");
            const double r = parseFloat();
            if (base.x == cap.x && base.y == cap.y && base.z == cap.z)
                fail(kind, "Degenerate cylinder, base point = apex point.");
            return std::make_shared<scene::Cylinder>(base, cap, std::fabs(r), parseOpen());
        }
        case Keyword::kw_cone: {
            const Vec3 base = parseVec3();
            comma("',' between the base point and its radius");
            const double r1 = parseFloat();
            comma("',' between the base radius and the cap point");
            const Vec3 cap = parseVec3();
            comma("',' between the cap point and its radius");
            const double r2 = parseFloat();
            if (base.x == cap.x && base.y == cap.y && base.z == cap.z) fail(kind, "Degenerate cone/cylinder.");
            const bool open = parseOpen();
            if (r1 == r2) return std::make_shared<scene::Cylinder>(base, cap, std::fabs(r1), open);
            return std::make_shared<scene::Cone>(base, std::fabs(r1), cap, std::fabs(r2), open);
        }
        case Keyword::kw_disc: {
            const Vec3 center = parseVec3();
            comma("',' between the centre and the normal");
            const Token at = peek();
            const Vec3 n = parseVec3();
            if (length(n) == 0) fail(at, "the normal of a disc must not be zero");
            comma("',' between the normal and the radius");
            const double r = parseFloat();
            double hole = 0;
            if (accept(Sym::Comma)) hole = parseFloat();
            return std::make_shared<scene::Disc>(center, n, r, hole);
        }
        case Keyword::kw_triangle: {
            Vec3 v[3];
            for (int i = 0; i < 3; ++i) {
                if (i) comma("',' between the corners");
                v[i] = parseVec3();
            }
            auto tri = std::make_shared<scene::Triangle>(v[0], v[1], v[2]);
            if (tri->isDegenerate()) warn(kind, "Degenerate triangle. Please remove.");
            return tri;
        }
        case Keyword::kw_smooth_triangle: {
            Vec3 v[3], n[3];
            for (int i = 0; i < 3; ++i) {
                if (i) comma("',' between the corners");
                v[i] = parseVec3();
                comma("',' between a corner and its normal");
                n[i] = parseVec3();
            }
            auto tri = std::make_shared<scene::SmoothTriangle>(v[0], n[0], v[1], n[1], v[2], n[2]);
            if (tri->isDegenerate()) warn(kind, "Degenerate triangle. Please remove.");
            return tri;
        }
        case Keyword::kw_quadric: {
            const Vec3 sq = parseVec3();
            comma("',' after the square terms <A,B,C>");
            const Vec3 mixed = parseVec3();
            comma("',' after the mixed terms <D,E,F>");
            const Vec3 lin = parseVec3();
            comma("',' after the linear terms <G,H,I>");
            const double j = parseFloat();
            return std::make_shared<scene::Quadric>(
                scene::Quadric::Coefficients{sq.x, sq.y, sq.z, mixed.x, mixed.y, mixed.z, lin.x, lin.y, lin.z, j});
        }
        default: unsupported(kind, std::string(kind.text));
    }
}

void Interpreter::addTransform(scene::Object& obj, scene::Texture* texture, const Transform& t) const {
    obj.transformBy(t);
    // A transformation after the texture moves the texture too (seed 003 B.3).
    if (texture) texture->transform = texture->transform.then(t);
}

std::vector<scene::ObjectRef> Interpreter::parseObjectList(const Token& modifier, Keyword alternative,
                                                           const std::vector<scene::ObjectRef>& alternativeList) {
    expect(Sym::LBrace, fmt::format("'{{' after '{}'", modifier.text).c_str());
    // clipped_by { bounded_by } and bounded_by { clipped_by } reuse the
    // other list.
    if (accept(alternative)) {
        expect(Sym::RBrace, fmt::format("'}}' closing '{}'", modifier.text).c_str());
        return alternativeList;
    }
    std::vector<scene::ObjectRef> list;
    while (isObjectStart(peek())) list.push_back(parseObject());
    if (list.empty()) {
        const Token t = peek();
        fail(t, fmt::format("expected an object in '{}', found {}", modifier.text, describeToken(t)));
    }
    expect(Sym::RBrace, fmt::format("'}}' closing '{}'", modifier.text).c_str());
    return list;
}

bool Interpreter::parseObjectModifier(scene::Object& obj, std::optional<scene::Texture>& texture) {
    Transform t;
    if (parseTransformation(t)) {
        addTransform(obj, texture ? &*texture : nullptr, t);
        return true;
    }
    const Token tok = peek();
    // Texture items edit the object's texture, creating it from the
    // default texture on first use.
    auto editTexture = [&]() -> scene::Texture& {
        if (!texture) texture = obj.texture ? *obj.texture : scene::Texture{};
        return *texture;
    };
    switch (tok.kw) {
        case Keyword::kw_pigment: editTexture().pigment = parsePigment(); return true;
        case Keyword::kw_finish: {
            scene::Texture& tx = editTexture();
            tx.finish = *parseFinish(&tx.finish);
            return true;
        }
        case Keyword::kw_texture: {
            scene::Texture& tx = editTexture();
            tx = *parseTexture(&tx);
            return true;
        }
        case Keyword::kw_inverse: next(); obj.inverse = !obj.inverse; return true;
        case Keyword::kw_clipped_by:
            next();
            obj.clippedBy = parseObjectList(tok, Keyword::kw_bounded_by, obj.boundedBy);
            return true;
        case Keyword::kw_bounded_by:
            next();
            obj.boundedBy = parseObjectList(tok, Keyword::kw_clipped_by, obj.clippedBy);
            return true;
        case Keyword::kw_double_illuminate: next(); obj.doubleIlluminate = true; return true;
        case Keyword::kw_no_shadow: next(); obj.noShadow = true; return true;
        case Keyword::kw_no_image: next(); obj.noImage = true; return true;
        case Keyword::kw_no_reflection: next(); obj.noReflection = true; return true;
        case Keyword::kw_hierarchy: next(); parseOptionalBool(); return true;  // a BVH is always built
        case Keyword::kw_hollow:
            // Only changes media and fog inside the object; neither exists yet.
            next();
            if (peek().kind == TokenKind::Number || peek().is(Keyword::kw_on) || peek().is(Keyword::kw_off) ||
                peek().is(Keyword::kw_true) || peek().is(Keyword::kw_false))
                parseFloat();
            return true;
        default: return false;
    }
}

bool Interpreter::parseTransformation(Transform& out) {
    const Token t = peek();
    switch (t.kw) {
        case Keyword::kw_translate: next(); out = Transform::translate(parseVec3()); return true;
        case Keyword::kw_rotate: next(); out = Transform::rotate(parseVec3()); return true;
        case Keyword::kw_scale: {
            next();
            const Token at = peek();
            Vec3 s = parseVec3();
            for (int i = 0; i < 3; ++i)
                if (s[i] == 0) {
                    warn(at, "scale by zero in a component; changed to 1");
                    s[i] = 1;
                }
            out = Transform::scale(s);
            return true;
        }
        case Keyword::kw_matrix: {
            next();
            expect(Sym::Less, "'<' starting the 12 matrix values");
            std::array<double, 12> v{};
            for (int i = 0; i < 12; ++i) {
                if (i) expect(Sym::Comma, "',' between matrix values");
                v[i] = toFloat(parseTernary(true), t);
            }
            expect(Sym::Greater, "'>' closing the matrix");
            if (!Transform::fromMatrix(Matrix4::fromPovMatrix(v), out))
                fail(t, "this matrix is singular and cannot be used as a transformation");
            return true;
        }
        case Keyword::kw_transform: out = parseTransformBlock(); return true;
        default: return false;
    }
}

Transform Interpreter::parseTransformBlock() {
    next();  // transform
    // `transform Ident` or `transform { [Ident] items... [inverse] }`.
    if (peek().isIdentifier()) {
        const Token id = next();
        const Value v = identifierValue(id);
        const auto* tp = std::get_if<TransformPtr>(&v);
        if (!tp) fail(id, fmt::format("'{}' is a {}, not a transform", id.text, valueKindName(v)));
        return **tp;
    }
    expect(Sym::LBrace, "'{' after 'transform'");
    Transform result;
    for (;;) {
        if (accept(Sym::RBrace)) break;
        if (accept(Keyword::kw_inverse)) {
            result = result.inverse();
            continue;
        }
        const Token t = peek();
        if (t.isIdentifier()) {
            next();
            const Value v = identifierValue(t);
            const auto* tp = std::get_if<TransformPtr>(&v);
            if (!tp) fail(t, fmt::format("'{}' is a {}, not a transform", t.text, valueKindName(v)));
            result = result.then(**tp);
            continue;
        }
        Transform step;
        if (!parseTransformation(step))
            fail(t, fmt::format("expected a transformation in 'transform', found {}", describeToken(t)));
        result = result.then(step);
    }
    return result;
}

// --- textures ------------------------------------------------------------------

namespace {

bool startsColor(const Token& t) {
    return t.isIdentifier() || t.is(Sym::Less) || t.kind == TokenKind::Number || t.is(Keyword::kw_color) ||
           t.is(Keyword::kw_colour) || t.is(Keyword::kw_rgb) || t.is(Keyword::kw_rgbf) || t.is(Keyword::kw_rgbt) ||
           t.is(Keyword::kw_rgbft) || t.is(Keyword::kw_srgb) || t.is(Keyword::kw_srgbf) ||
           t.is(Keyword::kw_srgbt) || t.is(Keyword::kw_srgbft) || t.is(Keyword::kw_red) ||
           t.is(Keyword::kw_green) || t.is(Keyword::kw_blue) || t.is(Keyword::kw_filter) ||
           t.is(Keyword::kw_transmit) || t.is(Sym::LParen);
}

// Pattern keywords that take a colour list or a colour map, and their
// default colours (POV-Ray's: checker blue/green, hexagon blue/green/red,
// brick grey mortar and red brick).
std::optional<scene::PatternKind> patternKeyword(Keyword k) {
    using scene::PatternKind;
    switch (k) {
        case Keyword::kw_checker: return PatternKind::Checker;
        case Keyword::kw_hexagon: return PatternKind::Hexagon;
        case Keyword::kw_brick: return PatternKind::Brick;
        case Keyword::kw_gradient: return PatternKind::Gradient;
        case Keyword::kw_onion: return PatternKind::Onion;
        case Keyword::kw_radial: return PatternKind::Radial;
        case Keyword::kw_spherical: return PatternKind::Spherical;
        case Keyword::kw_cylindrical: return PatternKind::Cylindrical;
        case Keyword::kw_planar: return PatternKind::Planar;
        case Keyword::kw_boxed: return PatternKind::Boxed;
        case Keyword::kw_leopard: return PatternKind::Leopard;
        // quilted, spiral1 and spiral2 do not match povray yet: they stay
        // "not supported yet" until they do.
        default: return std::nullopt;
    }
}

std::vector<Color> defaultListColors(scene::PatternKind kind) {
    using scene::PatternKind;
    const Color blue(RGB(0, 0, 1)), green(RGB(0, 1, 0)), red(RGB(1, 0, 0));
    switch (kind) {
        case PatternKind::Checker: return {blue, green};
        case PatternKind::Hexagon: return {blue, green, red};
        case PatternKind::Brick: return {Color(RGB(0.5)), Color(RGB(0.6, 0.15, 0.15))};
        default: return {};
    }
}

}  // namespace

PigmentPtr Interpreter::parsePigment() {
    next();  // pigment
    expect(Sym::LBrace, "'{' after 'pigment'");
    auto result = std::make_shared<scene::Pigment>();
    const Token t = peek();
    if (t.isIdentifier()) {
        const Value* v = lookup(std::string(t.text));
        if (v && std::holds_alternative<PigmentPtr>(*v)) {
            next();
            result = std::make_shared<scene::Pigment>(*std::get<PigmentPtr>(*v));
        }
    }
    for (;;) {
        if (accept(Sym::RBrace)) break;
        const Token item = peek();
        Transform step;
        if (parseTransformation(step)) {
            result->transform(step);
            continue;
        }
        if (item.is(Keyword::kw_quick_color) || item.is(Keyword::kw_quick_colour)) {
            next();
            parseColor();
            continue;
        }
        if (parsePigmentPatternItem(*result)) continue;
        if (startsColor(item)) {
            result->setSolid(parseColor());
            continue;
        }
        if (item.kind == TokenKind::Word && item.kw != Keyword::None)
            unsupported(item, fmt::format("'{}' in pigment", item.text));
        fail(item, fmt::format("expected a color or pigment item, found {}", describeToken(item)));
    }
    return result;
}

PigmentPtr Interpreter::parsePigmentListEntry() {
    const Token t = peek();
    if (t.is(Keyword::kw_pigment)) return parsePigment();
    if (t.isIdentifier()) {
        const Value* v = lookup(std::string(t.text));
        if (v && std::holds_alternative<PigmentPtr>(*v)) {
            next();
            return std::get<PigmentPtr>(*v);
        }
    }
    return std::make_shared<const scene::Pigment>(parseColor());
}

bool Interpreter::parsePigmentPatternItem(scene::Pigment& pigment) {
    const Token item = peek();
    if (const auto kind = patternKeyword(item.kw)) {
        next();
        scene::Pattern pattern = pigment.pattern();
        pattern.kind = *kind;
        if (*kind == scene::PatternKind::Gradient) {
            const Vec3 g = parseVec3();
            const double len = length(g);
            if (len == 0) fail(item, "gradient vector is zero");
            pattern.gradient = g * (1.0 / len);
        } else if (*kind == scene::PatternKind::Spiral1 || *kind == scene::PatternKind::Spiral2) {
            pattern.arms = static_cast<int>(parseFloat());
        }
        pigment.setPattern(pattern);
        if (pattern.isList()) {
            // Up to listSize colours or pigments, optionally comma-separated;
            // missing ones keep the pattern's defaults.
            const std::vector<Color> defaults = defaultListColors(*kind);
            std::vector<PigmentPtr> list;
            for (const Color& c : defaults) list.push_back(std::make_shared<const scene::Pigment>(c));
            for (std::size_t i = 0; i < defaults.size(); ++i) {
                if (i > 0) accept(Sym::Comma);
                const Token n = peek();
                const bool isPigmentId = n.isIdentifier() && lookup(std::string(n.text)) &&
                                         std::holds_alternative<PigmentPtr>(*lookup(std::string(n.text)));
                if (!(n.is(Keyword::kw_pigment) || isPigmentId || startsColor(n))) break;
                list[i] = parsePigmentListEntry();
            }
            pigment.setList(std::move(list));
        }
        return true;
    }
    auto editPattern = [&](auto&& edit) {
        scene::Pattern p = pigment.pattern();
        edit(p);
        pigment.pattern() = p;
    };
    switch (item.kw) {
        case Keyword::kw_color_map:
        case Keyword::kw_colour_map:
            pigment.setColorMap(parseColorMap());
            return true;
        case Keyword::kw_brick_size: {
            next();
            const Vec3 v = parseVec3();
            editPattern([&](scene::Pattern& p) { p.brickSize = v; });
            return true;
        }
        case Keyword::kw_mortar: {
            next();
            const double m = parseFloat();
            editPattern([&](scene::Pattern& p) { p.mortar = m; });
            return true;
        }
        case Keyword::kw_control0: {
            next();
            const double c = parseFloat();
            editPattern([&](scene::Pattern& p) { p.control0 = c; });
            return true;
        }
        case Keyword::kw_control1: {
            next();
            const double c = parseFloat();
            editPattern([&](scene::Pattern& p) { p.control1 = c; });
            return true;
        }
        case Keyword::kw_frequency: {
            next();
            const double f = parseFloat();
            editPattern([&](scene::Pattern& p) { p.frequency = f; });
            return true;
        }
        case Keyword::kw_phase: {
            next();
            const double f = parseFloat();
            editPattern([&](scene::Pattern& p) { p.phase = f; });
            return true;
        }
        case Keyword::kw_ramp_wave:
        case Keyword::kw_triangle_wave:
        case Keyword::kw_sine_wave:
        case Keyword::kw_scallop_wave:
        case Keyword::kw_cubic_wave: {
            next();
            const scene::WaveType w = item.kw == Keyword::kw_ramp_wave       ? scene::WaveType::Ramp
                                      : item.kw == Keyword::kw_triangle_wave ? scene::WaveType::Triangle
                                      : item.kw == Keyword::kw_sine_wave     ? scene::WaveType::Sine
                                      : item.kw == Keyword::kw_scallop_wave  ? scene::WaveType::Scallop
                                                                             : scene::WaveType::Cubic;
            editPattern([&](scene::Pattern& p) { p.wave = w; });
            return true;
        }
        case Keyword::kw_poly_wave: {
            next();
            double e = 1.0;
            const Token n = peek();
            if (n.kind == TokenKind::Number || n.is(Sym::LParen) || n.is(Sym::Minus) ||
                (n.isIdentifier() && lookup(std::string(n.text)) &&
                 std::holds_alternative<double>(*lookup(std::string(n.text)))))
                e = parseFloat();
            editPattern([&](scene::Pattern& p) {
                p.wave = scene::WaveType::Poly;
                p.exponent = e;
            });
            return true;
        }
        default: return false;
    }
}

scene::ColorMap Interpreter::parseColorMap() {
    const Token kw = next();  // color_map
    expect(Sym::LBrace, "'{' after 'color_map'");
    std::vector<scene::ColorMap::Entry> entries;
    for (;;) {
        if (accept(Sym::RBrace)) break;
        const Token open = peek();
        expect(Sym::LBracket, "'[' or '}' in color_map");
        const double v1 = parseFloat();
        const bool hadComma = accept(Sym::Comma);
        if (hadComma && peek().kind == TokenKind::Number) {
            // [v1, v2 color C1 color C2]: a band from C1 to C2
            const double v2 = parseFloat();
            const Color c1 = parseColor();
            const Color c2 = parseColor();
            entries.push_back({v1, c1});
            entries.push_back({v2, c2});
        } else {
            entries.push_back({v1, parseColor()});
        }
        expect(Sym::RBracket, "']' after a color_map entry");
        if (entries.size() > scene::ColorMap::kMaxEntries)
            fail(open, fmt::format("a color_map holds at most {} entries", scene::ColorMap::kMaxEntries));
    }
    if (entries.empty()) fail(kw, "color_map needs at least one entry");
    for (std::size_t i = 1; i < entries.size(); ++i)
        if (entries[i].value < entries[i - 1].value)
            fail(kw, "color_map entries must be in increasing order");
    return scene::ColorMap(std::move(entries));
}

std::vector<scene::Pigment::MapEntry> Interpreter::parsePigmentMap() {
    const Token kw = next();  // pigment_map
    expect(Sym::LBrace, "'{' after 'pigment_map'");
    std::vector<scene::Pigment::MapEntry> entries;
    for (;;) {
        if (accept(Sym::RBrace)) break;
        expect(Sym::LBracket, "'[' or '}' in pigment_map");
        const double v = parseFloat();
        accept(Sym::Comma);
        entries.push_back({v, parsePigmentListEntry()});
        expect(Sym::RBracket, "']' after a pigment_map entry");
    }
    if (entries.empty()) fail(kw, "pigment_map needs at least one entry");
    if (entries.size() > scene::ColorMap::kMaxEntries)
        fail(kw, fmt::format("a pigment_map holds at most {} entries", scene::ColorMap::kMaxEntries));
    for (std::size_t i = 1; i < entries.size(); ++i)
        if (entries[i].value < entries[i - 1].value)
            fail(kw, "pigment_map entries must be in increasing order");
    return entries;
}

void Interpreter::parseFinishItems(scene::Finish& f) {
    for (;;) {
        if (accept(Sym::RBrace)) return;
        const Token t = next();
        switch (t.kw) {
            case Keyword::kw_ambient: f.ambient = parseColor().rgb; break;
            case Keyword::kw_emission: f.emission = parseColor().rgb; break;
            case Keyword::kw_diffuse: f.diffuse = parseFloat(); break;
            case Keyword::kw_brilliance: f.brilliance = parseFloat(); break;
            case Keyword::kw_phong: f.phong = parseFloat(); break;
            case Keyword::kw_phong_size: f.phongSize = parseFloat(); break;
            case Keyword::kw_specular: f.specular = parseFloat(); break;
            case Keyword::kw_roughness: f.roughness = parseFloat(); break;
            case Keyword::kw_metallic: {
                f.metallic = true;
                const Token n = peek();
                if (n.kind == TokenKind::Number || n.is(Sym::LParen)) f.metallic = parseFloat() != 0;
                break;
            }
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    unsupported(t, fmt::format("'{}' in finish", t.text));
                fail(t, fmt::format("expected a finish item or '}}', found {}", describeToken(t)));
        }
    }
}

FinishPtr Interpreter::parseFinish(const scene::Finish* base) {
    next();  // finish
    expect(Sym::LBrace, "'{' after 'finish'");
    scene::Finish f = base ? *base : scene::Finish{};
    const Token t = peek();
    if (t.isIdentifier()) {
        next();
        const Value v = identifierValue(t);
        const auto* fp = std::get_if<FinishPtr>(&v);
        if (!fp) fail(t, fmt::format("'{}' is a {}, not a finish", t.text, valueKindName(v)));
        f = **fp;
    }
    parseFinishItems(f);
    return std::make_shared<const scene::Finish>(f);
}

TexturePtr Interpreter::parseTexture(const scene::Texture* base) {
    next();  // texture
    expect(Sym::LBrace, "'{' after 'texture'");
    scene::Texture tex = base ? *base : scene::Texture{};
    const Token t = peek();
    if (t.isIdentifier()) {
        next();
        const Value v = identifierValue(t);
        const auto* tp = std::get_if<TexturePtr>(&v);
        if (!tp) fail(t, fmt::format("'{}' is a {}, not a texture", t.text, valueKindName(v)));
        tex = **tp;
    }
    for (;;) {
        if (accept(Sym::RBrace)) break;
        const Token item = peek();
        Transform step;
        if (parseTransformation(step)) {
            tex.transform = tex.transform.then(step);
            continue;
        }
        if (item.is(Keyword::kw_pigment)) {
            tex.pigment = parsePigment();
        } else if (item.is(Keyword::kw_finish)) {
            tex.finish = *parseFinish(&tex.finish);
        } else if (item.kind == TokenKind::Word && item.kw != Keyword::None) {
            unsupported(item, fmt::format("'{}' in texture", item.text));
        } else {
            fail(item, fmt::format("expected a texture item or '}}', found {}", describeToken(item)));
        }
    }
    return std::make_shared<const scene::Texture>(tex);
}

// --- camera, lights, settings -------------------------------------------------

void Interpreter::finalizeCamera(scene::Camera& cam, const Vec3* lookAt, double angle) const {
    if (angle > 0) {
        // The angle is the horizontal field of view; it sets the length of
        // the direction vector relative to the right vector.
        const double rightLength = length(cam.right);
        cam.direction = normalize(cam.direction) *
                        (0.5 * rightLength / std::tan(angle * std::numbers::pi / 360.0));
    }
    if (lookAt) {
        const double dirLength = length(cam.direction), upLength = length(cam.up),
                     rightLength = length(cam.right);
        // The sign of (up x direction) . right says whether the user set up
        // a left- or right-handed frame; keep it.
        const double handedness = dot(cross(cam.up, cam.direction), cam.right);
        const Vec3 dir = normalize(*lookAt - cam.location);
        const Vec3 right = normalize(cross(cam.sky, dir));
        const Vec3 up = cross(dir, right);
        cam.direction = dir * dirLength;
        cam.right = right * (handedness > 0 ? rightLength : -rightLength);
        cam.up = up * upLength;
    }
}

scene::Camera Interpreter::parseCamera() {
    next();  // camera
    expect(Sym::LBrace, "'{' after 'camera'");
    scene::Camera cam;
    const Token first = peek();
    if (first.isIdentifier()) {
        next();
        const Value v = identifierValue(first);
        const auto* cp = std::get_if<CameraPtr>(&v);
        if (!cp) fail(first, fmt::format("'{}' is a {}, not a camera", first.text, valueKindName(v)));
        cam = **cp;
    }
    std::optional<Vec3> lookAt;
    double angle = 0;
    Transform transform;
    bool transformed = false;
    for (;;) {
        if (accept(Sym::RBrace)) break;
        const Token t = peek();
        Transform step;
        if (parseTransformation(step)) {
            transform = transform.then(step);
            transformed = true;
            continue;
        }
        next();
        switch (t.kw) {
            case Keyword::kw_perspective: cam.projection = scene::Projection::Perspective; break;
            case Keyword::kw_location: cam.location = parseVec3(); break;
            case Keyword::kw_direction: cam.direction = parseVec3(); break;
            case Keyword::kw_right: cam.right = parseVec3(); break;
            case Keyword::kw_up: cam.up = parseVec3(); break;
            case Keyword::kw_sky: cam.sky = parseVec3(); break;
            case Keyword::kw_look_at: lookAt = parseVec3(); break;
            case Keyword::kw_angle: {
                angle = parseFloat();
                if (angle <= 0 || angle >= 180) fail(t, "camera angle must be between 0 and 180 degrees");
                break;
            }
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    unsupported(t, fmt::format("'{}' in camera", t.text));
                fail(t, fmt::format("expected a camera item or '}}', found {}", describeToken(t)));
        }
    }
    finalizeCamera(cam, lookAt ? &*lookAt : nullptr, angle);
    if (transformed) {
        cam.location = transform.point(cam.location);
        cam.direction = transform.direction(cam.direction);
        cam.right = transform.direction(cam.right);
        cam.up = transform.direction(cam.up);
    }
    return cam;
}

scene::Light Interpreter::parseLightSource() {
    next();  // light_source
    expect(Sym::LBrace, "'{' after 'light_source'");
    scene::Light light;
    light.position = parseVec3();
    accept(Sym::Comma);
    light.color = parseColor().rgb;
    // looks_like { OBJECT }: a visible stand-in for the light. As povray 3.7
    // does (checked against it): the object is moved to where the light is
    // when looks_like is read, the light's later transforms move both, and
    // it casts no shadow from any light (its own light sits inside it).
    std::shared_ptr<scene::Object> looksLike;
    for (;;) {
        if (accept(Sym::RBrace)) break;
        const Token t = peek();
        Transform step;
        if (parseTransformation(step)) {
            light.position = step.point(light.position);
            if (looksLike) looksLike->transformBy(step);
            continue;
        }
        next();
        switch (t.kw) {
            case Keyword::kw_shadowless: light.shadowless = true; break;
            case Keyword::kw_looks_like: {
                expect(Sym::LBrace, "'{' after 'looks_like'");
                const Token at = peek();
                if (isObjectStart(at)) {
                    looksLike = std::make_shared<scene::Object>(*parseObject());
                    looksLike->transformBy(Transform::translate(light.position));
                    expect(Sym::RBrace, "'}' closing 'looks_like'");
                } else if (at.isIdentifier()) {
                    // looks_like { Bulb scale 0.8 }: povray moves the
                    // object to the light first and applies the modifiers
                    // after that (the scale above also scales the position;
                    // checked against povray 3.7), unlike looks_like {
                    // object { Bulb scale 0.8 } }.
                    next();
                    const Value v = identifierValue(at);
                    const auto* src = std::get_if<ObjectPtr>(&v);
                    if (!src) fail(at, fmt::format("'{}' is a {}, not an object", at.text, valueKindName(v)));
                    looksLike = std::make_shared<scene::Object>(**src);
                    looksLike->transformBy(Transform::translate(light.position));
                    std::optional<scene::Texture> texture;
                    if (looksLike->texture) texture = *looksLike->texture;
                    looksLike->texture.reset();
                    while (!accept(Sym::RBrace)) {
                        if (!parseObjectModifier(*looksLike, texture)) {
                            const Token bad = peek();
                            fail(bad, fmt::format("expected an object modifier or '}}' in looks_like, found {}",
                                                  describeToken(bad)));
                        }
                    }
                    if (texture) looksLike->texture = std::make_shared<const scene::Texture>(*texture);
                } else {
                    fail(at, fmt::format("expected an object in looks_like, found {}", describeToken(at)));
                }
                looksLike->noShadow = true;
                break;
            }
            case Keyword::kw_point_at: case Keyword::kw_spotlight: case Keyword::kw_cylinder:
            case Keyword::kw_parallel: case Keyword::kw_area_light: case Keyword::kw_fade_distance:
            case Keyword::kw_fade_power: case Keyword::kw_projected_through:
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    unsupported(t, fmt::format("'{}' in light_source", t.text));
                fail(t, fmt::format("expected a light_source item or '}}', found {}", describeToken(t)));
        }
    }
    // Placed in the scene like any object (which settles what its CSG
    // children inherit, the no_shadow flag included).
    if (looksLike) scene_.objects.push_back(scene::csg::resolveInheritance(looksLike));
    return light;
}

void Interpreter::parseGlobalSettings() {
    next();
    expect(Sym::LBrace, "'{' after 'global_settings'");
    auto& g = scene_.globals;
    for (;;) {
        if (accept(Sym::RBrace)) break;
        const Token t = next();
        switch (t.kw) {
            case Keyword::kw_assumed_gamma: g.assumedGamma = parseFloat(); g.assumedGammaSet = true; break;
            case Keyword::kw_max_trace_level: g.maxTraceLevel = static_cast<int>(parseFloat()); break;
            case Keyword::kw_adc_bailout: g.adcBailout = parseFloat(); break;
            case Keyword::kw_ambient_light: g.ambientLight = parseColor().rgb; break;
            case Keyword::kw_number_of_waves: case Keyword::kw_noise_generator: parseFloat(); break;
            case Keyword::kw_charset: {
                static constexpr std::pair<Keyword, scene::TextCharset> kCharsets[] = {
                    {Keyword::kw_ascii, scene::TextCharset::Ascii},
                    {Keyword::kw_utf8, scene::TextCharset::Utf8},
                    {Keyword::kw_sys, scene::TextCharset::System}};
                const Token c = next();
                const auto* found = std::find_if(std::begin(kCharsets), std::end(kCharsets),
                                                 [&](const auto& entry) { return c.is(entry.first); });
                if (found == std::end(kCharsets))
                    fail(c, fmt::format("expected a charset type (ascii, utf8 or sys), found {}", describeToken(c)));
                textCharset_ = found->second;
                break;
            }
            case Keyword::kw_hf_gray_16: if (peek().kind == TokenKind::Number) parseFloat(); break;
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    unsupported(t, fmt::format("'{}' in global_settings", t.text));
                fail(t, fmt::format("expected a global setting or '}}', found {}", describeToken(t)));
        }
    }
}

}  // namespace frameray::sdl
