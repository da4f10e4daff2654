#include "render/renderer.h"

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <optional>
#include <vector>

#include "render/camera_rays.h"
#include "render/focal_blur.h"
#include "render/radiosity_final_pass.h"
#include "render/radiosity_pretrace.h"

namespace frameray::render {

FrameImage renderFrame(const World& world, const FrameSettings& settings, FrameStats& stats) {
    FrameImage image;
    image.width = settings.width;
    image.height = settings.height;
    image.rgb.assign(static_cast<size_t>(settings.width) * settings.height * 3, 0.0f);
    if (settings.alpha)
        image.alpha.assign(static_cast<size_t>(settings.width) * settings.height, 0.0f);
    PixelBlock window = settings.window;
    if (window.x1 <= window.x0 || window.y1 <= window.y0)
        window = {0, 0, settings.width, settings.height};
    const int blockSize = std::max(settings.blockSize, 4);
    const int blocksX = (window.x1 - window.x0 + blockSize - 1) / blockSize;
    const int blocksY = (window.y1 - window.y0 + blockSize - 1) / blockSize;

    // Radiosity (from +Q9, as povray) only when the scene declares it:
    // otherwise nothing is pretraced and no radiosity ray is traced.
    std::unique_ptr<Radiosity> radiosity;
    const scene::Scene& scene = world.scene();
    if (scene.globals.radiosity && settings.quality >= 9)
        radiosity = std::make_unique<Radiosity>(*scene.globals.radiosity, scene.camera.location,
                                                scene.renderVersion() < 3.7 - 1e-9);
    if (radiosity && settings.radiosityStart)
        for (RadiositySample s : *settings.radiosityStart) {
            // Loaded samples belong to no pass of this frame: every lookup sees them.
            s.pass = -1;
            radiosity->add(s);
        }
    const Tracer tracer(world, settings.quality, radiosity.get());
    const CameraRays camera(world.scene().camera, settings.width, settings.height);
    if (radiosity)
        pretraceRadiosity(tracer, camera, *radiosity, window, settings.width, settings.height,
                          stats.rays, stats.radiosity);
    std::optional<FocalBlurSampler> focalBlur;
    if (camera.camera().blur.enabled()) focalBlur.emplace(camera);
    tbb::combinable<RayCounts> rayCounts;
    tbb::combinable<AntialiasCounts> aaCounts;

    // Renders block `index` into the image, its radiosity lookups and new
    // samples going through `blockRadiosity` (none without radiosity).
    const auto renderBlock = [&](int index, RadiosityTask* blockRadiosity, RayCounts& rays,
                                 AntialiasCounts& aa) {
        const SampleFunction sample = [&](double x, double y) {
            // (x, y) = (i, j) is the centre of pixel column i, row j.
            if (focalBlur) {
                // Several rays per sample, each at a random spot of the pixel.
                if (settings.alpha)
                    return focalBlur->sample(
                        x, y,
                        std::function<PixelSample(const scene::Ray&)>([&](const scene::Ray& r) {
                            double transmit = 0;
                            const RGB c = tracer.traceCamera(r, rays, &transmit, blockRadiosity);
                            return PixelSample{c, transmit};
                        }));
                return focalBlur->sample(x, y, [&](const scene::Ray& r) {
                    return tracer.traceCamera(r, rays, nullptr, blockRadiosity);
                });
            }
            if (std::vector<scene::Ray> meshRays; camera.meshRays(x + 0.5, y + 0.5, meshRays)) {
                // mesh_camera: the mean of the pixel's rays; black
                // where it has none (povray).
                PixelSample mean{RGB{}, 0.0};
                if (meshRays.empty()) return mean;
                for (const scene::Ray& r : meshRays) {
                    double transmit = 0;
                    mean.rgb += tracer.traceCamera(r, rays, settings.alpha ? &transmit : nullptr,
                                                   blockRadiosity);
                    mean.transmit += transmit;
                }
                const double n = static_cast<double>(meshRays.size());
                return PixelSample{mean.rgb * (1.0 / n), mean.transmit / n};
            }
            const std::optional<scene::Ray> ray = camera.generate(x + 0.5, y + 0.5);
            // Where the projection traces nothing povray writes transparent black.
            if (!ray) return PixelSample{RGB{}, 1.0};
            if (settings.alpha) {
                double transmit = 0;
                const RGB c = tracer.traceCamera(*ray, rays, &transmit, blockRadiosity);
                return PixelSample{c, transmit};
            }
            return PixelSample{tracer.traceCamera(*ray, rays, nullptr, blockRadiosity), 0.0};
        };
        const int bx = window.x0 + (index % blocksX) * blockSize;
        const int by = window.y0 + (index / blocksX) * blockSize;
        const PixelBlock block{bx, by, std::min(bx + blockSize, window.x1),
                               std::min(by + blockSize, window.y1)};
        const std::vector<PixelSample> pixels = sampleBlock(block, settings.antialias, sample, aa);
        size_t i = 0;
        for (int y = block.y0; y < block.y1; ++y)
            for (int x = block.x0; x < block.x1; ++x, ++i) {
                const RGB& c = pixels[i].rgb;
                float* out = &image.rgb[(static_cast<size_t>(y) * settings.width + x) * 3];
                out[0] = static_cast<float>(std::clamp(c.r, 0.0, 1.0));
                out[1] = static_cast<float>(std::clamp(c.g, 0.0, 1.0));
                out[2] = static_cast<float>(std::clamp(c.b, 0.0, 1.0));
                if (settings.alpha)
                    image.alpha[static_cast<size_t>(y) * settings.width + x] =
                        static_cast<float>(std::clamp(1.0 - pixels[i].transmit, 0.0, 1.0));
            }
    };

    // The final pass: every block at once, then settled in block order as
    // povray's +WT1 render makes it (render/radiosity_final_pass.h).
    const int blockCount = blocksX * blocksY;
    std::vector<std::optional<RadiosityTask>> tasks(static_cast<size_t>(blockCount));
    // One block per task, handed out in order: blocks differ widely in cost
    // (glass, area-light penumbrae), and larger chunks left one thread
    // finishing a long tail while the other waited (measured: ~10 % of a
    // still frame's time).
    tbb::parallel_for(
        tbb::blocked_range<int>(0, blockCount, 1),
        [&](const tbb::blocked_range<int>& range) {
            for (int index = range.begin(); index < range.end(); ++index) {
                std::optional<RadiosityTask>& task = tasks[static_cast<size_t>(index)];
                if (radiosity) task.emplace(*radiosity, false, false);
                renderBlock(index, task ? &*task : nullptr, rayCounts.local(), aaCounts.local());
            }
        },
        tbb::simple_partitioner());
    if (radiosity)
        stats.radiosity += settleFinalPass(*radiosity, tasks, [&](int index, RadiosityTask& task) {
            renderBlock(index, &task, rayCounts.local(), aaCounts.local());
        });
    rayCounts.combine_each([&](const RayCounts& c) { stats.rays += c; });
    aaCounts.combine_each([&](const AntialiasCounts& c) {
        stats.antialias.supersampledPixels += c.supersampledPixels;
        stats.antialias.samples += c.samples;
    });
    if (radiosity && settings.keepRadiosity) image.radiosityCache = radiosity->samples();
    return image;
}

}  // namespace frameray::render
