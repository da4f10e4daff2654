// Light sources (seed 000 "Light Sources", seed 003 §5.2.5): point lights,
// spotlights, cylinder lights and parallel lights, each optionally an area
// light, with distance fading, and the modifiers that say which rays they
// reach (shadowless, projected_through). The geometry here is in world
// space; the parser applies the light's transforms as it reads them.
#pragma once

#include <memory>

#include "scene/photon_settings.h"
#include "util/color.h"
#include "util/matrix.h"
#include "util/vec3.h"

namespace frameray::scene {

struct Object;

enum class LightKind { Point, Spot, Cylinder };

// POV-Ray's cubic ease between two values: 0 at or below `low`, 1 at or
// above `high`, 3s^2 - 2s^3 in between (s the position between them).
// Measured against povray 3.7: this is exactly its spotlight edge.
double smoothEdge(double low, double high, double x);

// An area light: a size1 x size2 grid of point lights spanning axis1 x axis2
// around the light's position (seed 000 "Area Lights").
struct AreaLight {
    Vec3 axis1;
    Vec3 axis2;
    int size1 = 1;
    int size2 = 1;
    // Times the grid is split into quarters before the corner-difference
    // test may stop the subdivision. POV-Ray samples every point of the
    // grid when `adaptive` is not given, which a large level does.
    int adaptive = kSampleEveryPoint;
    bool jitter = false;
    bool circular = false;  // grid squeezed into a disc
    bool orient = false;    // grid turned to face each lit point

    static constexpr int kSampleEveryPoint = 100;

    // Offset from the light's centre of grid point (i, j), before orient
    // and jitter: axis1 * (i/(size1-1) - 1/2) + axis2 * (j/(size2-1) - 1/2),
    // a single point at the centre along an axis of size 1, and the
    // square-to-disc remapping when circular.
    Vec3 gridOffset(double i, double j, const Vec3& a1, const Vec3& a2) const;
};

struct Light {
    LightKind kind = LightKind::Point;
    Vec3 position;
    RGB color{1.0};
    Vec3 pointAt{0, 0, 1};
    // Spot: half angles in degrees. Cylinder: distances from the axis.
    double radius = 30;
    double falloff = 45;
    double tightness = 0;
    bool parallel = false;  // rays all parallel to pointAt - position
    double fadeDistance = 0;
    double fadePower = 0;
    bool shadowless = false;
    bool mediaInteraction = true;
    bool mediaAttenuation = false;
    LightPhotons photons;
    bool isArea = false;
    AreaLight area;
    // Only points whose ray to the light crosses this object are lit.
    std::shared_ptr<const Object> projectedThrough;
    // The visible stand-in (already placed at the light, no_shadow); the
    // scene gets a copy when the light is placed in it.
    std::shared_ptr<const Object> looksLike;

    // Applies `t` after everything so far: position, point_at, the area
    // axes, looks_like and projected_through move with it.
    void transformBy(const Transform& t);

    // Unit vector of the spot/cylinder/parallel axis, light towards target.
    Vec3 axis() const;
    // How much of the light's colour reaches `p` for the light's shape
    // (spot cone, cylinder) and its distance fading; 1 for a plain point
    // light. `distance` is the distance from p to the light (for fading).
    double attenuation(const Vec3& p, double distance) const;
};

}  // namespace frameray::scene
