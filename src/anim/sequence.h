// The frames of a run: frame numbers, clock values, output names and the
// render window, computed from the options exactly as POV-Ray 3.7 does.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "image/frame_encoding.h"
#include "image/image_io.h"
#include "options/render_options.h"

namespace frameray::anim {

struct FrameSpec {
    int number = 0;  // frame_number
    double clock = 0;
    double clockDelta = 0;
    bool animated = false;
    std::filesystem::path output;  // final image path
    std::filesystem::path log;     // the frame's message log, beside the image
};

// The render window in 0-based pixel coordinates, end exclusive.
using RenderWindow = image::RenderWindow;

struct Sequence {
    std::vector<FrameSpec> frames;
    image::FileType fileType = image::FileType::PNG;
    bool animated = false;
    bool clockOn = false;  // clock_on: an animation, or Clock given
    // The built-in identifiers initial_frame, final_frame (one more than
    // Final_Frame in a cyclic animation), initial_clock, final_clock: all 0
    // when not animated, as in POV-Ray.
    int initialFrame = 0, finalFrame = 0;
    double initialClock = 0, finalClock = 0;
    RenderWindow window;
    // The journal of finished frames, beside the images (Continue_Trace).
    std::filesystem::path journal;
    std::string sceneName;  // the scene file's name without folder and extension (%s)
    // Shard_Index / Shard_Count: `frames` holds this shard's frames only;
    // the journal and the statistics file are the shard's own.
    int shardIndex = 0, shardCount = 1;
    size_t framesInAllShards = 0;
    std::string statisticsName = "sequence.json";
};

// Throws options::OptionError when the options make no sense (a render
// window outside the image).
Sequence planSequence(const options::RenderOptions& options);

// POV-Ray's output name of frame `number`: the name without its extension
// when that is the type's, the frame number padded to `digits` (the base
// name is shortened when the number has more digits), the extension.
std::filesystem::path outputName(const options::RenderOptions& options, image::FileType type,
                                 bool animated, int number, int digits);

image::FileType fileTypeFor(char letter);

}  // namespace frameray::anim
