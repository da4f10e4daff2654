// Atmosphere statements: background, fog, sky_sphere and rainbow. Values
// are checked and converted the way POV-Ray 3.7's parser does (its
// messages, its defaults, its angle conversions), so scene::Atmosphere
// holds exactly what POV-Ray renders from.
#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "sdl/builders.h"

namespace frameray::sdl {

namespace {

constexpr double kEpsilon = 1e-10;  // POV-Ray's EPSILON in its vector checks

// Fog items that set its turbulence (the fog density's noise).
constexpr Keyword kFogTurbulenceKeywords[] = {
    Keyword::kw_turbulence,
    Keyword::kw_octaves,
    Keyword::kw_omega,
    Keyword::kw_lambda,
};

bool isFogTurbulenceKeyword(Keyword k) {
    for (const Keyword c : kFogTurbulenceKeywords)
        if (c == k) return true;
    return false;
}

}  // namespace

void parseBackground(BuildContext& c) {
    Reader& r = c.reader;
    r.next();
    r.expect(Sym::LBrace, "'{' after 'background'");
    c.scene.background = r.parseColor();
    r.expect(Sym::RBrace, "'}' closing 'background'");
}

scene::Fog parseFog(BuildContext& c) {
    Reader& r = c.reader;
    r.next();  // fog
    r.expect(Sym::LBrace, "'{' after 'fog'");
    scene::Fog fog;
    // fog { Identifier ... } starts from a declared fog.
    if (const Token first = r.peek(); first.isIdentifier()) {
        if (const Value* v = r.lookup(first.text); v && std::holds_alternative<FogPtr>(*v)) {
            r.next();
            fog = *std::get<FogPtr>(*v);
        }
    }
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        const Token t = r.peek();
        // A colour: a colour keyword or an identifier holding one; a bare
        // float is the distance (povray warns).
        if (isColorKeyword(t.kw)) {
            fog.color = r.parseColor();
            continue;
        }
        if (t.isIdentifier()) {
            const Value* v = r.lookup(t.text);
            if (v && std::holds_alternative<VectorValue>(*v)) {
                fog.color = r.parseColor();
                continue;
            }
        }
        if (r.floatFollows()) {
            r.warn(t, "Should use distance keyword.");
            fog.distance = r.parseFloat();
            continue;
        }
        if (isFogTurbulenceKeyword(t.kw)) {
            // Any of them gives the fog a turbulence (amount 0 until set:
            // measured, `octaves 3` alone changes the fog).
            if (!fog.turbulence) fog.turbulence.emplace();
            parseTurbulenceItem(c, *fog.turbulence);
            continue;
        }
        // The fog's transformations turn its up vector; a translation
        // cannot move a direction (povray warns and ignores it).
        if (t.is(Keyword::kw_translate)) {
            r.next();
            r.parseVec3();
            r.warn(t, "A fog's up vector can't be translated.");
            continue;
        }
        Transform step;
        if (r.parseTransformation(step)) {
            fog.up = step.direction(fog.up);
            continue;
        }
        r.next();
        switch (t.kw) {
            case Keyword::kw_distance:
                fog.distance = r.parseFloat();
                break;
            case Keyword::kw_fog_type: {
                fog.typeNumber = static_cast<int>(r.parseFloat());
                if (fog.typeNumber < 1 || fog.typeNumber > 2) r.warn(t, "Unknown fog type.");
                fog.kind =
                    fog.typeNumber == 2 ? scene::Fog::Kind::Ground : scene::Fog::Kind::Constant;
                break;
            }
            case Keyword::kw_fog_alt:
                fog.altitude = r.parseFloat();
                break;
            case Keyword::kw_fog_offset:
                fog.offset = r.parseFloat();
                break;
            case Keyword::kw_turb_depth:
                fog.turbulenceDepth = r.parseFloat();
                break;
            case Keyword::kw_up:
                fog.up = r.parseVec3();
                break;
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    r.unsupported(t, fmt::format("'{}' in fog", t.text));
                r.fail(t, fmt::format("expected a fog item or '}}', found {}", describeToken(t)));
        }
    }
    // povray normalises without a check: a zero up vector gives NaNs there.
    fog.up = fog.up * (1.0 / length(fog.up));
    return fog;
}

