// Renders one frame: primary rays through the camera for every pixel of
// the render window, in blocks spread over threads by oneTBB, anti-aliased
// as render/antialias.h describes. The result is deterministic whatever the
// thread count (each block depends only on its own position).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "render/antialias.h"
#include "render/photons.h"
#include "render/radiosity_cache.h"
#include "render/tracer.h"
#include "render/world.h"

namespace frameray::render {

struct FrameSettings {
    int width = 320;
    int height = 240;
    // The pixels rendered, [x0,x1) x [y0,y1); empty means the whole image.
    // Pixels outside stay black.
    PixelBlock window{0, 0, 0, 0};
    int blockSize = 32;  // Render_Block_Size: anti-aliasing depends on it
    AntialiasSettings antialias;
    int quality = 9;  // +Q: fog and rainbows from 9 up
    // Output_Alpha (+UA): the background turns transparent black and each
    // pixel keeps how much of it shows through (FrameImage::alpha).
    bool alpha = false;
    // Radiosity samples the frame's cache starts with (a cache file, or
    // the first frame's cache in Radiosity_Stable sequences); the pretrace
    // and the final pass add to them. Null: an empty cache.
    std::shared_ptr<const std::vector<RadiositySample>> radiosityStart;
    // Keep the frame's whole cache in FrameImage::radiosityCache.
    bool keepRadiosity = false;
};

// Linear working-space colours, clipped to [0,1], row-major from the top.
struct FrameImage {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;  // 3 floats per pixel
    // With FrameSettings::alpha: 1 - transmittance per pixel, in [0, 1];
    // rgb is then what the visible surfaces add (the background adds
    // nothing). Empty otherwise.
    std::vector<float> alpha;
    // With FrameSettings::keepRadiosity: the samples the frame started
    // with, those its pretrace added, then each final-pass block's in
    // block order (the same for any thread count).
    std::vector<RadiositySample> radiosityCache;
};

struct FrameStats {
    RayCounts rays;
    AntialiasCounts antialias;
    RadiosityCounts radiosity;
    // The photon map's figures, when the scene shot photons.
    std::optional<PhotonStats> photons;
};

FrameImage renderFrame(const World& world, const FrameSettings& settings, FrameStats& stats);

}  // namespace frameray::render
