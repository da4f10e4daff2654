// light_source statements (seed 000 "Light Sources"): point, spotlight,
// cylinder and parallel lights, area lights, fading, looks_like and
// projected_through. Transforms move everything the light has read so far
// (position, point_at, area axes, looks_like, projected_through), as
// povray applies them in order.
#include <fmt/format.h>

#include <optional>

#include "scene/csg.h"
#include "sdl/builders.h"

namespace frameray::sdl {

namespace {

void transformLight(scene::Light& light, const Transform& t,
                    std::shared_ptr<scene::Object>& looksLike,
                    std::shared_ptr<scene::Object>& projectedThrough) {
    light.position = t.point(light.position);
    light.pointAt = t.point(light.pointAt);
    light.area.axis1 = t.direction(light.area.axis1);
    light.area.axis2 = t.direction(light.area.axis2);
    if (looksLike) looksLike->transformBy(t);
    if (projectedThrough) projectedThrough->transformBy(t);
}

// projected_through { OBJECT }, after the keyword.
std::shared_ptr<scene::Object> parseProjectedThrough(BuildContext& c) {
    Reader& r = c.reader;
    r.expect(Sym::LBrace, "'{' after 'projected_through'");
    const Token at = r.peek();
    if (!isObjectStart(at) && !at.isIdentifier())
        r.fail(at,
               fmt::format("expected an object in projected_through, found {}", describeToken(at)));
    std::shared_ptr<scene::Object> object;
    if (isObjectStart(at)) {
        object = std::make_shared<scene::Object>(*parseObject(c).object);
    } else {
        r.next();
        const Value v = r.identifierValue(at);
        const auto* src = std::get_if<ObjectPtr>(&v);
        if (!src) r.fail(at, fmt::format("'{}' is a {}, not an object", at.text, valueKindName(v)));
        object = std::make_shared<scene::Object>(*(*src)->object);
    }
    r.expect(Sym::RBrace, "'}' closing 'projected_through'");
    return object;
}

// looks_like { OBJECT }, after the keyword: a visible stand-in for the light
// at `position`. As povray 3.7 does (checked against it): the object is
// moved to where the light is when looks_like is read, the light's later
// transforms move both, and it casts no shadow from any light (its own
// light sits inside it).
std::shared_ptr<scene::Object> parseLooksLike(BuildContext& c, const Vec3& position) {
    Reader& r = c.reader;
    r.expect(Sym::LBrace, "'{' after 'looks_like'");
    const Token at = r.peek();
    std::shared_ptr<scene::Object> looksLike;
    if (isObjectStart(at)) {
        looksLike = std::make_shared<scene::Object>(*parseObject(c).object);
        looksLike->transformBy(Transform::translate(position));
        r.expect(Sym::RBrace, "'}' closing 'looks_like'");
    } else if (at.isIdentifier()) {
        // looks_like { Bulb scale 0.8 }: povray moves the object to the
        // light first and applies the modifiers after that (the scale above
        // also scales the position; checked against povray 3.7), unlike
        // looks_like { object { Bulb scale 0.8 } }.
        r.next();
        const Value v = r.identifierValue(at);
        const auto* src = std::get_if<ObjectPtr>(&v);
        if (!src) r.fail(at, fmt::format("'{}' is a {}, not an object", at.text, valueKindName(v)));
        looksLike = std::make_shared<scene::Object>(*(*src)->object);
        looksLike->transformBy(Transform::translate(position));
        std::optional<scene::Texture> texture;
        if (looksLike->texture) texture = *looksLike->texture;
        looksLike->texture.reset();
        // Lights inside the stand-in are not placed.
        ObjectValue draft{looksLike, nullptr};
        while (!r.accept(Sym::RBrace)) {
            if (!parseObjectModifier(c, draft, texture)) {
                const Token bad = r.peek();
                r.fail(bad,
                       fmt::format("expected an object modifier or '}}' in looks_like, found {}",
                                   describeToken(bad)));
            }
        }
        if (texture) looksLike->texture = std::make_shared<const scene::Texture>(*texture);
    } else {
        r.fail(at, fmt::format("expected an object in looks_like, found {}", describeToken(at)));
    }
    looksLike->noShadow = true;
    return looksLike;
}

}  // namespace

scene::Light parseLightSource(BuildContext& c) {
    Reader& r = c.reader;
    r.next();  // light_source
    r.expect(Sym::LBrace, "'{' after 'light_source'");
    scene::Light light;
    std::shared_ptr<scene::Object> looksLike, projectedThrough;
    const Token first = r.peek();
    bool fromIdentifier = false;
    if (first.isIdentifier()) {
        // light_source { MyLight ... }: a declared light, modified.
        const Value v = r.identifierValue(first);
        if (const auto* lp = std::get_if<LightPtr>(&v)) {
            r.next();
            light = **lp;
            if (light.looksLike) looksLike = std::make_shared<scene::Object>(*light.looksLike);
            if (light.projectedThrough)
                projectedThrough = std::make_shared<scene::Object>(*light.projectedThrough);
            fromIdentifier = true;
        }
    }
    if (!fromIdentifier) {
        light.position = r.parseVec3();
        r.accept(Sym::Comma);
        light.color = r.parseColor().rgb;
    }
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        const Token t = r.peek();
        Transform step;
        if (r.parseTransformation(step)) {
            transformLight(light, step, looksLike, projectedThrough);
            continue;
        }
        r.next();
        switch (t.kw) {
            case Keyword::kw_shadowless:
                light.shadowless = true;
                break;
            case Keyword::kw_photons:
                parseLightPhotons(c, light.photons);
                break;
            case Keyword::kw_spotlight:
                light.kind = scene::LightKind::Spot;
                break;
            case Keyword::kw_cylinder:
                light.kind = scene::LightKind::Cylinder;
                break;
            case Keyword::kw_parallel:
                light.parallel = true;
                break;
            case Keyword::kw_point_at:
                light.pointAt = r.parseVec3();
                break;
            case Keyword::kw_radius:
                light.radius = r.parseFloat();
                break;
            case Keyword::kw_falloff:
                light.falloff = r.parseFloat();
                break;
            case Keyword::kw_tightness:
                light.tightness = r.parseFloat();
                break;
            case Keyword::kw_fade_distance:
                light.fadeDistance = r.parseFloat();
                break;
            case Keyword::kw_fade_power:
                light.fadePower = r.parseFloat();
                break;
            case Keyword::kw_media_interaction:
                light.mediaInteraction = r.parseOptionalBool();
                break;
            case Keyword::kw_media_attenuation:
                light.mediaAttenuation = r.parseOptionalBool();
                break;
            case Keyword::kw_area_light: {
                light.isArea = true;
                light.area.axis1 = r.parseVec3();
                r.accept(Sym::Comma);  // commas optional, as in povray
                light.area.axis2 = r.parseVec3();
                r.accept(Sym::Comma);
                light.area.size1 = std::max(1, static_cast<int>(r.parseFloat()));
                r.accept(Sym::Comma);
                light.area.size2 = std::max(1, static_cast<int>(r.parseFloat()));
                break;
            }
            case Keyword::kw_adaptive: {
                const double level = r.parseFloat();
                if (level < 0) r.fail(t, "adaptive must be 0 or more");
                light.area.adaptive = static_cast<int>(level);
                break;
            }
            case Keyword::kw_jitter:
                light.area.jitter = true;
                break;
            case Keyword::kw_circular:
                light.area.circular = true;
                break;
            case Keyword::kw_orient:
                light.area.orient = true;
                break;
            case Keyword::kw_projected_through:
                projectedThrough = parseProjectedThrough(c);
                break;
            case Keyword::kw_looks_like:
                looksLike = parseLooksLike(c, light.position);
                break;
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    r.unsupported(t, fmt::format("'{}' in light_source", t.text));
                r.fail(t, fmt::format("expected a light_source item or '}}', found {}",
                                      describeToken(t)));
        }
    }
    // Resolving settles what the CSG children inherit, no_shadow included.
    light.looksLike = looksLike ? scene::csg::resolveInheritance(looksLike) : nullptr;
    light.projectedThrough =
        projectedThrough ? scene::csg::resolveInheritance(projectedThrough) : nullptr;
    return light;
}

void placeLight(BuildContext& c, scene::Light light) {
    // The looks_like object is placed in the scene like any object.
    if (light.looksLike) c.scene.objects.push_back(light.looksLike);
    c.scene.lights.push_back(std::move(light));
}

}  // namespace frameray::sdl
