#include "render/radiosity_pretrace.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <utility>
#include <vector>

#include "render/pretrace_jitter.h"

namespace frameray::render {

namespace {

// The lines start, start + step, ... below `end`, each the one before plus
// step, as povray steps its pretrace grid (its spots' positions to the
// last bit).
std::vector<double> gridLines(double start, double end, double step) {
    std::vector<double> lines;
    double line = start;
    while (line < end) {
        lines.push_back(line);
        line += step;
    }
    return lines;
}

}  // namespace

void pretraceRadiosity(const Tracer& tracer, const CameraRays& camera, Radiosity& radiosity,
                       const PixelBlock& window, int width, int height, RayCounts& rays,
                       RadiosityCounts& counts) {
    const scene::RadiositySettings& set = radiosity.settings();
    RadiosityTask task(radiosity, true, true);
    // The passes halve the block size from pretrace_start down to
    // pretrace_end (povray's pass count: 0.08 to 0.02 is three passes).
    // Each pass goes tile by tile (povray's 32-pixel render blocks, in
    // rows). Within a tile the spots lie on a grid of the pass's step,
    // aligned across the image, each at its cell's centre moved by up to a
    // pixel (povray's jitter cycle, render/pretrace_jitter.h), even where that lies past
    // the image's edge. At +WT1 povray lets every
    // lookup see every sample gathered so far, whichever tile gathered it.
    //
    // A tile (or, with nearest_count's second value, each part of it) goes
    // on to the next pass unless its lookups found no diffuse surface, or
    // (adaptive pretrace) their weights already cover the second value on
    // average; a part of at least 9 spots may be split for the next pass
    // into parts of at least 4 x 4 of its spots (povray 3.7's rules).
    constexpr int kTile = 32;
    const int tilesX = (window.x1 - window.x0 + kTile - 1) / kTile;
    const int tilesY = (window.y1 - window.y0 + kTile - 1) / kTile;
    const int coverage = set.nearestCountPretrace;
    struct TileState {
        int partsX = 1, partsY = 1;
        std::deque<std::pair<int, int>> open{{0, 0}};  // parts still refining
    };
    std::vector<TileState> tiles(static_cast<size_t>(tilesX * tilesY));
    // Block sizes are fractions of the image's longer side (povray 3.7).
    const double longer = std::max(width, height);
    const double startSize = longer * set.pretraceStart;
    const double endSize = std::max(1.0, longer * set.pretraceEnd);
    std::vector<double> sizes;
    for (double size = startSize;; size *= 0.5) {
        sizes.push_back(std::max(size, endSize));
        if (size <= endSize * (1 + 1e-9)) break;
    }
    const PretraceJitter jitterCycle;
    for (size_t pass = 0; pass < sizes.size(); ++pass) {
        const double step = sizes[pass];
        const double nextStep = pass + 1 < sizes.size() ? sizes[pass + 1] : step;
        const double jitter = std::min(1.0, step / 2);
        const double offset = (step - 1) / 2;
        task.setTile(static_cast<int>(pass) + 1, 0);
        for (int tile = 0; tile < tilesX * tilesY; ++tile) {
            TileState& state = tiles[static_cast<size_t>(tile)];
            if (state.open.empty()) continue;
            PretraceJitter::Walk walk(jitterCycle, static_cast<int>(pass) + 1, tile);
            const int tx0 = window.x0 + (tile % tilesX) * kTile;
            const int ty0 = window.y0 + (tile / tilesX) * kTile;
            const int tw = std::min(tx0 + kTile, window.x1) - tx0;
            const int th = std::min(ty0 + kTile, window.y1) - ty0;
            const auto spots = [](int extent, double size) {
                return static_cast<int>(static_cast<unsigned>((extent + size - 1) / size));
            };
            const int divideX =
                coverage ? std::max(1, spots(tw, nextStep) / (state.partsX * 4)) : 1;
            const int divideY =
                coverage ? std::max(1, spots(th, nextStep) / (state.partsY * 4)) : 1;
            const double startX = std::ceil((tx0 - 0.5) / step) * step;
            const double startY = std::ceil((ty0 - 0.5) / step) * step;
            const size_t parts = state.open.size();
            for (size_t part = 0; part < parts; ++part) {
                const auto [px, py] = state.open.front();
                state.open.pop_front();
                const double x0 = tx0 + double(tw) * px / state.partsX;
                const double x1 = x0 + double(tw) / state.partsX;
                const double y0 = ty0 + double(th) * py / state.partsY;
                const double y1 = y0 + double(th) / state.partsY;
                task.topQueries = 0;
                task.topCoverage = 0;
                int traced = 0;
                const std::vector<double> columns = gridLines(startX, x1, step);
                for (const double gy : gridLines(startY, y1, step)) {
                    if (gy < y0) continue;
                    for (const double gx : columns) {
                        if (gx < x0) continue;
                        // Each spot takes the walk's next two numbers, the
                        // first for y, the second for x (povray 3.7 at +WT1).
                        // Not kept within the image: povray's spots of the last
                        // row and column lie at their cells' centres, beyond
                        // the edge when the cell reaches past it (measured from
                        // its cache file).
                        const double jy = walk.next();
                        const double jx = walk.next();
                        const double x = gx + offset + jitter * jx + 0.5;
                        const double y = gy + offset + jitter * jy + 0.5;
                        ++traced;
                        // A mesh_camera's pixel has its own rays (none, one
                        // or several); every other projection one.
                        // (A mesh_camera's spots stay on its pixels.)
                        if (std::vector<scene::Ray> meshRays; camera.meshRays(
                                std::clamp(x, double(window.x0), window.x1 - 1e-6),
                                std::clamp(y, double(window.y0), window.y1 - 1e-6), meshRays)) {
                            for (const scene::Ray& ray : meshRays)
                                tracer.traceCamera(ray, rays, nullptr, &task);
                        } else if (const std::optional<scene::Ray> ray = camera.generate(x, y)) {
                            tracer.traceCamera(*ray, rays, nullptr, &task);
                        }
                    }
                }
                bool again = true;
                // Enough spots, and nothing looked up here or the lookups
                // covered well enough: this part of the tile is done.
                if (traced >= 9 &&
                    (task.topQueries == 0 ||
                     (coverage &&
                      task.topCoverage / static_cast<double>(task.topQueries) >= coverage)))
                    again = false;
                if (again)
                    for (int dy = 0; dy < divideY; ++dy)
                        for (int dx = 0; dx < divideX; ++dx)
                            state.open.emplace_back(px * divideX + dx, py * divideY + dy);
            }
            state.partsX *= divideX;
            state.partsY *= divideY;
        }
    }
    counts += task.counts;
}

}  // namespace frameray::render
