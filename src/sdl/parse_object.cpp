// Objects (seed 003 §5.2-5.3): `KIND { BODY MODIFIERS }`, where the
// builder table (builders.cpp) reads the body of each kind — a shape, a
// CSG's objects, a light_group's lights and objects, a copy of a declared
// object — and the modifiers are read here for every kind; and placing a
// top-level object into the scene with the light sources written inside it.
#include <fmt/format.h>

#include <optional>

#include "scene/csg.h"
#include "sdl/builders.h"

namespace frameray::sdl {

namespace {

void addTransform(ObjectValue& obj, scene::Texture* texture, const Transform& t) {
    obj.transformBy(t);
    // A transformation after the texture moves the texture too (seed 003 B.3).
    if (texture) texture->transformBy(t);
}

std::vector<scene::ObjectRef> parseObjectList(
    BuildContext& c, const Token& modifier, Keyword alternative,
    const std::vector<scene::ObjectRef>& alternativeList) {
    Reader& r = c.reader;
    r.expect(Sym::LBrace, fmt::format("'{{' after '{}'", modifier.text).c_str());
    // clipped_by { bounded_by } and bounded_by { clipped_by } reuse the
    // other list.
    if (r.accept(alternative)) {
        r.expect(Sym::RBrace, fmt::format("'}}' closing '{}'", modifier.text).c_str());
        return alternativeList;
    }
    std::vector<scene::ObjectRef> list;
    while (isObjectStart(r.peek())) list.push_back(parseObject(c).object);
    if (list.empty()) {
        const Token t = r.peek();
        r.fail(t, fmt::format("expected an object in '{}', found {}", modifier.text,
                              describeToken(t)));
    }
    r.expect(Sym::RBrace, fmt::format("'}}' closing '{}'", modifier.text).c_str());
    return list;
}

scene::ObjectRef placeObjectLights(BuildContext& c, const scene::ObjectRef& obj,
                                   const ObjectLights* lights,
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
            if (light.looksLike) c.scene.objects.push_back(light.looksLike);
        childGroup = std::move(lit);
        childGlobal = childGroup->globalLights;
    } else if (lights) {
        // Lights of a plain CSG node light the whole scene.
        for (const scene::Light& light : lights->lights) placeLight(c, light);
    }
    if (copy->shape) copy->lightGroup = childGroup;
    for (size_t i = 0; i < copy->children.size(); ++i) {
        const ObjectLights* childLights =
            lights && i < lights->children.size() ? lights->children[i].get() : nullptr;
        copy->children[i] =
            placeObjectLights(c, copy->children[i], childLights, childGroup, childGlobal);
    }
    return copy;
}

}  // namespace

ObjectValue parseObject(BuildContext& c) {
    Reader& r = c.reader;
    const Reader::NestingGuard nesting(r, r.peek());
    const Token kind = r.next();
    const Builder* builder = findBuilder(kind.kw);
    if (!builder || builder->kind != BuilderKind::Object || (!builder->shape && !builder->body))
        r.unsupported(kind, std::string(kind.text));
    r.expect(Sym::LBrace, fmt::format("'{{' after '{}'", kind.text).c_str());

    ObjectValue result{std::make_shared<scene::Object>(), nullptr};
    if (builder->shape)
        result.object->shape = builder->shape(c, kind);
    else
        builder->body(c, kind, result);  // may replace the object (object { })
    scene::Object* obj = result.object.get();
    // The texture being built by this object's modifiers (starting from a
    // copied object's); it becomes obj->texture when the object is closed.
    std::optional<scene::Texture> texture;
    if (obj->texture) texture = *obj->texture;
    obj->texture.reset();

    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        // Only a light_group statement itself takes global_lights (povray
        // refuses it in object { GROUP }).
        if (kind.is(Keyword::kw_light_group) && r.accept(Keyword::kw_global_lights)) {
            auto lights = std::make_shared<ObjectLights>(*result.lights);
            lights->globalLights = r.parseOptionalBool();
            result.lights = std::move(lights);
            continue;
        }
        if (!parseObjectModifier(c, result, texture)) {
            const Token t = r.peek();
            // povray reads a CSG's objects before its modifiers.
            if (obj->isCsg() && isObjectStart(t))
                r.fail(t,
                       fmt::format("No matching }} in '{}', {} found instead: a CSG's objects come "
                                   "before its modifiers",
                                   kind.text, t.text));
            if (t.is(Keyword::kw_global_lights))
                r.fail(t, fmt::format("No matching }} in '{}', global_lights found instead: it "
                                      "belongs in a light_group statement itself",
                                      kind.text));
            if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                r.unsupported(t, fmt::format("'{}' in {}", t.text, kind.text));
            r.fail(t,
                   fmt::format("expected an object modifier or '}}', found {}", describeToken(t)));
        }
    }
    if (texture) obj->texture = std::make_shared<const scene::Texture>(*texture);
    // The 2.0 form `finish { ior N }` fills an object that has no interior.
    if (obj->texture && obj->texture->finish->legacyIor > 0 && !obj->interior) {
        scene::Interior interior;
        interior.ior = obj->texture->finish->legacyIor;
        obj->interior = std::make_shared<const scene::Interior>(interior);
    }
    return result;
}

