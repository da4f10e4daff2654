// Normal perturbation (seed 003 §5.4.2): `normal { bumps | dents | wrinkles
// | ripples | waves | <any colour-mapped pattern> amount ... }` tilts the
// shading normal the way povray 3.7 does. The built-in normal patterns add
// a vector (vector noise, wave gradients) in pattern space; any other
// pattern is sampled at four points of a small tetrahedron around the hit
// point and the samples steer the normal.
#pragma once

#include <memory>
#include <vector>

#include "scene/image_map.h"
#include "scene/patterns.h"
#include "util/matrix.h"
#include "util/vec3.h"

namespace frameray::scene {

// Where the entries of a map (texture_map, normal_map) on `pattern` are
// evaluated for texture point p: povray evaluates them at the point the
// pattern's warps (turbulence, warp {}) displaced, so the entries of a
// turbulent map are turbulent too (measured). The entries carry the map's
// transformations themselves, so the displaced point is taken back through
// them; without warps this is p.
Vec3 mapEntryPoint(const Pattern& pattern, const Vec3& p);

struct Normal {
    // The pattern with its transformations, warps, turbulence, wave type,
    // frequency and phase.
    Pattern pattern;
    // The bump size (the number after the pattern, or bump_size).
    double amount = 0.5;
    // Size of the sampling tetrahedron for patterns that are not normal
    // patterns of their own (accuracy).
    double accuracy = 0.02;
    // uv_mapping in the normal: the pattern is evaluated at the surface's
    // (u, v, 0) through the normal's own transformations, and its
    // perturbation is not turned by the texture's or object's (measured).
    bool uvMapping = false;
    // bump_map: the image whose heights tilt the normal (the pattern's
    // chain still places it).
    std::shared_ptr<const ImageMap> bumpMap;

    // normal_map (the pattern value picks one or two normals), a list
    // pattern's normals (`checker normal {..} normal {..}`) or `average`:
    // the picked normals perturb the surface and their results are blended.
    enum class MapMode { None, Values, List, Average };
    struct MapEntry {
        double value;  // map value; the weight under `average`
        std::shared_ptr<const Normal> normal;
    };
    MapMode mapMode = MapMode::None;
    std::vector<MapEntry> map;

    // slope_map: the pattern value becomes a height by cubic interpolation
    // between entries that give a height and a slope at a value.
    struct SlopeEntry {
        double value, height, slope;
    };
    std::vector<SlopeEntry> slopeMap;

    // The perturbed unit normal at texture-space point p, where n is the
    // texture-space unit normal; `surface` (world-space normal and ray) is
    // what slope and aoi read.
    Vec3 perturb(const Vec3& p, const Vec3& n, const SurfaceInfo* surface = nullptr) const;

    // perturb() before the final normalisation.
    Vec3 perturbUnnormalized(const Vec3& p, const Vec3& n,
                             const SurfaceInfo* surface = nullptr) const;

    // Moves the pattern and the normals of its map by t.
    void transformBy(const Transform& t);

    // The slope map's height at pattern value v.
    double slopeHeight(double v) const;
};

}  // namespace frameray::scene