scene::SkySphere parseSkySphere(BuildContext& c) {
    Reader& r = c.reader;
    const Token kw = r.next();  // sky_sphere
    r.expect(Sym::LBrace, "'{' after 'sky_sphere'");
    scene::SkySphere sky;
    // sky_sphere { Identifier ... } adds to a declared sky sphere.
    if (const Token first = r.peek(); first.isIdentifier()) {
        if (const Value* v = r.lookup(first.text); v && std::holds_alternative<SkySpherePtr>(*v)) {
            r.next();
            sky = *std::get<SkySpherePtr>(*v);
        }
    }
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        const Token t = r.peek();
        Transform step;
        if (r.parseTransformation(step)) {
            sky.transform = sky.transform.then(step);
            continue;
        }
        if (t.is(Keyword::kw_pigment)) {
            sky.pigments.push_back(parsePigment(c));
            if (sky.pigments.back()->uvMapping()) r.unsupported(t, "uv_mapping in sky_sphere");
            continue;
        }
        r.next();
        if (t.is(Keyword::kw_emission)) {
            sky.emission = r.parseColor().rgb;
            continue;
        }
        if (t.kind == TokenKind::Word && t.kw != Keyword::None)
            r.unsupported(t, fmt::format("'{}' in sky_sphere", t.text));
        r.fail(t, fmt::format("expected a sky_sphere item or '}}', found {}", describeToken(t)));
    }
    if (sky.pigments.empty()) r.fail(kw, "Empty sky_sphere statement.");
    return sky;
}

// A rainbow cannot be declared yet (the expression parser reports it as
// not supported): povray 3.7 converts a declared rainbow's angles to
// radians a second time when it is used, and crashes freeing it at exit.
void parseRainbow(BuildContext& c) {
    Reader& r = c.reader;
    const Token kw = r.next();  // rainbow
    r.expect(Sym::LBrace, "'{' after 'rainbow'");
    scene::Rainbow rainbow;
    double angle = 0, width = 0;
    bool falloffGiven = false, arcGiven = false;
    // falloff_angle and arc_angle are full angles in degrees (0..360);
    // povray keeps half of each, in radians.
    auto halfAngle = [&](const Token& at, const char* what) {
        const double a = r.parseFloat();
        if (a < 0.0 || a > 360.0)
            r.fail(at, fmt::format("Illegal {} angle in rainbow (Use value from 0 to 360 degrees).",
                                   what));
        return a * std::numbers::pi / 360.0;
    };
    for (;;) {
        if (r.accept(Sym::RBrace)) break;
        const Token t = r.peek();
        if (t.is(Keyword::kw_color_map) || t.is(Keyword::kw_colour_map)) {
            rainbow.colorMap = parseColorMap(c);
            continue;
        }
        r.next();
        switch (t.kw) {
            case Keyword::kw_angle:
                angle = r.parseFloat();
                break;
            case Keyword::kw_width:
                width = r.parseFloat();
                break;
            case Keyword::kw_direction:
                rainbow.antisolar = r.parseVec3();
                break;
            case Keyword::kw_up:
                rainbow.up = r.parseVec3();
                break;
            case Keyword::kw_distance:
                rainbow.distance = r.parseFloat();
                break;
            case Keyword::kw_jitter:
                rainbow.jitter = r.parseFloat();
                break;
            case Keyword::kw_falloff_angle:
                rainbow.falloffAngle = halfAngle(t, "falloff");
                falloffGiven = true;
                break;
            case Keyword::kw_arc_angle:
                rainbow.arcAngle = halfAngle(t, "arc");
                arcGiven = true;
                break;
            default:
                if (t.kind == TokenKind::Word && t.kw != Keyword::None)
                    r.unsupported(t, fmt::format("'{}' in rainbow", t.text));
                r.fail(t,
                       fmt::format("expected a rainbow item or '}}', found {}", describeToken(t)));
        }
    }
    // An arc without a falloff fades nowhere: the falloff starts at its end.
    if (arcGiven && !falloffGiven) rainbow.falloffAngle = rainbow.arcAngle;
    if (rainbow.arcAngle < rainbow.falloffAngle)
        r.fail(kw, "Arc angle is smaller than falloff angle in rainbow.");
    rainbow.falloffWidth = rainbow.arcAngle - rainbow.falloffAngle;
    if (std::fabs(dot(rainbow.antisolar, rainbow.antisolar)) < kEpsilon)
        r.fail(kw, "Rainbow's direction vector is zero.");
    if (std::fabs(dot(rainbow.up, rainbow.up)) < kEpsilon)
        r.fail(kw, "Rainbow's up vector is zero.");
    rainbow.antisolar = normalize(rainbow.antisolar);
    rainbow.up = normalize(rainbow.up);
    if (std::fabs(1.0 - std::fabs(dot(rainbow.up, rainbow.antisolar))) < kEpsilon)
        r.fail(kw, "Rainbow's up and direction vector are co-linear.");
    // Make up perpendicular to the antisolar direction.
    rainbow.right = cross(rainbow.up, rainbow.antisolar);
    rainbow.up = normalize(cross(rainbow.antisolar, rainbow.right));
    rainbow.right = normalize(rainbow.right);
    // `angle` is the middle of the band; keep its start.
    rainbow.bandStart = (angle - 0.5 * width) * std::numbers::pi / 180.0;
    rainbow.width = width * std::numbers::pi / 180.0;
    c.scene.atmosphere.rainbows.push_back(std::move(rainbow));
}

}  // namespace frameray::sdl
