// Polynomial shapes and blobs (seed 003 §5.2.3):
//
//     torus { Major, Minor [modifiers] }
//     poly { Order, <A1, ..., Am> [modifiers] }      m = (Order+1)(Order+2)(Order+3)/6
//     cubic { <A1, ..., A20> [modifiers] }
//     quartic { <A1, ..., A35> [modifiers] }
//     blob { [threshold T] sphere { C, R, [strength] S [transforms] }
//            cylinder { A, B, R, [strength] S [transforms] } component S, R, C ...
//            [modifiers] }
//
// `sturm [Bool]` is an object modifier of these shapes (povray accepts it
// anywhere among the modifiers): parseObjectModifier calls applySturm.
#include <fmt/format.h>

#include <cmath>
#include <optional>

#include "scene/blob.h"
#include "scene/polynomial_shapes.h"
#include "sdl/builders.h"
#include "util/roots.h"

namespace frameray::sdl {

static std::vector<double> parseCoefficientVector(BuildContext& c, int count, const Token& kind) {
    Reader& r = c.reader;
    r.expect(Sym::Less,
             fmt::format("'<' starting the {} coefficients of '{}'", count, kind.text).c_str());
    std::vector<double> values;
    values.reserve(count);
    // Commas between coefficients are optional (povray reads them as a
    // list of floats, not as a vector literal).
    while (!r.peek().is(Sym::Greater) && r.peek().kind != TokenKind::End) {
        const Token at = r.peek();
        values.push_back(r.toFloat(r.parseAdditive(), at));
        r.accept(Sym::Comma);
    }
    const Token close = r.peek();
    r.expect(Sym::Greater, "'>' closing the coefficients");
    if (static_cast<int>(values.size()) != count)
        r.fail(close, fmt::format("'{}' needs {} coefficients, found {}", kind.text, count,
                                  values.size()));
    return values;
}

std::shared_ptr<const scene::Shape> parsePolynomialShape(BuildContext& c, const Token& kind) {
    Reader& r = c.reader;
    switch (kind.kw) {
        case Keyword::kw_torus: {
            const double major = r.parseFloat();
            r.accept(Sym::Comma);  // optional, as in povray
            const double minor = r.parseFloat();
            return std::make_shared<scene::Torus>(major, minor, false);
        }
        case Keyword::kw_poly: {
            const Token at = r.peek();
            const double order = r.parseFloat();
            if (order < 2 || order > kMaxPolynomialDegree)
                r.fail(at, "Order of poly is out of range.");
            const int n = static_cast<int>(order);
            r.accept(Sym::Comma);  // optional, as between any parameters (povray)
            const std::vector<double> coefficients =
                parseCoefficientVector(c, scene::PolynomialSurface::coefficientCount(n), kind);
            return std::make_shared<scene::PolynomialSurface>(n, coefficients, false, "poly");
        }
        case Keyword::kw_cubic:
            return std::make_shared<scene::PolynomialSurface>(
                3, parseCoefficientVector(c, 20, kind), false, "cubic");
        case Keyword::kw_quartic:
            return std::make_shared<scene::PolynomialSurface>(
                4, parseCoefficientVector(c, 35, kind), false, "quartic");
        default:
            r.unsupported(kind, std::string(kind.text));
    }
}

void parseBlobBody(BuildContext& c, const Token&, ObjectValue& blob) {
    Reader& r = c.reader;
    using Component = scene::Blob::Component;
    std::vector<Component> components;
    // Each component's own texture (null: the blob object's), in blob
    // space; the object keeps them when any component has one.
    std::vector<std::shared_ptr<const scene::Texture>> textures;
    double threshold = 1;
    // A component's transformations, applied in order after its geometry
    // (and to its texture when they follow it), and its texture, started
    // from the default texture as an object's is.
    auto parseComponentModifiers = [&](Component& comp, const char* what) {
        std::optional<scene::Texture> texture;
        auto editTexture = [&]() -> scene::Texture& {
            if (!texture) texture = c.defaultTexture;
            return *texture;
        };
        for (;;) {
            if (r.accept(Sym::RBrace)) {
                textures.push_back(texture ? std::make_shared<const scene::Texture>(*texture)
                                           : nullptr);
                return;
            }
            Transform t;
            const Token at = r.peek();
            if (r.parseTransformation(t)) {
                comp.toBlob = comp.transformed ? comp.toBlob.then(t) : t;
                comp.transformed = true;
                if (texture) texture->transformBy(t);
                continue;
            }
            if (at.is(Keyword::kw_pigment)) {
                scene::Texture& tx = editTexture();
                tx.pigment = parseTexturePigment(c, tx);
                continue;
            }
            if (at.is(Keyword::kw_normal)) {
                scene::Texture& tx = editTexture();
                tx.normal = parseTextureNormal(c, tx);
                continue;
            }
            if (at.is(Keyword::kw_finish)) {
                scene::Texture& tx = editTexture();
                tx.finish = parseFinish(c, tx.finish.get());
                continue;
            }
            if (at.is(Keyword::kw_texture)) {
                scene::Texture& tx = editTexture();
                tx = parseLayeredTextures(c, tx.map ? nullptr : &tx);
                continue;
            }
            r.fail(at, fmt::format("expected a transformation or '}}' in a blob {}, found {}", what,
                                   describeToken(at)));
        }
    };
    auto parseStrength = [&]() {
        r.accept(Keyword::kw_strength);
        return r.parseFloat();
    };
    for (;;) {
        const Token t = r.peek();
        if (r.accept(Keyword::kw_threshold)) {
            threshold = r.parseFloat();
        } else if (t.is(Keyword::kw_sphere) || t.is(Keyword::kw_cylinder)) {
            // sphere { C, R, [strength] S ... }, cylinder { A, B, R, ... }:
            // the commas optional, as in povray.
            r.next();
            const bool cylinder = t.is(Keyword::kw_cylinder);
            const char* what = cylinder ? "cylinder" : "sphere";
            r.expectAfter(Sym::LBrace, "'{'", what);
            Component comp;
            if (cylinder) comp.kind = Component::Kind::Cylinder;
            comp.a = r.parseVec3();
            r.accept(Sym::Comma);
            if (cylinder) {
                comp.b = r.parseVec3();
                r.accept(Sym::Comma);
            }
            comp.radius = r.parseFloat();
            r.accept(Sym::Comma);
            comp.strength = parseStrength();
            parseComponentModifiers(comp, what);
            components.push_back(comp);
        } else if (r.accept(Keyword::kw_component)) {
            // The 2.0 form: component Strength, Radius, <Centre>.
            Component comp;
            comp.strength = r.parseFloat();
            r.accept(Sym::Comma);  // optional, as in povray
            comp.radius = r.parseFloat();
            r.accept(Sym::Comma);  // optional, as in povray
            comp.a = r.parseVec3();
            components.push_back(comp);
            textures.push_back(nullptr);
        } else {
            if (components.empty()) r.fail(t, "Need at least one component in a blob.");
            break;
        }
        if (!components.empty() && components.back().radius <= 0)
            r.fail(t, "a blob component needs a positive radius");
    }
    for (const auto& texture : textures) {
        if (!texture) continue;
        blob.object->componentTextures = std::move(textures);
        break;
    }
    blob.object->shape = std::make_shared<scene::Blob>(std::move(components), threshold, false);
}

void applySturm(BuildContext& c, scene::Object& obj, const Token& at) {
    Reader& r = c.reader;
    const bool on = r.parseOptionalBool();
    const scene::Shape* shape = obj.shape.get();
    if (const auto* torus = dynamic_cast<const scene::Torus*>(shape)) {
        obj.shape = std::make_shared<scene::Torus>(torus->majorRadius(), torus->minorRadius(), on);
    } else if (const auto* poly = dynamic_cast<const scene::PolynomialSurface*>(shape)) {
        obj.shape = std::make_shared<scene::PolynomialSurface>(poly->withSturm(on));
    } else if (const auto* blob = dynamic_cast<const scene::Blob*>(shape)) {
        obj.shape = std::make_shared<scene::Blob>(blob->withSturm(on));
    } else if (shape && (std::string_view(shape->name()) == "lathe" ||
                         std::string_view(shape->name()) == "sor" ||
                         std::string_view(shape->name()) == "prism" ||
                         std::string_view(shape->name()) == "sphere_sweep")) {
        // Their own solvers decide; povray accepts the keyword on them.
    } else {
        r.fail(at, "Keyword 'sturm' cannot be used with this object.");
    }
}

}  // namespace frameray::sdl
