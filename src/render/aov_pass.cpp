#include "render/aov_pass.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <unordered_map>

#include "render/camera_rays.h"
#include "render/texture_blend.h"

namespace frameray::render {

namespace {

using ObjectIds = std::unordered_map<const scene::Object*, float>;

// Every primitive under `obj` gets `id` (a hit names the primitive, for
// CSG the child whose surface it is).
void collectIds(const scene::Object& obj, float id, ObjectIds& ids) {
    ids.emplace(&obj, id);
    for (const scene::ObjectRef& child : obj.children) collectIds(*child, id, ids);
}

// The pigment colour of the top texture layer at p (see aov_pass.h).
RGB albedoOf(const scene::Texture& texture, const Vec3& p, const Vec3& uv) {
    const Vec3 at = texture.uvMapping ? uv : p;
    if (texture.map) return blendTextureMap(texture, at, uv, albedoOf);
    if (!texture.pigment) return RGB(0.0);
    scene::SurfaceInfo surface{};
    surface.uv = uv;
    return texture.pigment->at(texture.transform.inversePoint(at), &surface).rgb;
}

std::vector<std::string> channelNames(const AovRequest& r) {
    std::vector<std::string> names;
    if (r.depth) names.push_back("Z");
    if (r.normal) names.insert(names.end(), {"N.x", "N.y", "N.z"});
    if (r.objectId) names.push_back("objectId");
    if (r.albedo) names.insert(names.end(), {"albedo.R", "albedo.G", "albedo.B"});
    return names;
}

// One pixel's channels, in channelNames' order.
void writePixel(const AovRequest& r, float* out, const Hit* hit, const scene::Ray* ray,
                const ObjectIds& ids) {
    const scene::Object* obj = hit ? hit->object : nullptr;
    const Vec3 p = obj ? ray->at(hit->t) : Vec3();
    Vec3 n;
    if (obj && (r.normal || r.albedo)) {
        n = obj->normalAt(p);
        if (dot(n, ray->direction) > 0) n = -n;
    }
    if (r.depth) *out++ = obj ? static_cast<float>(hit->t * length(ray->direction)) : kAovMissDepth;
    if (r.normal)
        for (const double c : {n.x, n.y, n.z}) *out++ = static_cast<float>(c);
    if (r.objectId) {
        const auto it = obj ? ids.find(obj) : ids.end();
        *out++ = it != ids.end() ? it->second : 0.0f;
    }
    if (r.albedo) {
        RGB c(0.0);
        if (obj && obj->texture) {
            const scene::Texture& t = *obj->texture;
            c = albedoOf(t, p, t.usesUv() ? obj->surfaceUv(p) : p);
        }
        for (const double v : {c.r, c.g, c.b}) *out++ = static_cast<float>(v);
    }
}

}  // namespace

AovImage renderAovs(const World& world, const AovRequest& request, int width, int height,
                    const PixelBlock& window) {
    AovImage image;
    image.width = width;
    image.height = height;
    image.names = channelNames(request);
    const size_t channels = image.names.size();
    image.values.resize(static_cast<size_t>(width) * height * channels);
    ObjectIds ids;
    const scene::Scene& scene = world.scene();
    for (size_t i = 0; i < scene.objects.size(); ++i)
        collectIds(*scene.objects[i], static_cast<float>(i + 1), ids);
    PixelBlock w = window;
    if (w.x1 <= w.x0 || w.y1 <= w.y0) w = {0, 0, width, height};
    const CameraRays camera(scene.camera, width, height);
    // Each row depends on its own pixels only: the same values whatever
    // the threads.
    tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
        for (int y = rows.begin(); y < rows.end(); ++y)
            for (int x = 0; x < width; ++x) {
                float* out = &image.values[(static_cast<size_t>(y) * width + x) * channels];
                std::optional<scene::Ray> ray;
                if (x >= w.x0 && x < w.x1 && y >= w.y0 && y < w.y1)
                    ray = camera.generate(x + 0.5, y + 0.5);
                Hit hit;
                const bool met = ray && world.intersect(*ray, 0.0, scene::kInfinity, hit);
                writePixel(request, out, met ? &hit : nullptr, ray ? &*ray : nullptr, ids);
            }
    });
    return image;
}

}  // namespace frameray::render
