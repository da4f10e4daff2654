// Scene statements: objects and their modifiers, camera, lights, textures,
// global settings. Builds scene:: values from the token stream.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "scene/csg.h"
#include "scene/flat_shapes.h"
#include "scene/mesh.h"
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
    {Keyword::kw_sphere, true},
    {Keyword::kw_box, true},
    {Keyword::kw_plane, true},
    {Keyword::kw_object, true},
    {Keyword::kw_cylinder, true},
    {Keyword::kw_cone, true},
    {Keyword::kw_torus, true},
    {Keyword::kw_disc, true},
    {Keyword::kw_triangle, true},
    {Keyword::kw_smooth_triangle, true},
    {Keyword::kw_quadric, true},
    {Keyword::kw_quartic, true},
    {Keyword::kw_cubic, true},
    {Keyword::kw_poly, true},
    {Keyword::kw_union, true},
    {Keyword::kw_merge, true},
    {Keyword::kw_intersection, true},
    {Keyword::kw_difference, true},
    {Keyword::kw_blob, true},
    {Keyword::kw_lathe, true},
    {Keyword::kw_sor, true},
    {Keyword::kw_prism, true},
    {Keyword::kw_superellipsoid, true},
    {Keyword::kw_sphere_sweep, true},
    {Keyword::kw_isosurface, true},
    {Keyword::kw_parametric, true},
    {Keyword::kw_mesh, true},
    {Keyword::kw_mesh2, true},
    {Keyword::kw_height_field, true},
    {Keyword::kw_bicubic_patch, true},
    {Keyword::kw_text, true},
    {Keyword::kw_julia_fractal, true},
    {Keyword::kw_polygon, true},
    {Keyword::kw_ovus, false},
    {Keyword::kw_light_group, true},
};

const ObjectKeyword* findObjectKeyword(Keyword kw) {
    for (const auto& o : kObjectKeywords)
        if (o.kw == kw) return &o;
    return nullptr;
}

// A mesh object: its shape, or (triangles with their own textures) a union
// of its texture groups.
bool isMeshObject(const scene::Object& obj) {
    if (obj.shape) return dynamic_cast<const scene::MeshShape*>(obj.shape.get()) != nullptr;
    return !obj.children.empty() &&
           std::all_of(obj.children.begin(), obj.children.end(),
                       [](const scene::ObjectRef& c) { return c && isMeshObject(*c); });
}

}  // namespace

bool Interpreter::isObjectStart(const Token& t) const {
    return t.kind == TokenKind::Word && findObjectKeyword(t.kw) != nullptr;
}

bool Interpreter::parseStatement() {
    const Token t = peek();
    if (t.kind == TokenKind::End) return false;
    if (isObjectStart(t)) {
        // Placing the object settles what its CSG children inherit; an
        // object without a texture takes the #default texture in force.
        const ObjectValue parsed = parseObject();
        scene::ObjectRef obj = parsed.object;
        if (defaultTextureSet_ && !obj->texture) {
            auto textured = std::make_shared<scene::Object>(*obj);
            textured->texture = std::make_shared<const scene::Texture>(defaultTexture_);
            obj = std::move(textured);
        }
        scene_.objects.push_back(placeObjectLights(scene::csg::resolveInheritance(obj),
                                                   parsed.lights.get(), nullptr, std::nullopt));
        return true;
    }
    switch (t.kw) {
        case Keyword::kw_camera:
            scene_.camera = parseCamera();
            return true;
        case Keyword::kw_light_source:
            placeLight(parseLightSource());
            return true;
        case Keyword::kw_global_settings:
            parseGlobalSettings();
            return true;
        case Keyword::kw_background:
            parseBackground();
            return true;
        case Keyword::kw_fog:
            scene_.atmosphere.fogs.push_back(parseFog());
            return true;
        case Keyword::kw_sky_sphere: {
            scene::SkySphere sky = parseSkySphere();
            if (scene_.atmosphere.skySphere)
                warn(t, "Only one sky-sphere allowed (last one will be used).");
            scene_.atmosphere.skySphere = std::move(sky);
            return true;
        }
        case Keyword::kw_rainbow:
            parseRainbow();
            return true;
        case Keyword::kw_default:  // povray 3.7 takes `default { }` without '#', silently
            next();
            directiveDefault();
            return true;
        case Keyword::kw_media:
            scene_.atmosphere.media.push_back(parseMedia());
            return true;
        case Keyword::kw_photons:
        case Keyword::kw_radiosity:
            unsupported(t, std::string(t.text));
        default:
            break;
    }
    if (t.is(Sym::Semicolon)) {  // stray semicolons are harmless
        next();
        return true;
    }
    fail(t, fmt::format("expected an object, camera, light_source or directive, found {}",
                        describeToken(t)));
}

