// Runs a sequence: for every frame, parse the scene afresh with the
// frame's clock, build the world, render, and write the image and the
// frame's message log. Frames overlap in a oneTBB pipeline (parse serial
// in frame order, render in parallel, write in order); see frame_loop.cpp.
#pragma once

#include "anim/sequence.h"
#include "options/render_options.h"

namespace frameray::anim {

// Returns the process exit code: 0 when every frame was written.
int runSequence(const options::RenderOptions& options, const Sequence& sequence);

}  // namespace frameray::anim
