// Surface appearance: pigment and finish (seed 003 §5.4). Pigments are solid
// colours or deterministic patterns (patterns.h) with colour lists, colour
// maps (color_map.h) or pigment maps.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "scene/color_map.h"
#include "scene/image_map.h"
#include "scene/normals.h"
#include "scene/patterns.h"
#include "util/color.h"
#include "util/matrix.h"
#include "util/shared_transform.h"
#include "util/value_box.h"

namespace frameray::scene {

// A pigment is a solid colour, a colour-list pattern (checker, hexagon,
// brick: one sub-pigment per index), a colour-mapped pattern or a
// pigment-mapped pattern. Evaluation is const, thread-safe and does not
// allocate. A plain colour is 56 bytes: the pattern and everything that
// goes with it live out of line, only once written (issue 23: 10^6
// spheres each with its own colour).
class Pigment {
  public:
    enum class Kind { Solid, List, ColorMapped, PigmentMapped, ImageMapped };
    struct MapEntry {
        double value;
        std::shared_ptr<const Pigment> pigment;
    };

    Pigment() = default;
    explicit Pigment(const Color& c) : color_(c) {}

    // Colour at a point in the texture's space; the pigment's own
    // transformation is applied here.
    // `surface`: the normal and ray in the same space as p (slope, aoi).
    Color at(const Vec3& p, const SurfaceInfo* surface = nullptr) const;
    const Color& solidColor() const { return color_; }
    Kind kind() const { return kind_; }
    // Whether anything beyond the kind, colour and uv_mapping was written
    // (pattern, maps, transformation, quick_color).
    bool hasPatternPart() const { return more_.holds(); }
    bool isSolid() const { return kind_ == Kind::Solid; }

    // Builders used by the parser.
    void setSolid(const Color& c) {
        kind_ = Kind::Solid;
        color_ = c;
    }
    void setPattern(const Pattern& p);  // picks List or ColorMapped from the pattern
    Pattern& pattern() { return more_.edit().pattern; }
    const Pattern& pattern() const { return more_.get().pattern; }
    void setList(std::vector<std::shared_ptr<const Pigment>> list) {
        more_.edit().list = std::move(list);
    }
    const std::vector<std::shared_ptr<const Pigment>>& list() const { return more_.get().list; }
    void setColorMap(ColorMap map);
    // A pattern without a colour_map takes povray's default map for it,
    // which may depend on items after the pattern keyword (mandel's
    // exponent): the parser calls this once the pigment block is read.
    void settleDefaultColorMap();
    void setPigmentMap(std::vector<MapEntry> map);
    // image_map (image_map.h): the image, seen through the pattern's chain.
    void setImageMap(std::shared_ptr<const ImageMap> map) {
        more_.edit().imageMap = std::move(map);
        kind_ = Kind::ImageMapped;
    }
    const std::shared_ptr<const ImageMap>& imageMap() const { return more_.get().imageMap; }
    // uv_mapping: the pigment is evaluated at the surface's (u, v, 0)
    // (SurfaceInfo::uv) through its own transformations only (povray 3.7,
    // measured: the texture's and object's transformations do not move it).
    void setUvMapping() { uvMapping_ = true; }
    bool uvMapping() const { return uvMapping_; }
    // Whether this pigment or one it holds is uv-mapped.
    bool usesUv() const;
    // Whether every colour at() can return has filter and transmit 0
    // (every colour, map entry and sub-pigment has): a shadow ray needs
    // not evaluate it to know it lets nothing through. False when unsure
    // (image maps).
    bool alwaysOpaque() const;
    // quick_color: what +Q0/+Q1 show instead of the pigment.
    void setQuickColor(const Color& c) { more_.edit().quickColor = c; }
    const std::optional<Color>& quickColor() const { return more_.get().quickColor; }
    // `average`: the pigment map's entries are averaged, weighted by their
    // values, instead of picked by the pattern.
    void setAverage() { more_.edit().average = true; }
    // Pigment-local transformation ("this, then t"); composes before the
    // texture's transform.
    // The pattern keeps the same transformation in its own chain, where
    // warps may interleave with it.
    void transform(const Transform& t) {
        Patterned& m = more_.edit();
        m.transform = m.transform.then(t);
        m.hasTransform = true;
        m.pattern.addTransform(t);
    }

