// pigment { } and normal { } inside a texture (or an object's texture)
// that has been transformed.
//
// povray applies a texture's transformations to its pigment and normal at
// once; frameray keeps them in Texture::transform, applied after the
// pigment's and normal's own. So a pigment or normal block given after a
// transformation edits the transformed one (measured: texture { T pigment
// { rotate z*30 } } with T scaled <2,1,1> turns the scaled checker), while
// what the block brings anew (a pigment or normal identifier, a first
// normal) is not transformed (measured: texture { scale <4,1,1> normal {
// gradient x 1 } } shows the unscaled gradient). Both follow from editing
// in texture space: the transformation is added before the block and taken
// back after it.
#include "sdl/builders.h"

namespace frameray::sdl {

namespace {

// Whether tex.transform moves pigment and normal as povray's would.
bool inTextureSpace(const scene::Texture& tex) {
    return !tex.uvMapping && !tex.transform.isIdentity() &&
           !(tex.pigment && tex.pigment->uvMapping()) && !(tex.normal && tex.normal->uvMapping);
}

}  // namespace

PigmentPtr parseTexturePigment(BuildContext& c, const scene::Texture& tex) {
    if (!inTextureSpace(tex)) return parsePigment(c, tex.pigment.get());
    scene::Pigment base = tex.pigment ? *tex.pigment : *c.defaultTexture.pigment;
    base.transform(tex.transform);
    auto edited = std::make_shared<scene::Pigment>(*parsePigment(c, &base));
    edited->transform(tex.transform.inverse());
    return edited;
}

std::shared_ptr<const scene::Normal> parseTextureNormal(BuildContext& c,
                                                        const scene::Texture& tex) {
    if (!inTextureSpace(tex)) return parseNormal(c, tex.normal.get());
    std::optional<scene::Normal> base;
    if (tex.normal) {
        base = *tex.normal;
        base->transformBy(tex.transform);
    }
    const auto parsed = parseNormal(c, base ? &*base : nullptr);
    if (!parsed) return nullptr;
    auto edited = std::make_shared<scene::Normal>(*parsed);
    edited->transformBy(tex.transform.inverse());
    return edited;
}

}  // namespace frameray::sdl
