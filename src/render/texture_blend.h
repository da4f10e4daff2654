// A texture_map's colour as povray blends it for the colour-only views of
// a surface (+Q quick colours in the tracer, the albedo AOV): the weighted
// sum of each entry's colour at the map's entry point.
#pragma once

#include "scene/texture.h"

namespace frameray::render {

// `texture.map` must be set; colourOf(entry texture, entry point, uv) -> RGB
// gives an entry's colour (it may recurse into nested maps).
template <class ColourOf>
RGB blendTextureMap(const scene::Texture& texture, const Vec3& at, const Vec3& uv,
                    ColourOf&& colourOf) {
    RGB color(0.0);
    const Vec3 q = texture.transform.inversePoint(at);
    const Vec3 entry = texture.map->entryPoint(q);
    texture.map->visit(
        q, [&](const scene::Texture& t, double w) { color += colourOf(t, entry, uv) * w; });
    return color;
}

}  // namespace frameray::render
