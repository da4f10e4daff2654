// Surface appearance: pigment and finish (seed 003 §5.4). The skeleton has
// solid-colour pigments; patterns arrive with the textures issue behind the
// same Pigment interface.
#pragma once

#include <memory>

#include "util/color.h"
#include "util/matrix.h"

namespace frameray::scene {

class Pigment {
public:
    Pigment() = default;
    explicit Pigment(const Color& c) : color_(c) {}
    // Colour at a point in the texture's space.
    Color at(const Vec3& /*p*/) const { return color_; }
    const Color& solidColor() const { return color_; }

private:
    Color color_;  // POV-Ray's default pigment is black
};

// POV-Ray 3.7 finish defaults.
struct Finish {
    RGB ambient{0.1};
    RGB emission{0.0};
    double diffuse = 0.6;
    double brilliance = 1.0;
    double phong = 0.0;
    double phongSize = 40.0;
    double specular = 0.0;
    double roughness = 0.05;
    bool metallic = false;
};

struct Texture {
    std::shared_ptr<const Pigment> pigment = std::make_shared<Pigment>();
    Finish finish;
    // Object-to-texture space; a transform applied after the texture moves
    // it with the object (seed 003 B.3).
    Transform transform;
};

}  // namespace frameray::scene
