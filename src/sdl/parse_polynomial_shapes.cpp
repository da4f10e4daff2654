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
#include "sdl/interpreter.h"
#include "util/roots.h"

namespace frameray::sdl {

std::vector<double> Interpreter::parseCoefficientVector(int count, const Token& kind) {
    expect(Sym::Less,
           fmt::format("'<' starting the {} coefficients of '{}'", count, kind.text).c_str());
    std::vector<double> values;
    values.reserve(count);
    // Commas between coefficients are optional (povray reads them as a
    // list of floats, not as a vector literal).
    while (!peek().is(Sym::Greater) && peek().kind != TokenKind::End) {
        const Token at = peek();
        values.push_back(toFloat(parseAdditive(), at));
        accept(Sym::Comma);
    }
    const Token close = peek();
    expect(Sym::Greater, "'>' closing the coefficients");
    if (static_cast<int>(values.size()) != count)
        fail(close,
             fmt::format("'{}' needs {} coefficients, found {}", kind.text, count, values.size()));
    return values;
}

std::shared_ptr<const scene::Shape> Interpreter::parsePolynomialShape(const Token& kind) {
    switch (kind.kw) {
        case Keyword::kw_torus: {
            const double major = parseFloat();
            accept(Sym::Comma);  // optional, as in povray
            const double minor = parseFloat();
            return std::make_shared<scene::Torus>(major, minor, false);
        }
        case Keyword::kw_poly: {
            const Token at = peek();
            const double order = parseFloat();
            if (order < 2 || order > kMaxPolynomialDegree)
                fail(at, "Order of poly is out of range.");
            const int n = static_cast<int>(order);
            accept(Sym::Comma);  // optional, as between any parameters (povray)
            const std::vector<double> coefficients =
                parseCoefficientVector(scene::PolynomialSurface::coefficientCount(n), kind);
            return std::make_shared<scene::PolynomialSurface>(n, coefficients, false, "poly");
        }
        case Keyword::kw_cubic:
            return std::make_shared<scene::PolynomialSurface>(3, parseCoefficientVector(20, kind),
                                                              false, "cubic");
        case Keyword::kw_quartic:
            return std::make_shared<scene::PolynomialSurface>(4, parseCoefficientVector(35, kind),
                                                              false, "quartic");
        case Keyword::kw_blob:
            return parseBlob();
        default:
            unsupported(kind, std::string(kind.text));
    }
}

std::shared_ptr<const scene::Shape> Interpreter::parseBlob() {
    using Component = scene::Blob::Component;
    std::vector<Component> components;
    // Each component's own texture (null: the blob object's), in blob
    // space; handed to parseObject through blobComponentTextures_.
    std::vector<std::shared_ptr<const scene::Texture>> textures;
    double threshold = 1;
    // A component's transformations, applied in order after its geometry
    // (and to its texture when they follow it), and its texture, started
    // from the default texture as an object's is.
    auto parseComponentModifiers = [&](Component& c, const char* what) {
        std::optional<scene::Texture> texture;
        auto editTexture = [&]() -> scene::Texture& {
            if (!texture) texture = defaultTexture_;
            return *texture;
        };
        for (;;) {
            if (accept(Sym::RBrace)) {
                textures.push_back(texture ? std::make_shared<const scene::Texture>(*texture)
                                           : nullptr);
                return;
            }
            Transform t;
            const Token at = peek();
            if (parseTransformation(t)) {
                c.toBlob = c.transformed ? c.toBlob.then(t) : t;
                c.transformed = true;
                if (texture) texture->transformBy(t);
                continue;
            }
            if (at.is(Keyword::kw_pigment)) {
                scene::Texture& tx = editTexture();
                tx.pigment = parseTexturePigment(tx);
                continue;
            }
            if (at.is(Keyword::kw_normal)) {
                scene::Texture& tx = editTexture();
                tx.normal = parseTextureNormal(tx);
                continue;
            }
            if (at.is(Keyword::kw_finish)) {
                scene::Texture& tx = editTexture();
                tx.finish = *parseFinish(&tx.finish);
                continue;
            }
            if (at.is(Keyword::kw_texture)) {
                scene::Texture& tx = editTexture();
                tx = parseLayeredTextures(tx.map ? nullptr : &tx);
                continue;
            }
            fail(at, fmt::format("expected a transformation or '}}' in a blob {}, found {}", what,
                                 describeToken(at)));
        }
    };
    auto parseStrength = [&]() {
        accept(Keyword::kw_strength);
        return parseFloat();
    };
    for (;;) {
        const Token t = peek();
        if (accept(Keyword::kw_threshold)) {
            threshold = parseFloat();
        } else if (accept(Keyword::kw_sphere)) {
            expect(Sym::LBrace, "'{' after 'sphere'");
            Component c;
            c.a = parseVec3();
            accept(Sym::Comma);  // optional, as in povray
            c.radius = parseFloat();
            accept(Sym::Comma);  // optional, as in povray
            c.strength = parseStrength();
            parseComponentModifiers(c, "sphere");
            components.push_back(c);
        } else if (accept(Keyword::kw_cylinder)) {
            expect(Sym::LBrace, "'{' after 'cylinder'");
            Component c;
            c.kind = Component::Kind::Cylinder;
            c.a = parseVec3();
            accept(Sym::Comma);  // optional, as in povray
            c.b = parseVec3();
            accept(Sym::Comma);  // optional, as in povray
            c.radius = parseFloat();
            accept(Sym::Comma);  // optional, as in povray
            c.strength = parseStrength();
            parseComponentModifiers(c, "cylinder");
            components.push_back(c);
        } else if (accept(Keyword::kw_component)) {
            // The 2.0 form: component Strength, Radius, <Centre>.
            Component c;
            c.strength = parseFloat();
            accept(Sym::Comma);  // optional, as in povray
            c.radius = parseFloat();
            accept(Sym::Comma);  // optional, as in povray
            c.a = parseVec3();
            components.push_back(c);
            textures.push_back(nullptr);
        } else {
            if (components.empty()) fail(t, "Need at least one component in a blob.");
            break;
        }
        if (!components.empty() && components.back().radius <= 0)
            fail(t, "a blob component needs a positive radius");
    }
    blobComponentTextures_.clear();
    for (const auto& texture : textures) {
        if (!texture) continue;
        blobComponentTextures_ = std::move(textures);
        break;
    }
    return std::make_shared<scene::Blob>(std::move(components), threshold, false);
}

void Interpreter::applySturm(scene::Object& obj, const Token& at) {
    const bool on = parseOptionalBool();
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
        fail(at, "Keyword 'sturm' cannot be used with this object.");
    }
}

}  // namespace frameray::sdl
