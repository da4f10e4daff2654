// A scene object: a shape placed by a transform, with its texture and the
// object modifiers (seed 003 §5.3).
#pragma once

#include <memory>

#include "scene/shapes.h"
#include "scene/texture.h"

namespace frameray::scene {

struct Object {
    std::shared_ptr<const Shape> shape;
    Transform transform;  // object space -> world space
    std::shared_ptr<const Texture> texture;  // null: the default texture
    bool noShadow = false;
    bool noImage = false;
    bool noReflection = false;

    // World-space bounds (conservative), infinite when the shape is unbounded.
    Bounds worldBounds() const;
};

}  // namespace frameray::scene
