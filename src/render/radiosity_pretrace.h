// Radiosity's pretrace: the mosaic passes povray makes before the final
// render to fill the irradiance cache (render/radiosity.h).
#pragma once

#include "render/antialias.h"
#include "render/camera_rays.h"
#include "render/radiosity.h"
#include "render/tracer.h"

namespace frameray::render {

// Traces the pretrace passes over `window` (pixels of an image `width` x
// `height`): the first with blocks pretrace_start of the longer side wide,
// each next with blocks half as wide, the last pretrace_end wide (never
// under a pixel). One camera ray per block, at a spot within it moved by
// povray 3.7's jitter cycle (render/pretrace_jitter.h); its pixel colour is discarded, its
// radiosity lookups fill the cache. Runs on the calling thread, in a fixed order, tile by tile (see
// radiosity_pretrace.cpp).
void pretraceRadiosity(const Tracer& tracer, const CameraRays& camera, Radiosity& radiosity,
                       const PixelBlock& window, int width, int height, RayCounts& rays,
                       RadiosityCounts& counts);

}  // namespace frameray::render
