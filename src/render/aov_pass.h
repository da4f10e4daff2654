// Extra layers for compositing (Output_AOVs): what the camera ray through
// each pixel's centre meets first, as separate channels beside the colour.
// A pass of its own after the frame's render, run only when a layer is
// asked for, so frames without AOVs pay nothing.
//
// What each layer holds, at the first surface a camera ray sees (the
// surfaces no_image hides are skipped, as the colour pass does):
// - depth (`Z`): distance along the ray from the camera, in scene units;
//   kAovMissDepth where the ray meets nothing.
// - normal (`N.x N.y N.z`): the surface's world-space unit normal, turned
//   to face the camera, before any `normal {}` perturbation; 0 on a miss.
// - object_id (`objectId`): 1 + the position of the top-level object (in
//   the order the scene declares them) the surface belongs to; 0 on a
//   miss. The same object has the same id in every frame as long as the
//   scene declares the same objects in the same order.
// - albedo (`albedo.R G B`): the colour of the top texture layer's pigment
//   at the point (a texture_map's entries blended as their weights say),
//   linear, without lighting, shadows, reflection or transparency; 0 on a
//   miss.
// One ray per pixel, whatever the anti-aliasing (a sample of the pixel's
// centre, as compositors expect for ids and depth); focal blur and mesh
// cameras use the camera's centre ray.
#pragma once

#include <string>
#include <vector>

#include "render/antialias.h"
#include "render/world.h"

namespace frameray::render {

struct AovRequest {
    bool depth = false;
    bool normal = false;
    bool objectId = false;
    bool albedo = false;
    bool any() const { return depth || normal || objectId || albedo; }
};

// Depth written where a camera ray meets nothing.
inline constexpr float kAovMissDepth = 1e10f;

// The layers' channels, named as compositors expect (Nuke, Blender):
// pixel-interleaved in `values`, names.size() floats per pixel, row-major
// from the top.
struct AovImage {
    int width = 0, height = 0;
    std::vector<std::string> names;
    std::vector<float> values;
};

// Pixels outside `window` (empty: the whole image) hold the miss values.
AovImage renderAovs(const World& world, const AovRequest& request, int width, int height,
                    const PixelBlock& window);

}  // namespace frameray::render
