#include "sdl/object_value.h"

namespace frameray::sdl {

void ObjectLights::transformBy(const Transform& t) {
    for (scene::Light& light : lights) light.transformBy(t);
    for (auto& child : children) {
        if (!child) continue;
        auto moved = std::make_shared<ObjectLights>(*child);
        moved->transformBy(t);
        child = std::move(moved);
    }
}

bool ObjectLights::any() const {
    if (!lights.empty() || isLightGroup) return true;
    for (const auto& child : children)
        if (child && child->any()) return true;
    return false;
}

void ObjectValue::transformBy(const Transform& t) {
    object->transformBy(t);
    if (!lights) return;
    auto moved = std::make_shared<ObjectLights>(*lights);
    moved->transformBy(t);
    lights = std::move(moved);
}

}  // namespace frameray::sdl
