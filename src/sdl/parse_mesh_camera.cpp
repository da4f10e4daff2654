// mesh_camera { RAYS_PER_PIXEL, DISTRIBUTION [, MAX_DISTANCE] mesh { ... }
// [mesh { ... } ...] [smooth] } inside a camera block (povray 3.7). Each
// mesh is a mesh statement (often `mesh { Declared transforms }`); its
// faces, in the order written, give the primary rays (scene/mesh_camera.h).
#include <fmt/format.h>

#include "scene/mesh.h"
#include "scene/mesh_camera.h"
#include "sdl/interpreter.h"

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

std::shared_ptr<scene::MeshCamera> Interpreter::parseMeshCamera(const Token& at) {
    expect(Sym::LBrace, "'{' after 'mesh_camera'");
    auto camera = std::make_shared<scene::MeshCamera>();
    const Token raysAt = peek();
    const double rays = parseFloat();
    accept(Sym::Comma);
    const Token distributionAt = peek();
    const double distribution = parseFloat();
    accept(Sym::Comma);
    if (rays < 1 || rays != static_cast<int>(rays))
        fail(raysAt, "mesh_camera needs a whole number of rays per pixel, 1 or more");
    if (distribution == 2)
        unsupported(distributionAt, fmt::format("mesh_camera distribution {}", distribution));
    if (distribution != 0 && distribution != 1 && distribution != 3)
        fail(distributionAt, "mesh_camera distribution must be 0, 1, 2 or 3");
    camera->raysPerPixel = static_cast<int>(rays);
    camera->distribution = static_cast<int>(distribution);
    if (!peek().is(Keyword::kw_mesh) && !peek().is(Sym::RBrace))
        unsupported(peek(), "mesh_camera max distance");
    while (peek().is(Keyword::kw_mesh)) {
        const Token meshAt = peek();
        const ObjectValue mesh = parseObject();
        scene::MeshCamera::Placed placed;
        if (!mesh.object || !placedMesh(*mesh.object, placed))
            fail(meshAt, "mesh_camera needs meshes");
        camera->meshes.push_back(std::move(placed));
    }
    if (peek().is(Keyword::kw_smooth)) unsupported(peek(), "mesh_camera smooth");
    expect(Sym::RBrace, "'}' closing mesh_camera");
    if (camera->meshes.empty()) fail(at, "mesh_camera needs at least one mesh");
    if (camera->distribution == 0 &&
        static_cast<size_t>(camera->raysPerPixel) > camera->meshes.size())
        fail(raysAt, "Rays per pixel must be <= number of meshes");
    if (camera->distribution == 3) {
        if (camera->raysPerPixel != 1) fail(raysAt, "Rays per pixel must be 1 for distribution 3");
        camera->prepareUvLookup();
    }
    return camera;
}

}  // namespace frameray::sdl
