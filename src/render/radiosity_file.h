// Radiosity cache files (Radiosity_To_File / Radiosity_From_File): a
// frame's irradiance samples written as text, to start another render (a
// later frame, another run) from them. The format is frameray's own (a
// header line, then one sample a line with every number written exactly),
// not povray's .rca layout: a file of povray's is refused with a message.
#pragma once

#include <filesystem>
#include <span>
#include <vector>

#include "render/radiosity_cache.h"

namespace frameray::render {

// Writes the samples; throws std::runtime_error naming the file when it
// cannot be written.
void writeRadiosityFile(const std::filesystem::path& file,
                        std::span<const RadiositySample> samples);

// Reads a file writeRadiosityFile wrote; throws std::runtime_error naming
// the file (and the line) when it cannot be read or is not such a file.
std::vector<RadiositySample> readRadiosityFile(const std::filesystem::path& file);

}  // namespace frameray::render