// --- objects -----------------------------------------------------------------

ObjectValue Interpreter::parseObject() {
    const NestingGuard nesting(*this, peek());
    const Token kind = next();
    const ObjectKeyword* ok = findObjectKeyword(kind.kw);
    if (!ok || !ok->supported) unsupported(kind, std::string(kind.text));
    expect(Sym::LBrace, fmt::format("'{{' after '{}'", kind.text).c_str());

    ObjectValue result{std::make_shared<scene::Object>(), nullptr};
    scene::Object* obj = result.object.get();
    // The texture being built by this object's modifiers; it becomes
    // obj->texture when the object is closed.
    std::optional<scene::Texture> texture;
    switch (kind.kw) {
        case Keyword::kw_object: {
            // object { OBJECT ... } wraps an object statement as povray does
            // (object { sphere { ... } translate x }).
            if (isObjectStart(peek()) && !peek().isIdentifier()) {
                const ObjectValue inner = parseObject();
                *obj = *inner.object;
                result.lights = inner.lights;
                if (obj->texture) texture = *obj->texture;
                obj->texture.reset();
                break;
            }
            const Token id = next();
            if (!id.isIdentifier())
                fail(id, fmt::format("expected an object identifier, found {}", describeToken(id)));
            const Value v = identifierValue(id);
            const auto* src = std::get_if<ObjectPtr>(&v);
            if (const auto* light = std::get_if<LightPtr>(&v)) {
                // object { LIGHT ... }: a light that moves as an object, an
                // empty union holding it (povray 3.7 allows it anywhere an
                // object goes).
                obj->op = scene::CsgOp::Union;
                auto lights = std::make_shared<ObjectLights>();
                lights->lights.push_back(**light);
                result.lights = std::move(lights);
                break;
            }
            if (!src)
                fail(id, fmt::format("'{}' is a {}, not an object", id.text, valueKindName(v)));
            *obj = *(*src)->object;
            result.lights = (*src)->lights;
            if (obj->texture) texture = *obj->texture;
            obj->texture.reset();
            break;
        }
        case Keyword::kw_union:
        case Keyword::kw_merge:
        case Keyword::kw_intersection:
        case Keyword::kw_difference:
            result.lights = parseCsgChildren(kind, *obj);
            break;
        case Keyword::kw_light_group:
            result.lights = parseLightGroupMembers(*obj);
            break;
        case Keyword::kw_text:
            parseTextObject(*obj);
            break;
        case Keyword::kw_mesh:
            // mesh { DECLARED_MESH modifiers } copies the declared mesh as
            // object { } would (povray 3.7; no triangles may follow).
            if (const Token id = peek(); id.isIdentifier()) {
                next();
                const Value v = identifierValue(id);
                const auto* src = std::get_if<ObjectPtr>(&v);
                if (!src || !isMeshObject(*(*src)->object))
                    fail(id, fmt::format("'{}' is not a mesh", id.text));
                *obj = *(*src)->object;
                if (obj->texture) texture = *obj->texture;
                obj->texture.reset();
                break;
            }
            parseMesh(*obj);
            break;
        case Keyword::kw_mesh2:
            parseMesh2(*obj);
            break;
        case Keyword::kw_height_field:
            parseHeightField(*obj);
            break;
        case Keyword::kw_bicubic_patch:
            obj->shape = parseBicubicPatch();
            break;
        default:
            obj->shape = parseShape(kind);
            // A blob's component textures (parseBlob).
            obj->componentTextures = std::move(blobComponentTextures_);
            blobComponentTextures_.clear();
            break;
    }

    for (;;) {
        if (accept(Sym::RBrace)) break;
        // Only a light_group statement itself takes global_lights (povray
        // refuses it in object { GROUP }).
        if (kind.is(Keyword::kw_light_group) && accept(Keyword::kw_global_lights)) {
            auto lights = std::make_shared<ObjectLights>(*result.lights);
            lights->globalLights = parseOptionalBool();
            result.lights = std::move(lights);
            continue;
        }
        if (!parseObjectModifier(result, texture)) {
            const Token t = peek();
            // povray reads a CSG's objects before its modifiers.
            if (obj->isCsg() && isObjectStart(t))
                fail(t, fmt::format(
                            "No matching }} in '{}', {} found instead: a CSG's objects come before "
                            "its modifiers",
                            kind.text, t.text));
            if (t.is(Keyword::kw_global_lights))
                fail(t, fmt::format("No matching }} in '{}', global_lights found instead: it "
                                    "belongs in a light_group statement itself",
                                    kind.text));
            if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                unsupported(t, fmt::format("'{}' in {}", t.text, kind.text));
            fail(t, fmt::format("expected an object modifier or '}}', found {}", describeToken(t)));
        }
    }
    if (texture) obj->texture = std::make_shared<const scene::Texture>(*texture);
    // The 2.0 form `finish { ior N }` fills an object that has no interior.
    if (obj->texture && obj->texture->finish.legacyIor > 0 && !obj->interior) {
        scene::Interior interior;
        interior.ior = obj->texture->finish.legacyIor;
        obj->interior = std::make_shared<const scene::Interior>(interior);
    }
    return result;
}

