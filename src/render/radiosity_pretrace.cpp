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
    // rows); a lookup sees the samples of earlier passes and of its own
    // tile, never those other tiles of its pass gathered.
    constexpr int kTile = 32;
    const int tilesX = (window.x1 - window.x0 + kTile - 1) / kTile;
    const int tilesY = (window.y1 - window.y0 + kTile - 1) / kTile;
    int pass = 0;
    for (double fraction = set.pretraceStart;; fraction *= 0.5, ++pass) {
        const double step = std::max(1.0, fraction * width);
        const int columns = static_cast<int>(std::ceil((window.x1 - window.x0) / step));
        const int rows = static_cast<int>(std::ceil((window.y1 - window.y0) / step));
        for (int tile = 0; tile < tilesX * tilesY; ++tile) {
            task.setTile(pass + 1, tile);
            const int tx0 = window.x0 + (tile % tilesX) * kTile;
            const int ty0 = window.y0 + (tile / tilesX) * kTile;
            for (int j = 0; j < rows; ++j)
                for (int i = 0; i < columns; ++i) {
                    SampleRandom jitter(i, j, static_cast<std::uint64_t>(pass) + 0x5ad105ULL);
                    const double x =
                        std::min(window.x0 + (i + jitter.next()) * step, window.x1 - 1e-6);
                    const double y =
                        std::min(window.y0 + (j + jitter.next()) * step, window.y1 - 1e-6);
                    // The spot belongs to the tile it falls in.
                    if (x < tx0 || x >= tx0 + kTile || y < ty0 || y >= ty0 + kTile) continue;
                    if (const std::optional<scene::Ray> ray = camera.generate(x, y))
                        tracer.traceCamera(*ray, rays, nullptr, &task);
                }
        }
        if (fraction <= set.pretraceEnd * (1 + 1e-9) || step <= 1.0) break;
    }
    counts += task.counts;
}

}  // namespace frameray::render
