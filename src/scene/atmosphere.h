// The scene's atmosphere (seed 003 §5.6): fogs, the sky sphere and
// rainbows, as parsed. The background colour stays in scene::Scene; how a
// ray sees all of them is render/atmosphere.
//
// Angles and vectors are stored the way POV-Ray 3.7 stores them after
// parsing (radians, normalised, its quirks included), so the renderer
// evaluates them with POV-Ray's formulas unchanged.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "scene/color_map.h"
#include "scene/media.h"
#include "scene/texture.h"
#include "util/color.h"
#include "util/matrix.h"
#include "util/vec3.h"

namespace frameray::scene {

struct Fog {
    // fog_type 2 is ground fog; every other value (1, and unknown types,
    // which povray warns about) is constant fog.
    enum class Kind { Constant, Ground };

    Kind kind = Kind::Constant;
    int typeNumber = 1;   // fog_type as given
    double distance = 0;  // a fog with |distance| <= 1e-10 has no effect
    Color color;          // filter tints what is behind, transmit is the least transmittance
    double offset = 0;    // ground fog: the height where it starts thinning
    double altitude = 0;  // ground fog: the height scale of the thinning
    Vec3 up{0, 1, 0};     // normalised; rotated/scaled by the fog's transformations
    // turbulence, octaves, omega, lambda (any of them makes one, amount 0
    // by default) and turb_depth: the fog thins or thickens by the
    // turbulence halfway along the ray (render/atmosphere.cpp).
    std::optional<Turbulence> turbulence;
    double turbulenceDepth = 0.5;
};

struct SkySphere {
    // Layers in the order written; the last one is the innermost (evaluated
    // first), as a layered texture.
    std::vector<std::shared_ptr<const Pigment>> pigments;
    RGB emission{1.0};
    // Maps the sky's space to the world; pigments are evaluated at the
    // inverse image of the (unit) ray direction, translation included.
    Transform transform;
};

struct Rainbow {
    // Start of the colour band and its width, both in radians
    // (povray: angle - width/2 and width, converted at the end of parsing).
    double bandStart = 0;
    double width = 0;
    double distance = 1.0e7;  // povray's MAX_DISTANCE
    double jitter = 0;
    // Half of arc_angle and of falloff_angle, in radians. Unset, both keep
    // povray's raw default 180 (not converted), which no ray angle reaches.
    double arcAngle = 180.0;
    double falloffAngle = 180.0;
    double falloffWidth = 0;  // arcAngle - falloffAngle
    Vec3 antisolar;           // direction, normalised
    Vec3 up{0, 1, 0};         // normalised, made perpendicular to antisolar
    Vec3 right{1, 0, 0};      // up x antisolar, normalised
    // Without a colour map a rainbow shows nothing.
    std::optional<ColorMap> colorMap;
};

struct Atmosphere {
    std::vector<Fog> fogs;
    std::optional<SkySphere> skySphere;  // povray keeps only the last one
    std::vector<Rainbow> rainbows;
    // Scene-level media { }: fills the open air (and hollow objects).
    MediaList media;
};

}  // namespace frameray::scene