std::shared_ptr<const ObjectLights> Interpreter::parseCsgChildren(const Token& kind,
                                                                  scene::Object& csg) {
    switch (kind.kw) {
        case Keyword::kw_merge:
            csg.op = scene::CsgOp::Merge;
            break;
        case Keyword::kw_intersection:
            csg.op = scene::CsgOp::Intersection;
            break;
        case Keyword::kw_difference:
            csg.op = scene::CsgOp::Difference;
            break;
        default:
            csg.op = scene::CsgOp::Union;
            break;
    }
    auto lights = std::make_shared<ObjectLights>();
    for (;;) {
        const Token at = peek();
        // Light sources may sit in any CSG; they move with it.
        if (at.is(Keyword::kw_light_source)) {
            lights->lights.push_back(parseLightSource());
            continue;
        }
        if (!isObjectStart(at)) break;
        ObjectValue child = parseObject();
        csg.children.push_back(std::move(child.object));
        lights->children.push_back(std::move(child.lights));
        // povray's warning (its wording, for difference too); the triangle
        // still takes part, enclosing nothing.
        if (csg.op != scene::CsgOp::Union && csg.op != scene::CsgOp::Merge &&
            csg.children.back()->warnsAsPatch())
            warn(at, "Patch objects not allowed in intersection.");
    }
    if (csg.children.size() < 2) warn(kind, "Should have at least 2 objects in csg.");
    return lights->any() ? lights : nullptr;
}

std::shared_ptr<const ObjectLights> Interpreter::parseLightGroupMembers(scene::Object& group) {
    // A union of its objects that its lights light alone.
    group.op = scene::CsgOp::Union;
    auto lights = std::make_shared<ObjectLights>();
    lights->isLightGroup = true;
    for (;;) {
        const Token at = peek();
        if (at.is(Keyword::kw_light_source)) {
            lights->lights.push_back(parseLightSource());
        } else if (isObjectStart(at)) {
            ObjectValue child = parseObject();
            group.children.push_back(std::move(child.object));
            lights->children.push_back(std::move(child.lights));
        } else {
            break;
        }
    }
    return lights;
}

