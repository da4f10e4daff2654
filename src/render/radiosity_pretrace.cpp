#include "render/radiosity_pretrace.h"

#include <algorithm>
#include <cmath>

#include "util/sample_random.h"

namespace frameray::render {

void pretraceRadiosity(const Tracer& tracer, const CameraRays& camera, Radiosity& radiosity,
                       const PixelBlock& window, int width, RayCounts& rays,
                       RadiosityCounts& counts) {
    const scene::RadiositySettings& set = radiosity.settings();
    RadiosityTask task(radiosity, true, true);
    // The passes halve the block size from pretrace_start down to
    // pretrace_end (povray's pass count: 0.08 to 0.02 is three passes).
    // Each pass goes tile by tile (povray's 32-pixel render blocks, in
    // rows). Within a tile the spots lie on a grid of the pass's step,
    // aligned across the image, each at its cell's centre moved by up to a
    // pixel (hashed from the pass and the spot). At +WT1 povray lets every
    // lookup see every sample gathered so far, whichever tile gathered it.
    constexpr int kTile = 32;
    const int tilesX = (window.x1 - window.x0 + kTile - 1) / kTile;
    const int tilesY = (window.y1 - window.y0 + kTile - 1) / kTile;
    int pass = 0;
    for (double fraction = set.pretraceStart;; fraction *= 0.5, ++pass) {
        const double step = std::max(1.0, std::max(fraction, set.pretraceEnd) * width);
        const double jitter = std::min(1.0, step / 2);
        const double offset = (step - 1) / 2;
        task.setTile(pass + 1, 0);
        for (int tile = 0; tile < tilesX * tilesY; ++tile) {
            const int tx0 = window.x0 + (tile % tilesX) * kTile;
            const int ty0 = window.y0 + (tile / tilesX) * kTile;
            const int tx1 = std::min(tx0 + kTile, window.x1);
            const int ty1 = std::min(ty0 + kTile, window.y1);
            for (double gy = std::ceil((ty0 - 0.5) / step) * step; gy < ty1; gy += step)
                for (double gx = std::ceil((tx0 - 0.5) / step) * step; gx < tx1; gx += step) {
                    SampleRandom r(gx, gy, static_cast<std::uint64_t>(pass) + 0x5ad105ULL);
                    const double x = std::clamp(gx + offset + jitter * (2 * r.next() - 1) + 0.5,
                                                double(window.x0), window.x1 - 1e-6);
                    const double y = std::clamp(gy + offset + jitter * (2 * r.next() - 1) + 0.5,
                                                double(window.y0), window.y1 - 1e-6);
                    if (const std::optional<scene::Ray> ray = camera.generate(x, y))
                        tracer.traceCamera(*ray, rays, nullptr, &task);
                }
        }
        if (fraction <= set.pretraceEnd * (1 + 1e-9) || step <= 1.0) break;
    }
    counts += task.counts;
}

}  // namespace frameray::render
