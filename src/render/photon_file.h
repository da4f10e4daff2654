// Photon map files (global photons { save_file / load_file }): a frame's
// surface and media photon maps, shot once and reused by later frames or
// runs. The format is frameray's own, not povray's (whose files the parser
// refuses): scene::kPhotonFileMagic, the two maps' photon counts as 64-bit
// little-endian integers, then each map's photons (position, power and
// direction: nine 32-bit little-endian floats) followed by its split axes
// (one byte each). The kd-trees are kept as built, so a loaded map gives
// the very same gathers and gather radius as the shot one.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "render/photon_map.h"

namespace frameray::render {

struct PhotonMaps {
    PhotonMap surface;
    PhotonMap media;
};

std::string encodePhotonFile(const PhotonMap& surface, const PhotonMap& media);

// The maps in `bytes`; throws std::runtime_error naming `shownAs` when they
// are not a whole file encodePhotonFile wrote.
PhotonMaps decodePhotonFile(std::string_view bytes, const std::string& shownAs);

// Writes the maps to `file` (replacing it atomically, so a frame loading it
// never sees half a file); throws std::runtime_error naming the file when
// it cannot be written.
void writePhotonFile(const std::filesystem::path& file, const PhotonMap& surface,
                     const PhotonMap& media);

}  // namespace frameray::render
