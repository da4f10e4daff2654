// Light sources (seed 003 §5.2.5).
#pragma once

#include "util/color.h"
#include "util/vec3.h"

namespace frameray::scene {

struct Light {
    Vec3 position;
    RGB color{1.0};
    bool shadowless = false;
};

}  // namespace frameray::scene
