// libFuzzer target: a scene parsed as fuzz_scene parses it, then built into
// a World (Embree) and rendered at 16x12 pixels, and its pixels gamma
// encoded as the frame loop encodes them. Whatever the scene holds (NaN or
// huge vectors, degenerate shapes, odd lights and cameras), rendering must
// either finish or end with an exception for its frame; an abort (Embree's
// ray assertions), a sanitizer report or a hang is a bug.
//
// Budgets: the parse budgets of fuzz_scene; the image is tiny so a render
// costs milliseconds, and libFuzzer's -timeout catches a render that runs
// away (an exponential ray tree, an endless root search).
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

#include "fuzz_parse_budget.h"
#include "image/frame_encoding.h"
#include "render/renderer.h"
#include "render/world.h"
#include "sdl/interpreter.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace frameray;
    static sdl::TokenCache cache;
    sdl::FrameContext frame = fuzz::fuzzFrame();
    frame.imageWidth = 16;
    frame.imageHeight = 12;
    fuzz::DiscardMessages messages;
    try {
        sdl::Interpreter interpreter(frame, cache, messages);
        const std::string text(reinterpret_cast<const char*>(data), size);
        const scene::Scene scene = interpreter.parseText("fuzz.pov", text);
        const render::World world(scene);
        render::FrameSettings settings;
        settings.width = frame.imageWidth;
        settings.height = frame.imageHeight;
        render::FrameStats stats;
        const render::FrameImage frameImage = render::renderFrame(world, settings, stats);
        const auto gamma = image::GammaEncoding::forScene(
            scene.globals.assumedGammaSet, scene.globals.assumedGamma, scene.renderVersion(), 0);
        const image::EncodedImage encoded = image::encodeFrame(
            frameImage.width, frameImage.height, frameImage.rgb, frameImage.alpha, gamma, 8,
            {0, 0, frameImage.width, frameImage.height});
        (void)encoded;
    } catch (const std::exception& e) {
        (void)e.what();
    }
    return 0;
}
