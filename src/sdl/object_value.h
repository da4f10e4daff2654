// An object as the scene language holds it until it is placed in the
// scene: the scene::Object, and the light sources written inside its CSG
// nodes and light_groups, which move with it. Placing the object
// (placeObjectLights) hands those lights to the scene or to the light
// group's primitives; the scene model never carries them.
#pragma once

#include <memory>
#include <vector>

#include "scene/lights.h"
#include "scene/object.h"

namespace frameray::sdl {

// The lights of one CSG node and of the nodes below it (null where a
// subtree holds none).
struct ObjectLights {
    std::vector<scene::Light> lights;  // written in this node, world space
    bool isLightGroup = false;         // the node is a light_group ...
    bool globalLights = false;         // ... and its global_lights value
    // Index-aligned with the node's children.
    std::vector<std::shared_ptr<const ObjectLights>> children;

    // Moves every light of the tree by t (a transformation of the object).
    void transformBy(const Transform& t);
    // Whether a light or a light_group lies anywhere in the tree.
    bool any() const;
};

struct ObjectValue {
    std::shared_ptr<scene::Object> object;
    std::shared_ptr<const ObjectLights> lights;  // null: no lights inside

    // Applies t to the object and to its lights.
    void transformBy(const Transform& t);
};

}  // namespace frameray::sdl
