#include "anim/frame_loop.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>

#include "anim/frame_log.h"
#include "image/image_io.h"
#include "render/gamma.h"
#include "render/renderer.h"
#include "render/world.h"
#include "sdl/diagnostics.h"
#include "sdl/interpreter.h"
#include "sdl/token_cache.h"

namespace frameray::anim {

namespace fs = std::filesystem;

namespace {

sdl::FrameContext contextFor(const options::RenderOptions& o, const Sequence& seq, const FrameSpec& f) {
    sdl::FrameContext ctx;
    ctx.clock = f.clock;
    ctx.clockDelta = f.clockDelta;
    ctx.clockOn = f.animated;
    ctx.frameNumber = f.number;
    ctx.initialClock = seq.initialClock;
    ctx.finalClock = seq.finalClock;
    ctx.initialFrame = seq.initialFrame;
    ctx.finalFrame = seq.finalFrame;
    ctx.imageWidth = o.width;
    ctx.imageHeight = o.height;
    ctx.libraryPaths = o.libraryPaths;
    ctx.declares = o.declares;
    ctx.version = o.version;
    return ctx;
}

image::EncodedImage encode(const render::FrameImage& img, const render::GammaEncoding& gamma, int bitDepth) {
    image::EncodedImage out;
    out.width = img.width;
    out.height = img.height;
    out.channels = 3;
    out.bitDepth = bitDepth;
    out.values.resize(img.rgb.size());
    for (size_t i = 0; i < img.rgb.size(); ++i) out.values[i] = static_cast<float>(gamma.encode(img.rgb[i]));
    return out;
}

}  // namespace

int runSequence(const options::RenderOptions& o, const Sequence& seq) {
    sdl::TokenCache cache;  // shared by the frames: files are lexed once
    for (const FrameSpec& frame : seq.frames) {
        const auto start = std::chrono::steady_clock::now();
        FrameLog log(o.verbose);
        std::error_code ec;
        if (o.outputToFile && !frame.output.parent_path().empty())
            fs::create_directories(frame.output.parent_path(), ec);
        try {
            sdl::Interpreter interpreter(contextFor(o, seq, frame), cache, log);
            const scene::Scene scene = interpreter.parseFile(o.inputFile);
            const render::World world(scene);
            render::FrameStats stats;
            const render::FrameImage image = render::renderFrame(world, {o.width, o.height}, stats);
            if (o.outputToFile) {
                const auto gamma = render::GammaEncoding::forScene(scene, o.fileGamma);
                image::writeAtomic(frame.output, seq.fileType, encode(image, gamma, o.bitDepth));
            }
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (o.verbose)
                spdlog::info("frame {} ({} of {}): {} in {:.2f} s, {} camera and {} shadow rays", frame.number,
                             &frame - seq.frames.data() + 1, seq.frames.size(), frame.output.string(), seconds,
                             stats.rays.camera, stats.rays.shadow);
        } catch (const sdl::SdlError& e) {
            log.message(sdl::Stream::Fatal, e.what());
            log.save(frame.log);
            return 1;
        } catch (const std::exception& e) {
            log.message(sdl::Stream::Fatal, fmt::format("error: frame {}: {}", frame.number, e.what()));
            log.save(frame.log);
            return 1;
        }
        if (o.outputToFile) log.save(frame.log);
    }
    return 0;
}

}  // namespace frameray::anim
