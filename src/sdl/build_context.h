// What the statement builders (builders.h) share while one frame's scene
// is built: the reader they read from, the scene they build, and the
// state of the language that outlives one statement (#default's texture,
// the text charset, the fonts and images read so far).
#pragma once

#include <map>
#include <memory>
#include <string>

#include "image/image_io.h"
#include "scene/normals.h"
#include "scene/scene.h"
#include "scene/ttf_font.h"
#include "sdl/reader.h"

namespace frameray::sdl {

struct BuildContext {
    explicit BuildContext(Reader& r) : reader(r) {}
    BuildContext(const BuildContext&) = delete;
    BuildContext& operator=(const BuildContext&) = delete;

    Reader& reader;
    scene::Scene scene;  // the scene being built
    // #default { texture | pigment | normal | finish }: where new textures,
    // pigments and finishes start, and what objects without a texture get.
    scene::Texture defaultTexture;
    bool defaultTextureSet = false;
    // defaultTexture as given to the objects placed without a texture: one
    // instance they all share (made on first use, dropped by #default).
    std::shared_ptr<const scene::Texture> placedDefaultTexture;
    // What a normal without a base starts from: #default's normal settings,
    // kept even without a pattern (measured: #default { normal { bump_size
    // 1.5 } } makes normal { gradient x } and normal_map entries 1.5 deep).
    scene::Normal defaultNormal;
    // Text objects: the global_settings charset in force, and the fonts
    // read so far, by the name the scene gave (this frame's only).
    scene::TextCharset textCharset = scene::TextCharset::Ascii;
    std::map<std::string, std::shared_ptr<scene::TtfFont>> fonts;
    // Images read so far by their resolved path (this frame's only).
    std::map<std::string, std::shared_ptr<const image::SourceImage>> images;
};

}  // namespace frameray::sdl
