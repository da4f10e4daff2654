// The frames of a run: frame numbers, clock values and output names,
// computed from the options as POV-Ray 3.7 does.
#pragma once

#include <filesystem>
#include <vector>

#include "image/image_io.h"
#include "options/render_options.h"

namespace frameray::anim {

struct FrameSpec {
    int number = 0;            // frame_number
    double clock = 0;
    double clockDelta = 0;
    bool animated = false;     // clock_on
    std::filesystem::path output;  // final image path
    std::filesystem::path log;     // the frame's message log, beside the image
};

struct Sequence {
    std::vector<FrameSpec> frames;
    image::FileType fileType = image::FileType::PNG;
    int initialFrame = 1, finalFrame = 1;
    double initialClock = 0, finalClock = 1;
};

// Throws options::OptionError when the frame range makes no sense.
Sequence planSequence(const options::RenderOptions& options);

image::FileType fileTypeFor(char letter);

}  // namespace frameray::anim
