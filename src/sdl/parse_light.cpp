// light_source statements (seed 000 "Light Sources"): point, spotlight,
// cylinder and parallel lights, area lights, fading, looks_like and
// projected_through. Transforms move everything the light has read so far
// (position, point_at, area axes, looks_like, projected_through), as
// povray applies them in order.
#include <fmt/format.h>

#include <optional>

#include "scene/csg.h"
#include "sdl/interpreter.h"

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

}  // namespace

scene::Light Interpreter::parseLightSource() {
    next();  // light_source
    expect(Sym::LBrace, "'{' after 'light_source'");
    scene::Light light;
    std::shared_ptr<scene::Object> looksLike, projectedThrough;
    const Token first = peek();
    bool fromIdentifier = false;
    if (first.isIdentifier()) {
        // light_source { MyLight ... }: a declared light, modified.
        const Value v = identifierValue(first);
        if (const auto* lp = std::get_if<LightPtr>(&v)) {
            next();
            light = **lp;
            if (light.looksLike) looksLike = std::make_shared<scene::Object>(*light.looksLike);
            if (light.projectedThrough)
                projectedThrough = std::make_shared<scene::Object>(*light.projectedThrough);
            fromIdentifier = true;
        }
    }
    if (!fromIdentifier) {
        light.position = parseVec3();
        accept(Sym::Comma);
        light.color = parseColor().rgb;
    }
    for (;;) {
        if (accept(Sym::RBrace)) break;
        const Token t = peek();
        Transform step;
        if (parseTransformation(step)) {
            transformLight(light, step, looksLike, projectedThrough);
            continue;
        }
        next();
        switch (t.kw) {
            case Keyword::kw_shadowless:
                light.shadowless = true;
                break;
            case Keyword::kw_photons:
                parseLightPhotons(light.photons);
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
                light.pointAt = parseVec3();
                break;
            case Keyword::kw_radius:
                light.radius = parseFloat();
                break;
            case Keyword::kw_falloff:
                light.falloff = parseFloat();
                break;
            case Keyword::kw_tightness:
                light.tightness = parseFloat();
                break;
            case Keyword::kw_fade_distance:
                light.fadeDistance = parseFloat();
                break;
            case Keyword::kw_fade_power:
                light.fadePower = parseFloat();
                break;
            case Keyword::kw_media_interaction:
                light.mediaInteraction = parseOptionalBool();
                break;
            case Keyword::kw_media_attenuation:
                light.mediaAttenuation = parseOptionalBool();
                break;
            case Keyword::kw_area_light: {
                light.isArea = true;
                light.area.axis1 = parseVec3();
                accept(Sym::Comma);  // commas optional, as in povray
                light.area.axis2 = parseVec3();
                accept(Sym::Comma);
                light.area.size1 = std::max(1, static_cast<int>(parseFloat()));
                accept(Sym::Comma);
                light.area.size2 = std::max(1, static_cast<int>(parseFloat()));
                break;
            }
            case Keyword::kw_adaptive: {
                const double level = parseFloat();
                if (level < 0) fail(t, "adaptive must be 0 or more");
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
            case Keyword::kw_projected_through: {
                expect(Sym::LBrace, "'{' after 'projected_through'");
                const Token at = peek();
                if (!isObjectStart(at) && !at.isIdentifier())
                    fail(at, fmt::format("expected an object in projected_through, found {}",
                                         describeToken(at)));
                if (isObjectStart(at)) {
                    projectedThrough = std::make_shared<scene::Object>(*parseObject().object);
                } else {
                    next();
                    const Value v = identifierValue(at);
                    const auto* src = std::get_if<ObjectPtr>(&v);
                    if (!src)
                        fail(at,
                             fmt::format("'{}' is a {}, not an object", at.text, valueKindName(v)));
                    projectedThrough = std::make_shared<scene::Object>(*(*src)->object);
                }
                expect(Sym::RBrace, "'}' closing 'projected_through'");
                break;
            }
            case Keyword::kw_looks_like: {
                // looks_like { OBJECT }: a visible stand-in for the light. As
                // povray 3.7 does (checked against it): the object is moved to
                // where the light is when looks_like is read, the light's
                // later transforms move both, and it casts no shadow from any
                // light (its own light sits inside it).
                expect(Sym::LBrace, "'{' after 'looks_like'");
                const Token at = peek();
                if (isObjectStart(at)) {
                    looksLike = std::make_shared<scene::Object>(*parseObject().object);
                    looksLike->transformBy(Transform::translate(light.position));
                    expect(Sym::RBrace, "'}' closing 'looks_like'");
                } else if (at.isIdentifier()) {
                    // looks_like { Bulb scale 0.8 }: povray moves the object
                    // to the light first and applies the modifiers after
                    // that (the scale above also scales the position;
                    // checked against povray 3.7), unlike looks_like {
                    // object { Bulb scale 0.8 } }.
                    next();
                    const Value v = identifierValue(at);
                    const auto* src = std::get_if<ObjectPtr>(&v);
                    if (!src)
                        fail(at,
                             fmt::format("'{}' is a {}, not an object", at.text, valueKindName(v)));
                    looksLike = std::make_shared<scene::Object>(*(*src)->object);
                    looksLike->transformBy(Transform::translate(light.position));
                    std::optional<scene::Texture> texture;
                    if (looksLike->texture) texture = *looksLike->texture;
                    looksLike->texture.reset();
                    // Lights inside the stand-in are not placed.
                    ObjectValue draft{looksLike, nullptr};
                    while (!accept(Sym::RBrace)) {
                        if (!parseObjectModifier(draft, texture)) {
                            const Token bad = peek();
                            fail(bad,
                                 fmt::format(
                                     "expected an object modifier or '}}' in looks_like, found {}",
                                     describeToken(bad)));
                        }
                    }
                    if (texture)
                        looksLike->texture = std::make_shared<const scene::Texture>(*texture);
                } else {
                    fail(at, fmt::format("expected an object in looks_like, found {}",
                                         describeToken(at)));
                }
                looksLike->noShadow = true;
                break;
            }
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    unsupported(t, fmt::format("'{}' in light_source", t.text));
                fail(t, fmt::format("expected a light_source item or '}}', found {}",
                                    describeToken(t)));
        }
    }
    // Resolving settles what the CSG children inherit, no_shadow included.
    light.looksLike = looksLike ? scene::csg::resolveInheritance(looksLike) : nullptr;
    light.projectedThrough =
        projectedThrough ? scene::csg::resolveInheritance(projectedThrough) : nullptr;
    return light;
}

void Interpreter::placeLight(scene::Light light) {
    // The looks_like object is placed in the scene like any object.
    if (light.looksLike) scene_.objects.push_back(light.looksLike);
    scene_.lights.push_back(std::move(light));
}

}  // namespace frameray::sdl