  private:
    // Everything but the kind, the colour and uv_mapping: absent for a
    // plain colour (an empty box reads as these defaults).
    struct Patterned {
        std::optional<Color> quickColor;
        Pattern pattern;
        std::vector<std::shared_ptr<const Pigment>> list;
        ColorMap colorMap;
        std::vector<MapEntry> pigmentMap;
        std::shared_ptr<const ImageMap> imageMap;
        bool average = false;
        bool defaultColorMap = false;  // colorMap is the pattern's default
        bool hasTransform = false;
        Transform transform;
    };
    Kind kind_ = Kind::Solid;
    bool uvMapping_ = false;
    Color color_;  // POV-Ray's default pigment is black
    ValueBox<Patterned> more_;
};

// The pigment a texture starts with (black): one immutable instance that
// every default texture points at, without an allocation.
std::shared_ptr<const Pigment> defaultPigment();

// How much of the mirrored ray a surface adds (the 3.7 reflection block;
// `reflection C` is min = max = C). The reflectance at an angle of
// incidence with cosine c is min + (max - min) * (1 - c)^falloff, or
// min + (max - min) * Fresnel(c, ior) with fresnel; metallic tints it
// toward the pigment except at grazing angles; the reflected colour is
// raised to 1 / exponent before it is scaled.
struct Reflection {
    RGB min{0.0};
    RGB max{0.0};
    bool fresnel = false;
    double falloff = 1.0;
    double exponent = 1.0;
    double metallic = 0.0;

    bool any() const {
        return max.r > 0 || max.g > 0 || max.b > 0 || min.r > 0 || min.g > 0 || min.b > 0;
    }
};

// Thin-film iridescence (irid { amount thickness turbulence }).
struct Iridescence {
    double amount = 0.0;
    double thickness = 0.0;
    double turbulence = 0.0;
};

// POV-Ray 3.7 finish defaults.
struct Finish {
    RGB ambient{0.1};
    RGB emission{0.0};
    double diffuse = 0.6;
    double diffuseBack = 0.0;  // the second value of `diffuse a, b`: light through the surface
    double brilliance = 1.0;
    double crand = 0.0;
    double phong = 0.0;
    double phongSize = 40.0;
    double specular = 0.0;
    double roughness = 0.05;
    double metallic = 0.0;  // highlight tint toward the pigment (0 = white highlights)
    Reflection reflection;
    bool conserveEnergy = false;
    Iridescence irid;
    // The 2.0 forms `refraction` and `ior` in a finish: ior moves to the
    // object's interior when it has none of its own.
    double legacyIor = 0.0;  // 0 = not given
    // subsurface { translucency C }: light carried under the surface
    // (render/subsurface.h) takes the place of the lights' diffuse term
    // when global_settings has a subsurface block.
    bool subsurface = false;
    RGB translucency{
        0.0};  // per channel, the reciprocal of the reduced scattering coefficient (1/mm)
};

// povray's default finish: one immutable instance that every default
// texture points at, without an allocation.
std::shared_ptr<const Finish> defaultFinish();

// Which of a finish block's values were given with `albedo`: povray 3.7
// then reads them as the fraction of the light the surface sends back in
// all, and derives the coefficient from the lobe's shape (measured):
//   diffuse  = albedo * (brilliance + 1) / 2        (both values of diffuse)
//   phong    = albedo * (phong_size + 1) / 2
//   specular = albedo * (e + 2) / (4 * (2 - 2^(-e / 2))), e = 1 / roughness
struct FinishAlbedo {
    bool diffuse = false;
    bool phong = false;
    bool specular = false;
};

// Converts the albedo values of `f` to coefficients (see FinishAlbedo).
void applyAlbedo(Finish& f, const FinishAlbedo& albedo);

struct Texture;

// A patterned texture: `texture_map { [v texture body] .. }`, a list
// pattern's textures (`checker texture {..} texture {..}`, `tiles`), or
// `average` over a texture_map, or a `material_map` (an image whose pixels
// pick the textures). The pattern carries its chain of transformations and
// warps.
struct TextureMap {
    enum class Mode { Values, List, Average, Material };
    struct Entry {
        double value;  // map value; the weight under `average`
        std::shared_ptr<const Texture> texture;
    };
    Pattern pattern;
    Mode mode = Mode::Values;
    std::vector<Entry> entries;
    // material_map: the image whose scalar texels are texture indices.
    std::shared_ptr<const ImageMap> material;

    // The entry a material_map index picks (povray 3.7, measured with 1 to
    // 8 textures: an index past the end wraps modulo the count, except
    // that the index equal to the count takes the last texture).
    static std::size_t materialEntry(double index, std::size_t count) {
        const auto i = static_cast<std::size_t>(std::max(0.0, index));
        return i > count ? i % count : std::min(i, count - 1);
    }

    // Calls visit(texture, weight) for each texture that colours texture
    // point q: one or two for a map (povray 3.7 shades both and blends the
    // results, measured), one for a list pattern, all for `average`.
    template <typename Visit>
    void visit(const Vec3& q, Visit&& visit, const SurfaceInfo* surface = nullptr) const;

    // Moves the pattern and every entry by t.
    void transformBy(const Transform& t);

    // Where the entries are evaluated for texture point p (mapEntryPoint).
    Vec3 entryPoint(const Vec3& p) const { return mapEntryPoint(pattern, p); }
};

// A texture is ~130 bytes: its pigment, finish and transformations are
// shared (never null; the defaults are shared instances), so the textures
// of 10^6 objects that differ only in colour carry little more than the
// pigment (issue 23).
struct Texture {
    std::shared_ptr<const Pigment> pigment = defaultPigment();
    std::shared_ptr<const Finish> finish = defaultFinish();
    // Object-to-texture space; a transform applied after the texture moves
    // it with the object (seed 003 B.3).
    SharedTransform transform;

