// The camera (seed 003 §5.5): parsed settings, and the derived frame of
// vectors primary rays are built from.
#pragma once

#include "util/matrix.h"
#include "util/vec3.h"

namespace frameray::scene {

enum class Projection { Perspective, Orthographic };

struct Camera {
    Projection projection = Projection::Perspective;
    // POV-Ray's defaults; look_at, angle and sky are applied by finalize().
    Vec3 location{0, 0, 0};
    Vec3 direction{0, 0, 1};
    Vec3 up{0, 1, 0};
    Vec3 right{1.33, 0, 0};
    Vec3 sky{0, 1, 0};
};

}  // namespace frameray::scene
