// Renders one frame: primary rays through the camera for every pixel of
// the render window, in tiles spread over threads by oneTBB. The result is
// deterministic whatever the thread count (each pixel depends only on its
// own coordinates).
#pragma once

#include <cstdint>
#include <vector>

#include "render/tracer.h"
#include "render/world.h"

namespace frameray::render {

struct FrameSettings {
    int width = 320;
    int height = 240;
    int quality = 9;  // +Q: fog and rainbows from 9 up
};

// Linear working-space colours, clipped to [0,1], row-major from the top.
struct FrameImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;  // 3 floats per pixel
};

struct FrameStats {
    RayCounts rays;
};

FrameImage renderFrame(const World& world, const FrameSettings& settings, FrameStats& stats);

// The camera ray through the centre of pixel (x, y).
scene::Ray primaryRay(const scene::Camera& camera, double x, double y, int width, int height);

}  // namespace frameray::render
