// mesh_camera { RAYS_PER_PIXEL, DISTRIBUTION [, MAX_DISTANCE] mesh { ... }
// [mesh { ... } ...] [smooth] } inside a camera block (povray 3.7). Each
// mesh is a mesh statement (often `mesh { Declared transforms }`); its
// faces, in the order written, give the primary rays (scene/mesh_camera.h).

#include "scene/mesh.h"
#include "scene/mesh_camera.h"
#include "sdl/builders.h"

namespace frameray::sdl {

namespace {

// The mesh of a parsed mesh statement and its object-to-world transform:
// the primitive itself, or (a mesh whose triangles carry textures) the
// first of its texture groups, which share the mesh.
bool placedMesh(const scene::Object& obj, scene::MeshCamera::Placed& placed) {
    if (const auto* shape = dynamic_cast<const scene::MeshShape*>(obj.shape.get())) {
        placed = {shape->mesh(), obj.transform};
        return true;
    }
    return !obj.shape && !obj.children.empty() && placedMesh(*obj.children.front(), placed);
}

}  // namespace

std::shared_ptr<scene::MeshCamera> parseMeshCamera(BuildContext& c, const Token& at) {
    Reader& r = c.reader;
    r.expect(Sym::LBrace, "'{' after 'mesh_camera'");
    auto camera = std::make_shared<scene::MeshCamera>();
    const Token raysAt = r.peek();
    const double rays = r.parseFloat();
    r.accept(Sym::Comma);
    const Token distributionAt = r.peek();
    const double distribution = r.parseFloat();
    r.accept(Sym::Comma);
    if (rays < 1 || rays != static_cast<int>(rays))
        r.fail(raysAt, "mesh_camera needs a whole number of rays per pixel, 1 or more");
    if (distribution != 0 && distribution != 1 && distribution != 2 && distribution != 3)
        r.fail(distributionAt, "mesh_camera distribution must be 0, 1, 2 or 3");
    camera->raysPerPixel = static_cast<int>(rays);
    camera->distribution = static_cast<int>(distribution);
    if (!r.peek().is(Keyword::kw_mesh) && !r.peek().is(Sym::RBrace))
        r.unsupported(r.peek(), "mesh_camera max distance");
    while (r.peek().is(Keyword::kw_mesh)) {
        const Token meshAt = r.peek();
        const ObjectValue mesh = parseObject(c);
        scene::MeshCamera::Placed placed;
        if (!mesh.object || !placedMesh(*mesh.object, placed))
            r.fail(meshAt, "mesh_camera needs meshes");
        camera->meshes.push_back(std::move(placed));
    }
    const Token smoothAt = r.peek();
    if (r.accept(Keyword::kw_smooth)) camera->smooth = true;
    r.expect(Sym::RBrace, "'}' closing mesh_camera");
    if (camera->meshes.empty()) r.fail(at, "mesh_camera needs at least one mesh");
    if (camera->distribution == 0 &&
        static_cast<size_t>(camera->raysPerPixel) > camera->meshes.size())
        r.fail(raysAt, "Rays per pixel must be <= number of meshes");
    if (camera->distribution >= 2 && camera->raysPerPixel != 1)
        r.fail(raysAt, "Rays per pixel must be 1 for distribution 2 or 3");
    if (camera->distribution == 3) {
        if (camera->smooth && camera->hasUnblendableUvFace())
            r.unsupported(smoothAt, "mesh_camera smooth over a flat face");
        camera->prepareUvLookup();
    }
    return camera;
}

}  // namespace frameray::sdl
