// Runs a sequence: for every frame, parse the scene afresh with the
// frame's clock, build the world, render, and write the image and the
// frame's message log. Frames run one after another for now; the
// scheduler issue overlaps them.
#pragma once

#include "anim/sequence.h"
#include "options/render_options.h"

namespace frameray::anim {

// Returns the process exit code: 0 when every frame was written.
int runSequence(const options::RenderOptions& options, const Sequence& sequence);

}  // namespace frameray::anim
