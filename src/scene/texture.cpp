#include "scene/texture.h"

#include <cmath>

namespace frameray::scene {

void applyAlbedo(Finish& f, const FinishAlbedo& albedo) {
    if (albedo.diffuse) {
        const double k = (f.brilliance + 1.0) / 2.0;
        f.diffuse *= k;
        f.diffuseBack *= k;
    }
    if (albedo.phong) f.phong *= (f.phongSize + 1.0) / 2.0;
    if (albedo.specular) {
        const double e = 1.0 / f.roughness;
        f.specular *= (e + 2.0) / (4.0 * (2.0 - std::pow(2.0, -e / 2.0)));
    }
}

namespace {

// povray's built-in colour maps for patterns given without one (measured
// from its renders); every other pattern defaults to black to white.
ColorMap defaultColorMap(const Pattern& pattern) {
    auto rgb = [](double r, double g, double b) { return Color(RGB(r, g, b)); };
    switch (pattern.kind) {
        case PatternKind::Bozo:
            return ColorMap({{0.4, rgb(1, 1, 1)},
                             {0.4, rgb(0, 1, 0)},
                             {0.6, rgb(0, 1, 0)},
                             {0.6, rgb(0, 0, 1)},
                             {0.8, rgb(0, 0, 1)},
                             {0.8, rgb(1, 0, 0)}});
        case PatternKind::Marble:
            return ColorMap(
                {{0.0, rgb(0.9, 0.8, 0.8)}, {0.9, rgb(0.9, 0.08, 0.08)}, {0.9, rgb(0, 0, 0)}});
        case PatternKind::Wood:
            return ColorMap({{0.6, rgb(0.666, 0.312, 0.2)}, {0.6, rgb(0.4, 0.1333, 0.066)}});
        case PatternKind::Agate:
            return ColorMap({{0.0, rgb(1, 1, 1)},
                             {0.5, rgb(0.95, 0.75, 0.5)},
                             {0.5, rgb(0.9, 0.7, 0.5)},
                             {0.6, rgb(0.9, 0.7, 0.4)},
                             {0.6, rgb(1.0, 0.7, 0.4)},
                             {1.0, rgb(0.6, 0.3, 0.0)}});
        case PatternKind::Radial:
            // Cyan, yellow, magenta and back around the circle (measured).
            return ColorMap({{0.0, rgb(0, 1, 1)},
                             {1.0 / 3.0, rgb(1, 1, 0)},
                             {2.0 / 3.0, rgb(1, 0, 1)},
                             {1.0, rgb(0, 1, 1)}});
        case PatternKind::Fractal:
            // Only the plain mandel (exponent 2) has one: black up to 0.001,
            // then cyan, yellow, magenta by 0.015 and cyan from 0.1 (measured
            // at 1000 iterations; julia, magnet, other exponents are grey).
            if (pattern.fractal.kind == FractalSettings::Kind::Mandel &&
                pattern.fractal.exponent == 2)
                return ColorMap({{0.001, rgb(0, 0, 0)},
                                 {0.001, rgb(0, 1, 1)},
                                 {0.012, rgb(1, 1, 0)},
                                 {0.015, rgb(1, 0, 1)},
                                 {0.1, rgb(0, 1, 1)}});
            return ColorMap::grayscale();
        default:
            return ColorMap::grayscale();
    }
}

}  // namespace

std::shared_ptr<const Pigment> defaultPigment() {
    static const Pigment black;
    // Aliasing an empty owner: no allocation, no reference count.
    return {std::shared_ptr<const Pigment>(), &black};
}

std::shared_ptr<const Finish> defaultFinish() {
    static const Finish finish;
    return {std::shared_ptr<const Finish>(), &finish};
}

void Pigment::setPattern(const Pattern& p) {
    Patterned& m = more_.edit();
    m.pattern = p;
    m.average = false;
    // A pigment_map given before the pattern keyword still applies.
    kind_ = p.isList()              ? Kind::List
            : !m.pigmentMap.empty() ? Kind::PigmentMapped
                                    : Kind::ColorMapped;
    if (kind_ == Kind::ColorMapped && (m.colorMap.empty() || m.defaultColorMap)) {
        m.colorMap = defaultColorMap(p);
        m.defaultColorMap = true;
    }
}

void Pigment::settleDefaultColorMap() {
    if (!more_.holds() || !more_.get().defaultColorMap) return;
    Patterned& m = more_.edit();
    m.colorMap = defaultColorMap(m.pattern);
}

void Pigment::setColorMap(ColorMap map) {
    Patterned& m = more_.edit();
    m.colorMap = std::move(map);
    m.defaultColorMap = false;
    if (kind_ == Kind::PigmentMapped) kind_ = Kind::ColorMapped;
}

void Pigment::setPigmentMap(std::vector<MapEntry> map) {
    more_.edit().pigmentMap = std::move(map);
    kind_ = Kind::PigmentMapped;
}

Color Pigment::at(const Vec3& given, const SurfaceInfo* surface) const {
    if (kind_ == Kind::Solid) return color_;
    const Patterned& m = more_.get();
    const Pattern& pattern = m.pattern;
    const auto& pigmentMap = m.pigmentMap;
    const Vec3 point = uvMapping_ && surface ? surface->uv : given;
    const SurfaceInfo* sub = surface;  // world-space: the same for sub-pigments
    // Sub-pigments are evaluated in this pigment's space, at the point its
    // warps displaced (povray: the entries of a turbulent map are
    // turbulent too; measured). Only lists and pigment maps have entries:
    // a colour map does not pay for the warps twice.
    auto entryPoint = [&] {
        Vec3 q = mapEntryPoint(pattern, point);
        if (m.hasTransform) q = m.transform.inversePoint(q);
        return q;
    };
    switch (kind_) {
        case Kind::List: {
            const auto i = static_cast<std::size_t>(pattern.index(point));
            return i < m.list.size() && m.list[i] ? m.list[i]->at(entryPoint(), sub) : Color();
        }
        case Kind::ColorMapped:
            return m.colorMap.at(pattern.value(point, surface));
        case Kind::PigmentMapped: {
            if (pigmentMap.empty()) return Color();
            const Vec3 p = entryPoint();
            if (m.average) {
                // Every entry weighted by its value (povray's `average`).
                double total = 0;
                RGB rgb(0.0);
                double filter = 0, transmit = 0;
                for (const MapEntry& e : pigmentMap) {
                    if (e.value == 0) continue;
                    const Color c = e.pigment->at(p, sub);
                    rgb += c.rgb * e.value;
                    filter += c.filter * e.value;
                    transmit += c.transmit * e.value;
                    total += e.value;
                }
                if (total == 0) return Color();
                return Color(rgb * (1.0 / total), filter / total, transmit / total);
            }
            const double v = pattern.value(point, surface);
            if (v <= pigmentMap.front().value) return pigmentMap.front().pigment->at(p, sub);
            std::size_t hi = 1;
            while (hi < pigmentMap.size() && pigmentMap[hi].value <= v) ++hi;
            if (hi == pigmentMap.size()) return pigmentMap.back().pigment->at(p, sub);
            const MapEntry& a = pigmentMap[hi - 1];
            const MapEntry& b = pigmentMap[hi];
            const double span = b.value - a.value;
            if (span <= 0) return b.pigment->at(p, sub);
            const double t = (v - a.value) / span, s = 1.0 - t;
            const Color ca = a.pigment->at(p, sub), cb = b.pigment->at(p, sub);
            return Color(ca.rgb * s + cb.rgb * t, ca.filter * s + cb.filter * t,
                         ca.transmit * s + cb.transmit * t);
        }
        case Kind::ImageMapped:
            return m.imageMap->colorAt(pattern.patternPoint(point));
        case Kind::Solid:
            break;
    }
    return color_;
}

RGB Texture::throughAt(const Vec3& p, const Vec3* uv) const {
    SurfaceInfo surface{};
    if (uv) surface.uv = *uv;
    const SurfaceInfo* info = uv ? &surface : nullptr;
    if (map) {
        // Blended like the shaded colours (povray 3.7, measured).
        RGB through(0.0);
        const Vec3 q = transform.inversePoint(uvMapping && uv ? *uv : p);
        const Vec3 entry = map->entryPoint(q);
        map->visit(q, [&](const Texture& t, double w) { through += t.throughAt(entry, uv) * w; });
        return through;
    }
    RGB passed(1.0);
    const std::size_t layerCount = 1 + layersBelow.size();
    // One opaque layer makes the product black: settle that before any
    // pattern is evaluated (the loop below would return black at that
    // layer at the latest).
    for (std::size_t i = 0; i < layerCount; ++i)
        if ((i == 0 ? *this : *layersBelow[i - 1]).pigment->alwaysOpaque()) return RGB(0.0);
    for (std::size_t i = 0; i < layerCount; ++i) {
        const Texture& layer = i == 0 ? *this : *layersBelow[i - 1];
        const Vec3 at = layer.uvMapping && uv ? *uv : p;
        const Color c = layer.pigment->at(layer.transform.inversePoint(at), info);
        if (c.filter == 0 && c.transmit == 0) return RGB(0.0);
        passed *= c.rgb * c.filter + RGB(c.transmit);
    }
    return passed;
}

void Texture::stackOn(Texture& upper) const {
    // Layers are kept flat: this texture without its layers, then its layers.
    Texture alone = *this;
    alone.layersBelow.clear();
    upper.layersBelow.push_back(std::make_shared<const Texture>(std::move(alone)));
    upper.layersBelow.insert(upper.layersBelow.end(), layersBelow.begin(), layersBelow.end());
}

void TextureMap::transformBy(const Transform& t) {
    pattern.addTransform(t);
    for (auto& e : entries) {
        auto tex = std::make_shared<Texture>(*e.texture);
        tex->transformBy(t);
        e.texture = std::move(tex);
    }
}

bool Pigment::alwaysOpaque() const {
    const auto opaque = [](const Color& c) { return c.filter == 0 && c.transmit == 0; };
    switch (kind_) {
        case Kind::Solid:
            return opaque(color_);
        case Kind::List:
            // A missing entry reads as black.
            return std::all_of(more_.get().list.begin(), more_.get().list.end(),
                               [](const auto& p) { return !p || p->alwaysOpaque(); });
        case Kind::ColorMapped: {
            const auto& entries = more_.get().colorMap.entries();
            return std::all_of(entries.begin(), entries.end(),
                               [&](const ColorMap::Entry& e) { return opaque(e.color); });
        }
        case Kind::PigmentMapped: {
            const auto& map = more_.get().pigmentMap;
            return std::all_of(map.begin(), map.end(), [](const MapEntry& e) {
                return e.pigment && e.pigment->alwaysOpaque();
            });
        }
        case Kind::ImageMapped:
            return false;
    }
    return false;
}

bool Pigment::usesUv() const {
    if (uvMapping_) return true;
    if (!more_.holds()) return false;
    for (const auto& p : more_.get().list)
        if (p && p->usesUv()) return true;
    for (const MapEntry& e : more_.get().pigmentMap)
        if (e.pigment && e.pigment->usesUv()) return true;
    return false;
}

bool Texture::usesUv() const {
    if (uvMapping || (pigment && pigment->usesUv()) || (normal && normal->uvMapping)) return true;
    for (const auto& layer : layersBelow)
        if (layer->usesUv()) return true;
    if (map)
        for (const TextureMap::Entry& e : map->entries)
            if (e.texture->usesUv()) return true;
    return false;
}

void Texture::turnNormalsBy(const Transform& t) {
    uvObjectTransform = uvObjectTransform.then(t);
    for (auto& layer : layersBelow) {
        auto turned = std::make_shared<Texture>(*layer);
        turned->turnNormalsBy(t);
        layer = std::move(turned);
    }
    turnMapNormalsBy(t);
}

void Texture::turnMapNormalsBy(const Transform& t) {
    if (!map) return;
    auto turned = std::make_shared<TextureMap>(*map);
    for (auto& e : turned->entries) {
        auto entry = std::make_shared<Texture>(*e.texture);
        entry->turnNormalsBy(t);
        e.texture = std::move(entry);
    }
    map = std::move(turned);
}

void Texture::transformBy(const Transform& t) {
    if (uvMapping) {
        // Fixed to the surface's uv: only the layers below may move, and
        // the normal's perturbation turns with the object.
        uvObjectTransform = uvObjectTransform.then(t);
        // The entries stay on the uv too; their normals turn.
        turnMapNormalsBy(t);
        for (auto& layer : layersBelow) {
            auto moved = std::make_shared<Texture>(*layer);
            moved->transformBy(t);
            layer = std::move(moved);
        }
        return;
    }
    if (map) {
        auto moved = std::make_shared<TextureMap>(*map);
        moved->transformBy(t);
        map = std::move(moved);
        return;
    }
    transform = transform.then(t);
    for (auto& layer : layersBelow) {
        auto moved = std::make_shared<Texture>(*layer);
        moved->transformBy(t);
        layer = std::move(moved);
    }
}

}  // namespace frameray::scene
