// The order of radiosity's final pass (render/renderer.cpp renders the
// blocks): povray 3.7 at +WT1 renders the blocks in order, each seeing
// every sample the blocks before it gathered, its radiosity rays going on
// through the pool of directions where the block before left them.
// frameray gives that image whatever the thread count: every block first
// renders at once, seeing only the pretrace's samples and its own, its
// directions starting at the pool's beginning; then, in block order, a
// block keeps that image unless an earlier block's new sample may reach a
// point it looked up, or it gathered samples after earlier blocks had
// turned the pool; such a block renders again, alone, seeing every earlier
// sample and going on through the pool. Each block so ends exactly as the
// serial order makes it.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "render/radiosity.h"

namespace frameray::render {

// tasks[i]: block i's first rendering (its own samples, its lookups, its
// turn through the pool). Puts the final pass's samples into the shared
// cache in block order, calling rerender(i, task) for each block that must
// render again with `task` (writing to the shared cache, pool continued).
// Returns the counts of the blocks' kept renderings.
RadiosityCounts settleFinalPass(Radiosity& radiosity,
                                std::vector<std::optional<RadiosityTask>>& tasks,
                                const std::function<void(int, RadiosityTask&)>& rerender);

}  // namespace frameray::render