void parseObjectCopyBody(BuildContext& c, const Token&, ObjectValue& object) {
    Reader& r = c.reader;
    // object { OBJECT ... } wraps an object statement as povray does
    // (object { sphere { ... } translate x }).
    if (isObjectStart(r.peek()) && !r.peek().isIdentifier()) {
        object = parseObject(c);
        return;
    }
    const Token id = r.next();
    if (!id.isIdentifier())
        r.fail(id, fmt::format("expected an object identifier, found {}", describeToken(id)));
    const Value v = r.identifierValue(id);
    const auto* src = std::get_if<ObjectPtr>(&v);
    if (const auto* light = std::get_if<LightPtr>(&v)) {
        // object { LIGHT ... }: a light that moves as an object, an empty
        // union holding it (povray 3.7 allows it anywhere an object goes).
        object.object->op = scene::CsgOp::Union;
        auto lights = std::make_shared<ObjectLights>();
        lights->lights.push_back(**light);
        object.lights = std::move(lights);
        return;
    }
    if (!src) r.fail(id, fmt::format("'{}' is a {}, not an object", id.text, valueKindName(v)));
    object.object = std::make_shared<scene::Object>(*(*src)->object);
    object.lights = (*src)->lights;
}

void parseCsgBody(BuildContext& c, const Token& kind, ObjectValue& object) {
    Reader& r = c.reader;
    scene::Object& csg = *object.object;
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
        const Token at = r.peek();
        // Light sources may sit in any CSG; they move with it.
        if (at.is(Keyword::kw_light_source)) {
            lights->lights.push_back(parseLightSource(c));
            continue;
        }
        if (!isObjectStart(at)) break;
        ObjectValue child = parseObject(c);
        csg.children.push_back(std::move(child.object));
        lights->children.push_back(std::move(child.lights));
        // povray's warning (its wording, for difference too); the triangle
        // still takes part, enclosing nothing.
        if (csg.op != scene::CsgOp::Union && csg.op != scene::CsgOp::Merge &&
            csg.children.back()->warnsAsPatch())
            r.warn(at, "Patch objects not allowed in intersection.");
    }
    if (csg.children.size() < 2) r.warn(kind, "Should have at least 2 objects in csg.");
    if (lights->any()) object.lights = std::move(lights);
}

void parseLightGroupBody(BuildContext& c, const Token&, ObjectValue& object) {
    Reader& r = c.reader;
    scene::Object& group = *object.object;
    // A union of its objects that its lights light alone.
    group.op = scene::CsgOp::Union;
    auto lights = std::make_shared<ObjectLights>();
    lights->isLightGroup = true;
    for (;;) {
        const Token at = r.peek();
        if (at.is(Keyword::kw_light_source)) {
            lights->lights.push_back(parseLightSource(c));
        } else if (isObjectStart(at)) {
            ObjectValue child = parseObject(c);
            group.children.push_back(std::move(child.object));
            lights->children.push_back(std::move(child.lights));
        } else {
            break;
        }
    }
    object.lights = std::move(lights);
}

void placeObject(BuildContext& c, const ObjectValue& object) {
    // Placing the object settles what its CSG children inherit; an object
    // without a texture takes the #default texture in force.
    scene::ObjectRef obj = object.object;
    if (c.defaultTextureSet && !obj->texture) {
        auto textured = std::make_shared<scene::Object>(*obj);
        if (!c.placedDefaultTexture)
            c.placedDefaultTexture = std::make_shared<const scene::Texture>(c.defaultTexture);
        textured->texture = c.placedDefaultTexture;
        obj = std::move(textured);
    }
    c.scene.objects.push_back(placeObjectLights(c, scene::csg::resolveInheritance(obj),
                                                object.lights.get(), nullptr, std::nullopt));
}

// A texture (or a material's) given to an object that has one already
// lies on top of it as new layers, each starting from the #default
// texture; it does not edit the old one (measured with povray 3.7:
// `object { O texture { pigment { rgbt <0,1,0,0.5> } } }` shows O's own
// texture through the green, and `pigment { rgbf 0.9 } texture { Glass }`
// layers the glass over the grey, advanced/glasschess.pov). Patterned
// textures cannot be layered, either way.
static void layerOnTop(Reader& r, const Token& at, const scene::Object& obj,
                       std::optional<scene::Texture>& texture, scene::Texture upper,
                       const scene::Texture& defaultTexture) {
    // The object's uv_mapping maps the textures given after it; when
    // nothing but uv_mapping came before, there is nothing to layer over
    // (advanced/benchmark.pov's `object { MSH uv_mapping texture { } }`).
    if (texture && !obj.texture && texture->uvMapping) {
        upper.uvMapping = true;
        const bool onlyUvMapping = texture->pigment == defaultTexture.pigment &&
                                   texture->finish == defaultTexture.finish &&
                                   texture->normal == defaultTexture.normal && !texture->map &&
                                   texture->layersBelow.empty();
        if (onlyUvMapping) {
            texture = std::move(upper);
            return;
        }
    }
    const scene::Texture* below = texture ? &*texture : obj.texture.get();
    if (below) {
        if (below->map) r.fail(at, "Cannot layer over a patterned texture.");
        if (upper.map) r.fail(at, "Cannot layer a patterned texture over another.");
        below->stackOn(upper);
    }
    texture = std::move(upper);
}