scene::ObjectRef Interpreter::placeObjectLights(
    const scene::ObjectRef& obj, const ObjectLights* lights,
    const std::shared_ptr<const scene::LightGroup>& group,
    const std::optional<bool>& outermostGlobal) {
    if (!group && !lights) return obj;
    auto copy = std::make_shared<scene::Object>(*obj);
    std::shared_ptr<const scene::LightGroup> childGroup = group;
    std::optional<bool> childGlobal = outermostGlobal;
    if (lights && lights->isLightGroup) {
        // A nested group's objects see its own lights only; whether they
        // also see the scene's is the outermost group's global_lights
        // (measured: an inner group's own setting changes nothing).
        auto lit = std::make_shared<scene::LightGroup>();
        lit->lights = lights->lights;
        lit->globalLights = outermostGlobal.value_or(lights->globalLights);
        for (const scene::Light& light : lit->lights)
            if (light.looksLike) scene_.objects.push_back(light.looksLike);
        childGroup = std::move(lit);
        childGlobal = childGroup->globalLights;
    } else if (lights) {
        // Lights of a plain CSG node light the whole scene.
        for (const scene::Light& light : lights->lights) placeLight(light);
    }
    if (copy->shape) copy->lightGroup = childGroup;
    for (size_t i = 0; i < copy->children.size(); ++i) {
        const ObjectLights* childLights =
            lights && i < lights->children.size() ? lights->children[i].get() : nullptr;
        copy->children[i] =
            placeObjectLights(copy->children[i], childLights, childGroup, childGlobal);
    }
    return copy;
}

std::shared_ptr<const scene::Shape> Interpreter::parseShape(const Token& kind) {
    // The commas between a shape's numbers are optional in povray
    // (`box { <0,0,0> <1,1,1> }`): take one when it is there.
    auto comma = [&](const char*) { accept(Sym::Comma); };
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
            if (base.x == cap.x && base.y == cap.y && base.z == cap.z)
                fail(kind, "Degenerate cone/cylinder.");
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
        case Keyword::kw_polygon:
            return parsePolygon(kind);
        case Keyword::kw_julia_fractal:
            return parseJuliaFractal(kind);
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
            return std::make_shared<scene::Quadric>(scene::Quadric::Coefficients{
                sq.x, sq.y, sq.z, mixed.x, mixed.y, mixed.z, lin.x, lin.y, lin.z, j});
        }
        case Keyword::kw_torus:
        case Keyword::kw_poly:
        case Keyword::kw_cubic:
        case Keyword::kw_quartic:
        case Keyword::kw_blob:
            return parsePolynomialShape(kind);
        case Keyword::kw_superellipsoid:
            return parseSuperellipsoid(kind);
        case Keyword::kw_isosurface:
            return parseIsosurface(kind);
        case Keyword::kw_parametric:
            return parseParametric(kind);
        case Keyword::kw_sphere_sweep:
            return parseSphereSweep(kind);
        case Keyword::kw_lathe:
            return parseLathe(kind);
        case Keyword::kw_sor:
            return parseSor(kind);
        case Keyword::kw_prism:
            return parsePrism(kind);
        default:
            unsupported(kind, std::string(kind.text));
    }
}

void Interpreter::addTransform(ObjectValue& obj, scene::Texture* texture,
                               const Transform& t) const {
    obj.transformBy(t);
    // A transformation after the texture moves the texture too (seed 003 B.3).
    if (texture) texture->transformBy(t);
}

std::vector<scene::ObjectRef> Interpreter::parseObjectList(
    const Token& modifier, Keyword alternative,
    const std::vector<scene::ObjectRef>& alternativeList) {
    expect(Sym::LBrace, fmt::format("'{{' after '{}'", modifier.text).c_str());
    // clipped_by { bounded_by } and bounded_by { clipped_by } reuse the
    // other list.
    if (accept(alternative)) {
        expect(Sym::RBrace, fmt::format("'}}' closing '{}'", modifier.text).c_str());
        return alternativeList;
    }
    std::vector<scene::ObjectRef> list;
    while (isObjectStart(peek())) list.push_back(parseObject().object);
    if (list.empty()) {
        const Token t = peek();
        fail(t,
             fmt::format("expected an object in '{}', found {}", modifier.text, describeToken(t)));
    }
    expect(Sym::RBrace, fmt::format("'}}' closing '{}'", modifier.text).c_str());
    return list;
}

