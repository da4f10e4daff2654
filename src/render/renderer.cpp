#include "render/renderer.h"

#include <tbb/blocked_range2d.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace frameray::render {

namespace {
constexpr int kTileSize = 16;
}

scene::Ray primaryRay(const scene::Camera& camera, double x, double y, int width, int height) {
    // Screen coordinates in [-0.5, 0.5], y up.
    const double sx = x / width - 0.5;
    const double sy = 0.5 - y / height;
    return {camera.location, camera.direction + camera.right * sx + camera.up * sy};
}

FrameImage renderFrame(const World& world, const FrameSettings& settings, FrameStats& stats) {
    FrameImage image;
    image.width = settings.width;
    image.height = settings.height;
    image.rgb.assign(static_cast<size_t>(settings.width) * settings.height * 3, 0.0f);
    const Tracer tracer(world, settings.quality >= 9);
    const scene::Camera& camera = world.scene().camera;
    tbb::combinable<RayCounts> counts;

    tbb::parallel_for(
        tbb::blocked_range2d<int>(0, settings.height, kTileSize, 0, settings.width, kTileSize),
        [&](const tbb::blocked_range2d<int>& tile) {
            RayCounts& local = counts.local();
            for (int y = tile.rows().begin(); y < tile.rows().end(); ++y)
                for (int x = tile.cols().begin(); x < tile.cols().end(); ++x) {
                    const scene::Ray ray =
                        primaryRay(camera, x + 0.5, y + 0.5, settings.width, settings.height);
                    const RGB c = tracer.traceCamera(ray, local);
                    float* out = &image.rgb[(static_cast<size_t>(y) * settings.width + x) * 3];
                    out[0] = static_cast<float>(std::clamp(c.r, 0.0, 1.0));
                    out[1] = static_cast<float>(std::clamp(c.g, 0.0, 1.0));
                    out[2] = static_cast<float>(std::clamp(c.b, 0.0, 1.0));
                }
        });
    counts.combine_each([&](const RayCounts& c) { stats.rays += c; });
    return image;
}

}  // namespace frameray::render