    // uv_mapping: the texture (pigment, normal and patterned entries) is
    // evaluated at the surface's (u, v, 0) moved by `transform`, which
    // then holds only the texture's own transformations (those applied to
    // the object are ignored: povray 3.7, measured).
    bool uvMapping = false;
    // The transformations applied to a uv-mapped texture's object: they
    // leave the uv point alone but still turn the normal's perturbation
    // (measured: a bumps normal on a rotated sphere), also for the
    // textures of a uv-mapped texture's map.
    SharedTransform uvObjectTransform;
    // Adds t to uvObjectTransform of this texture, its layers and entries.
    void turnNormalsBy(const Transform& t);
    // The same for each entry of the map (copies; no-op without a map).
    void turnMapNormalsBy(const Transform& t);
    // Whether anything in the texture needs the surface's uv (the renderer
    // skips finding it otherwise: a mesh's uv costs a triangle search).
    bool usesUv() const;

    // Layered texture (seed 003 5.4.5): the layers under this one, the
    // nearest first. Each is a complete texture of its own; see
    // render::Tracer::shade for how povray composites them.
    std::vector<std::shared_ptr<const Texture>> layersBelow;

    // What the texture lets through at world point p (shadow rays): the
    // product of every layer's filter and transmit, black as soon as one
    // layer is opaque.
    // `uv`: the surface's (u, v, 0) for uv-mapped layers (p when unknown).
    RGB throughAt(const Vec3& p, const Vec3* uv = nullptr) const;

    // Puts this texture (with its own layers) under `upper`'s layers.
    void stackOn(Texture& upper) const;

    // Moves the texture, every layer with it, by t (a transformation given
    // after the texture in an object).
    void transformBy(const Transform& t);

    // Set for a patterned texture: its pigment, finish and normal are then
    // unused; a transformation moves the map's pattern and every entry
    // (measured: the textures of a map scale with it), so `transform`
    // stays the identity.
    std::shared_ptr<const TextureMap> map;

    // Normal perturbation (normals.h); none when null.
    std::shared_ptr<const Normal> normal;
    // The shading normal at world point p after the texture's normal, for a
    // unit normal n facing the viewer (slope and aoi read `surface`).
    // For a uv-mapped texture p is the surface's (u, v, 0), as uv is.
    Vec3 perturbNormal(const Vec3& p, const Vec3& n, const Vec3& uv,
                       const SurfaceInfo* surface = nullptr) const {
        if (!normal) return n;
        if (normal->uvMapping) return normalize(normal->perturb(uv, n, surface));
        if (uvObjectTransform.get().isIdentity()) {
            const Vec3 tn = normalize(transform.inverse().normal(n));
            return normalize(
                transform.normal(normal->perturb(transform.inversePoint(p), tn, surface)));
        }
        const Transform frame = transform.then(uvObjectTransform);
        const Vec3 tn = normalize(frame.inverse().normal(n));
        return normalize(frame.normal(normal->perturb(transform.inversePoint(p), tn, surface)));
    }
};

template <typename Visit>
void TextureMap::visit(const Vec3& q, Visit&& visit, const SurfaceInfo* surface) const {
    if (entries.empty()) return;
    switch (mode) {
        case Mode::List: {
            const auto i = static_cast<std::size_t>(std::max(0, pattern.index(q)));
            visit(*entries[std::min(i, entries.size() - 1)].texture, 1.0);
            return;
        }
        case Mode::Average: {
            double total = 0;
            for (const Entry& e : entries) total += e.value;
            if (total == 0) return;
            for (const Entry& e : entries)
                if (e.value != 0) visit(*e.texture, e.value / total);
            return;
        }
        case Mode::Material: {
            // Where the image does not reach (`once`) the first texture
            // shows (measured); interpolated indices are truncated.
            double u = 0, w = 0;
            double index = 0;
            if (material && material->imageCoordinates(pattern.patternPoint(q), u, w))
                index = std::floor(material->valueAtImagePoint(u, w));
            visit(*entries[materialEntry(index, entries.size())].texture, 1.0);
            return;
        }
        case Mode::Values:
            break;
    }
    const double v = pattern.value(q, surface);
    if (v <= entries.front().value) return visit(*entries.front().texture, 1.0);
    std::size_t hi = 1;
    while (hi < entries.size() && entries[hi].value <= v) ++hi;
    if (hi == entries.size()) return visit(*entries.back().texture, 1.0);
    const Entry& a = entries[hi - 1];
    const Entry& b = entries[hi];
    const double span = b.value - a.value;
    if (span <= 0) return visit(*b.texture, 1.0);
    const double t = (v - a.value) / span;
    visit(*a.texture, 1.0 - t);
    visit(*b.texture, t);
}

}  // namespace frameray::scene