bool Interpreter::parseObjectModifier(ObjectValue& draft, std::optional<scene::Texture>& texture) {
    scene::Object& obj = *draft.object;
    Transform t;
    if (parseTransformation(t)) {
        addTransform(draft, texture ? &*texture : nullptr, t);
        return true;
    }
    const Token tok = peek();
    // Texture items edit the object's texture, creating it from the
    // default texture on first use.
    auto editTexture = [&]() -> scene::Texture& {
        if (!texture) texture = obj.texture ? *obj.texture : defaultTexture_;
        return *texture;
    };
    switch (tok.kw) {
        case Keyword::kw_pigment:
            editTexture().pigment = parsePigment();
            return true;
        case Keyword::kw_normal: {
            scene::Texture& tx = editTexture();
            tx.normal = parseNormal(tx.normal.get());
            return true;
        }
        case Keyword::kw_finish: {
            scene::Texture& tx = editTexture();
            tx.finish = *parseFinish(&tx.finish);
            return true;
        }
        case Keyword::kw_texture: {
            scene::Texture& tx = editTexture();
            // A texture block starts from the object's texture unless that
            // is a patterned one (its pattern would swallow the new items).
            tx = parseLayeredTextures(tx.map ? nullptr : &tx);
            return true;
        }
        case Keyword::kw_interior:
            obj.interior = parseInterior(obj.interior.get());
            return true;
        case Keyword::kw_uv_mapping:
            // An object's uv_mapping maps the texture that follows it
            // (povray 3.7, measured: as `texture { uv_mapping ... }`).
            next();
            if (texture) fail(tok, "uv_mapping must be specified before texture.");
            editTexture().uvMapping = true;
            return true;
        case Keyword::kw_interior_texture:  // a texture body, from the default texture
            obj.interiorTexture = parseTexture(nullptr);
            return true;
        case Keyword::kw_material: {
            // Its texture replaces the object's; its interior too.
            const MaterialPtr m = parseMaterial();
            if (m->texture) texture = *m->texture;
            if (m->interior) obj.interior = m->interior;
            return true;
        }
        case Keyword::kw_inverse:
            next();
            obj.inverse = !obj.inverse;
            return true;
        case Keyword::kw_clipped_by:
            next();
            obj.clippedBy = parseObjectList(tok, Keyword::kw_bounded_by, obj.boundedBy);
            return true;
        case Keyword::kw_bounded_by:
            next();
            obj.boundedBy = parseObjectList(tok, Keyword::kw_clipped_by, obj.clippedBy);
            return true;
        case Keyword::kw_double_illuminate:
            next();
            obj.doubleIlluminate = true;
            return true;
        case Keyword::kw_no_shadow:
            next();
            obj.noShadow = true;
            return true;
        case Keyword::kw_no_image:
            next();
            obj.noImage = true;
            return true;
        case Keyword::kw_no_reflection:
            next();
            obj.noReflection = true;
            return true;
        case Keyword::kw_no_radiosity:
            next();
            obj.noRadiosity = true;
            return true;
        case Keyword::kw_radiosity:
            parseObjectRadiosity(obj);
            return true;
        case Keyword::kw_hierarchy:
            next();
            parseOptionalBool();
            return true;  // a BVH is always built
        case Keyword::kw_sturm:
            next();
            applySturm(obj, tok);
            return true;
        case Keyword::kw_photons:
            next();
            parseObjectPhotons(obj.photons, tok);
            return true;
        case Keyword::kw_split_union:
            next();
            if (!obj.isCsg() || obj.op != scene::CsgOp::Union)
                fail(tok, "split_union found in non-union object.");
            obj.photons.splitUnion = parseOptionalBool();
            return true;
        case Keyword::kw_hollow:
            // Lets fog reach rays inside the object (see render::Tracer).
            next();
            obj.hollow = parseOptionalBool();
            return true;
        default:
            return false;
    }
}

