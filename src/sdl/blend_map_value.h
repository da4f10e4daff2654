// A declared map: `#declare M = color_map { .. }` (or pigment_map,
// normal_map, slope_map, texture_map), used later as `color_map { M }`.
#pragma once

#include <vector>

#include "scene/color_map.h"
#include "scene/normals.h"
#include "scene/texture.h"

namespace frameray::sdl {

struct BlendMapValue {
    enum class Kind { Color, Pigment, Normal, Slope, Texture };
    Kind kind = Kind::Color;
    scene::ColorMap colors;
    std::vector<scene::Pigment::MapEntry> pigments;
    std::vector<scene::Normal::MapEntry> normals;
    std::vector<scene::Normal::SlopeEntry> slopes;
    std::vector<scene::TextureMap::Entry> textures;

    // "color_map", "pigment_map"... for messages.
    const char* kindName() const;
};

}  // namespace frameray::sdl