bool parseObjectModifier(BuildContext& c, ObjectValue& draft,
                         std::optional<scene::Texture>& texture) {
    Reader& r = c.reader;
    scene::Object& obj = *draft.object;
    Transform t;
    if (r.parseTransformation(t)) {
        addTransform(draft, texture ? &*texture : nullptr, t);
        return true;
    }
    const Token tok = r.peek();
    // Texture items edit the object's texture, creating it from the
    // default texture on first use.
    auto editTexture = [&]() -> scene::Texture& {
        if (!texture) texture = obj.texture ? *obj.texture : c.defaultTexture;
        // povray 3.7 edits the top layer, and refuses a patterned one
        // with the message of layering (measured).
        if (texture->map) r.fail(tok, "Cannot layer over a patterned texture.");
        return *texture;
    };
    switch (tok.kw) {
        case Keyword::kw_pigment: {
            scene::Texture& tx = editTexture();
            tx.pigment = parseTexturePigment(c, tx);
            return true;
        }
        case Keyword::kw_normal: {
            scene::Texture& tx = editTexture();
            tx.normal = parseTextureNormal(c, tx);
            return true;
        }
        case Keyword::kw_finish: {
            scene::Texture& tx = editTexture();
            tx.finish = parseFinish(c, tx.finish.get());
            return true;
        }
        case Keyword::kw_texture:
            layerOnTop(r, tok, obj, texture, parseLayeredTextures(c), c.defaultTexture);
            return true;
        case Keyword::kw_interior:
            obj.interior = parseInterior(c, obj.interior.get());
            return true;
        case Keyword::kw_uv_mapping:
            // An object's uv_mapping maps the texture that follows it
            // (povray 3.7, measured: as `texture { uv_mapping ... }`).
            r.next();
            if (texture) r.fail(tok, "uv_mapping must be specified before texture.");
            editTexture().uvMapping = true;
            return true;
        case Keyword::kw_interior_texture:  // a texture body, from the default texture
            obj.interiorTexture = parseTexture(c, nullptr);
            return true;
        case Keyword::kw_material: {
            // Its texture replaces the object's; its interior too.
            const MaterialPtr m = parseMaterial(c);
            if (m->texture) layerOnTop(r, tok, obj, texture, *m->texture, c.defaultTexture);
            if (m->interior) obj.interior = m->interior;
            return true;
        }
        case Keyword::kw_inverse:
            r.next();
            obj.inverse = !obj.inverse;
            return true;
        case Keyword::kw_clipped_by:
            r.next();
            obj.clippedBy = parseObjectList(c, tok, Keyword::kw_bounded_by, obj.boundedBy);
            return true;
        case Keyword::kw_bounded_by:
            r.next();
            obj.boundedBy =
                parseObjectList(c, tok, Keyword::kw_clipped_by, obj.clippedBy.objects());
            return true;
        case Keyword::kw_double_illuminate:
            r.next();
            obj.doubleIlluminate = true;
            return true;
        case Keyword::kw_no_shadow:
            r.next();
            obj.noShadow = true;
            return true;
        case Keyword::kw_no_image:
            r.next();
            obj.noImage = true;
            return true;
        case Keyword::kw_no_reflection:
            r.next();
            obj.noReflection = true;
            return true;
        case Keyword::kw_no_radiosity:
            r.next();
            obj.noRadiosity = true;
            return true;
        case Keyword::kw_radiosity:
            parseObjectRadiosity(c, obj);
            return true;
        case Keyword::kw_hierarchy:
            r.next();
            r.parseOptionalBool();
            return true;  // a BVH is always built
        case Keyword::kw_sturm:
            r.next();
            applySturm(c, obj, tok);
            return true;
        case Keyword::kw_photons:
            r.next();
            parseObjectPhotons(c, obj.photons, tok);
            return true;
        case Keyword::kw_split_union:
            r.next();
            if (!obj.isCsg() || obj.op != scene::CsgOp::Union)
                r.fail(tok, "split_union found in non-union object.");
            obj.photons.splitUnion = r.parseOptionalBool();
            return true;
        case Keyword::kw_hollow:
            // Lets fog reach rays inside the object (see render::Tracer).
            r.next();
            obj.hollow = r.parseOptionalBool();
            return true;
        default:
            return false;
    }
}

}  // namespace frameray::sdl