bool Interpreter::parseTransformation(Transform& out) {
    const Token t = peek();
    switch (t.kw) {
        case Keyword::kw_translate:
            next();
            out = Transform::translate(parseVec3());
            return true;
        case Keyword::kw_rotate:
            next();
            out = Transform::rotate(parseVec3());
            return true;
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
                if (i) accept(Sym::Comma);  // optional, as in povray
                v[i] = toFloat(parseAdditive(), t);
            }
            expect(Sym::Greater, "'>' closing the matrix");
            if (!Transform::fromMatrix(Matrix4::fromPovMatrix(v), out))
                fail(t, "this matrix is singular and cannot be used as a transformation");
            return true;
        }
        case Keyword::kw_transform:
            out = parseTransformBlock();
            return true;
        default:
            return false;
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
            if (!tp)
                fail(t, fmt::format("'{}' is a {}, not a transform", t.text, valueKindName(v)));
            result = result.then(**tp);
            continue;
        }
        Transform step;
        if (!parseTransformation(step))
            fail(t, fmt::format("expected a transformation in 'transform', found {}",
                                describeToken(t)));
        result = result.then(step);
    }
    return result;
}

// --- textures ------------------------------------------------------------------

// parseTexture: parse_texture_maps.cpp

// --- settings (camera: parse_camera.cpp, lights: parse_light.cpp) ------------

void Interpreter::parseGlobalSettings() {
    next();
    expect(Sym::LBrace, "'{' after 'global_settings'");
    auto& g = scene_.globals;
    for (;;) {
        if (accept(Sym::RBrace)) break;
        const Token t = next();
        switch (t.kw) {
            case Keyword::kw_assumed_gamma:
                g.assumedGamma = parseFloat();
                g.assumedGammaSet = true;
                break;
            case Keyword::kw_max_trace_level:
                g.maxTraceLevel = static_cast<int>(parseFloat());
                break;
            case Keyword::kw_adc_bailout:
                g.adcBailout = parseFloat();
                break;
            case Keyword::kw_ambient_light:
                g.ambientLight = parseColor().rgb;
                break;
            case Keyword::kw_irid_wavelength:
                g.iridWavelength = parseColor().rgb;
                break;
            case Keyword::kw_number_of_waves:
            case Keyword::kw_noise_generator:
                parseFloat();
                break;
            case Keyword::kw_charset: {
                static constexpr std::pair<Keyword, scene::TextCharset> kCharsets[] = {
                    {Keyword::kw_ascii, scene::TextCharset::Ascii},
                    {Keyword::kw_utf8, scene::TextCharset::Utf8},
                    {Keyword::kw_sys, scene::TextCharset::System}};
                const Token c = next();
                const auto* found =
                    std::find_if(std::begin(kCharsets), std::end(kCharsets),
                                 [&](const auto& entry) { return c.is(entry.first); });
                if (found == std::end(kCharsets))
                    fail(c, fmt::format("expected a charset type (ascii, utf8 or sys), found {}",
                                        describeToken(c)));
                textCharset_ = found->second;
                break;
            }
            case Keyword::kw_radiosity:
                parseRadiositySettings(t);
                break;
            case Keyword::kw_hf_gray_16:
                parseOptionalBool();
                break;
            case Keyword::kw_photons:
                // A second block replaces the first's values item by item.
                if (!g.photons) g.photons.emplace();
                parseGlobalPhotons(*g.photons);
                break;
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    unsupported(t, fmt::format("'{}' in global_settings", t.text));
                fail(t,
                     fmt::format("expected a global setting or '}}', found {}", describeToken(t)));
        }
    }
}

}  // namespace frameray::sdl
