#include "scene/mesh.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "scene/shape_math.h"

namespace frameray::scene {

namespace {

constexpr uint32_t kLeafSize = 4;

// Slab test of a box against a ray in (tMin, tMax); the entry distance in
// `tEnter`. Axes the ray runs parallel to only check the origin.
bool hitBox(const Bounds& b, const Vec3& origin, const Vec3& invDir,
            const std::array<bool, 3>& flat, double tMin, double tMax, double& tEnter) {
    double t0 = tMin, t1 = tMax;
    for (int a = 0; a < 3; ++a) {
        if (flat[a]) {
            if (origin[a] < b.lo[a] || origin[a] > b.hi[a]) return false;
            continue;
        }
        double n = (b.lo[a] - origin[a]) * invDir[a];
        double f = (b.hi[a] - origin[a]) * invDir[a];
        if (n > f) std::swap(n, f);
        t0 = std::max(t0, n);
        t1 = std::min(t1, f);
        if (t0 > t1) return false;
    }
    tEnter = t0;
    return true;
}

// Grows a box a little so that float-free but rounded slab tests never
// miss a triangle lying in the box's face.
Bounds padded(const Bounds& b) {
    const Vec3 size = b.hi - b.lo;
    const double m =
        std::max({size.x, size.y, size.z, std::fabs(b.lo.x), std::fabs(b.lo.y), std::fabs(b.lo.z),
                  std::fabs(b.hi.x), std::fabs(b.hi.y), std::fabs(b.hi.z)});
    const Vec3 pad(m * 1e-9 + 1e-300);
    return {b.lo - pad, b.hi + pad};
}

}  // namespace

TriangleMesh::TriangleMesh(std::vector<Vec3> vertices, std::vector<Vec3> normals,
                           std::vector<MeshTriangle> triangles, bool keepNormalLengths)
    : vertices_(std::move(vertices)), normals_(std::move(normals)) {
    if (!keepNormalLengths)
        for (Vec3& n : normals_)
            if (dot(n, n) > 0) n = normalize(n);
    // In place: a mesh from an exported file holds millions of triangles.
    triangles_ = std::move(triangles);
    inputFaces_ = triangles_;  // as given, degenerate ones included (mesh_camera)
    std::erase_if(triangles_, [&](const MeshTriangle& t) {
        const Vec3 &a = vertices_[t.vertex[0]], &b = vertices_[t.vertex[1]],
                   &c = vertices_[t.vertex[2]];
        const Vec3 n = cross(b - a, c - a);
        return dot(n, n) == 0;
    });
    // Group by texture, keeping the order of first appearance.
    std::stable_sort(
        triangles_.begin(), triangles_.end(),
        [](const MeshTriangle& x, const MeshTriangle& y) { return x.texture < y.texture; });
    std::vector<Vec3> centroids(triangles_.size());
    for (size_t i = 0; i < triangles_.size(); ++i) {
        const MeshTriangle& t = triangles_[i];
        centroids[i] =
            (vertices_[t.vertex[0]] + vertices_[t.vertex[1]] + vertices_[t.vertex[2]]) / 3.0;
    }
    // The BVH is built over an index permutation, applied to the triangles
    // once at the end (no per-level copies of triangles and centroids).
    std::vector<uint32_t> order(triangles_.size());
    std::iota(order.begin(), order.end(), 0u);
    uint32_t begin = 0;
    while (begin < triangles_.size()) {
        uint32_t end = begin;
        while (end < triangles_.size() && triangles_[end].texture == triangles_[begin].texture)
            ++end;
        Group g;
        g.texture = triangles_[begin].texture;
        g.nodes.reserve(2 * (end - begin) / kLeafSize + 1);
        build(g, order, begin, end, centroids);
        groups_.push_back(std::move(g));
        begin = end;
    }
    std::vector<Vec3>().swap(centroids);  // freed before the triangles move
    // triangles_[k] = old triangles_[order[k]], cycle by cycle, in place.
    for (uint32_t i = 0; i < order.size(); ++i) {
        if (order[i] == i) continue;
        const MeshTriangle first = triangles_[i];
        uint32_t k = i;
        for (;;) {
            const uint32_t from = order[k];
            order[k] = k;
            if (from == i) {
                triangles_[k] = first;
                break;
            }
            triangles_[k] = triangles_[from];
            k = from;
        }
    }
}

uint32_t TriangleMesh::build(Group& g, std::vector<uint32_t>& order, uint32_t begin, uint32_t end,
                             const std::vector<Vec3>& centroids) {
    const auto index = static_cast<uint32_t>(g.nodes.size());
    g.nodes.emplace_back();
    Bounds box, centroidBox;
    for (uint32_t i = begin; i < end; ++i) {
        for (const uint32_t v : triangles_[order[i]].vertex) box.extend(vertices_[v]);
        centroidBox.extend(centroids[order[i]]);
    }
    g.nodes[index].box = padded(box);
    if (end - begin <= kLeafSize) {
        g.nodes[index].first = begin;
        g.nodes[index].count = end - begin;
        return index;
    }
    // Median split along the widest axis of the centroids: cheap to build
    // and good enough for the regular meshes scenes make.
    const Vec3 extent = centroidBox.hi - centroidBox.lo;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(
        order.begin() + begin, order.begin() + mid, order.begin() + end,
        [&](uint32_t x, uint32_t y) { return centroids[x][axis] < centroids[y][axis]; });
    build(g, order, begin, mid, centroids);
    const uint32_t right = build(g, order, mid, end, centroids);
    g.nodes[index].first = right;
    g.nodes[index].count = 0;
    return index;
}

template <typename Visit, typename Limit>
void TriangleMesh::traverse(const Group& g, const Ray& ray, double tMin, Limit tMax,
                            Visit visit) const {
    if (g.nodes.empty()) return;
    Vec3 inv;
    std::array<bool, 3> flat{};
    for (int a = 0; a < 3; ++a) {
        flat[a] = ray.direction[a] == 0;
        inv[a] = flat[a] ? 0 : 1 / ray.direction[a];
    }
    // Each node waits with where the ray enters its box: a closest-hit
    // search that has since found a nearer hit skips it when popped.
    struct Pending {
        uint32_t node;
        double enter;
    };
    Pending stack[128];
    int top = 0;
    double enter;
    if (!hitBox(g.nodes[0].box, ray.origin, inv, flat, tMin, tMax(), enter)) return;
    stack[top++] = {0, enter};
    while (top > 0) {
        const Pending pending = stack[--top];
        if (pending.enter > tMax()) continue;
        const Node& node = g.nodes[pending.node];
        if (node.count > 0) {
            for (uint32_t i = node.first; i < node.first + node.count; ++i) visit(i);
            continue;
        }
        const uint32_t left = static_cast<uint32_t>(&node - g.nodes.data()) + 1, right = node.first;
        double tl, tr;
        const bool hl = hitBox(g.nodes[left].box, ray.origin, inv, flat, tMin, tMax(), tl);
        const bool hr = hitBox(g.nodes[right].box, ray.origin, inv, flat, tMin, tMax(), tr);
        // Nearer child on top of the stack.
        if (hl && hr) {
            if (tl <= tr) {
                stack[top++] = {right, tr};
                stack[top++] = {left, tl};
            } else {
                stack[top++] = {left, tl};
                stack[top++] = {right, tr};
            }
        } else if (hl) {
            stack[top++] = {left, tl};
        } else if (hr) {
            stack[top++] = {right, tr};
        }
    }
}

bool TriangleMesh::hitTriangle(uint32_t tri, const Ray& ray, double tMin, double tMax,
                               double& t) const {
    const MeshTriangle& m = triangles_[tri];
    double hit;
    if (!detail::hitTriangle(ray, vertices_[m.vertex[0]], vertices_[m.vertex[1]],
                             vertices_[m.vertex[2]], tMin, tMax, hit))
        return false;
    if (minY_ > -kInfinity && ray.origin.y + ray.direction.y * hit < minY_) return false;
    t = hit;
    return true;
}

bool TriangleMesh::firstHit(const Ray& ray, double tMin, double tMax, double& t, int group) const {
    bool found = false;
    for (size_t gi = 0; gi < groups_.size(); ++gi) {
        if (group != kAllGroups && static_cast<int>(gi) != group) continue;
        traverse(
            groups_[gi], ray, tMin, [&] { return tMax; },
            [&](uint32_t i) {
                double h;
                if (hitTriangle(i, ray, tMin, tMax, h)) {
                    tMax = h;
                    found = true;
                }
            });
    }
    if (found) t = tMax;
    return found;
}

void TriangleMesh::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts,
                           int group) const {
    const size_t from = ts.size();
    for (size_t gi = 0; gi < groups_.size(); ++gi) {
        if (group != kAllGroups && static_cast<int>(gi) != group) continue;
        traverse(
            groups_[gi], ray, tMin, [&] { return tMax; },
            [&](uint32_t i) {
                double h;
                if (hitTriangle(i, ray, tMin, tMax, h)) ts.push_back(h);
            });
    }
    std::sort(ts.begin() + static_cast<std::ptrdiff_t>(from), ts.end());
}

size_t TriangleMesh::crossingCount(const Ray& ray) const {
    size_t n = 0;
    for (const Group& g : groups_)
        traverse(
            g, ray, 0.0, [] { return kInfinity; },
            [&](uint32_t i) {
                double h;
                if (hitTriangle(i, ray, 0.0, kInfinity, h)) ++n;
            });
    return n;
}

Vec3 TriangleMesh::triangleNormal(uint32_t tri, const Vec3& p, const Transform* toWorld) const {
    const MeshTriangle& m = triangles_[tri];
    const Vec3 &a = vertices_[m.vertex[0]], &b = vertices_[m.vertex[1]],
               &c = vertices_[m.vertex[2]];
    auto place = [&](const Vec3& n) { return toWorld ? normalize(toWorld->normal(n)) : n; };
    const Vec3 face = place(normalize(cross(b - a, c - a)));
    if (m.normal[0] < 0) return face;
    // Barycentric weights of p (in the plane, least squares).
    const Vec3 e1 = b - a, e2 = c - a, w = p - a;
    const double d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
    const double w1 = dot(w, e1), w2 = dot(w, e2);
    const double det = d11 * d22 - d12 * d12;
    const double wb = (d22 * w1 - d12 * w2) / det, wc = (d11 * w2 - d12 * w1) / det;
    const Vec3 n = place(normals_[static_cast<size_t>(m.normal[0])]) * (1 - wb - wc) +
                   place(normals_[static_cast<size_t>(m.normal[1])]) * wb +
                   place(normals_[static_cast<size_t>(m.normal[2])]) * wc;
    return dot(n, n) > 0 ? normalize(n) : face;
}

int64_t TriangleMesh::nearestTriangle(const Vec3& p, int group) const {
    // The triangle nearest to p among those whose padded box holds it.
    // Distance: to the plane, plus how far p's projection lies outside the
    // triangle (in barycentric terms scaled by the edge), so that on a
    // shared edge either neighbour may answer but never a far one.
    double best = kInfinity;
    uint32_t bestTri = 0;
    bool found = false;
    for (size_t gi = 0; gi < groups_.size(); ++gi) {
        if (group != kAllGroups && static_cast<int>(gi) != group) continue;
        const Group& g = groups_[gi];
        if (g.nodes.empty()) continue;
        uint32_t stack[128];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const uint32_t ni = stack[--top];
            const Node& node = g.nodes[ni];
            // Generous tolerance: p comes from a world-space hit.
            const Vec3 size = node.box.hi - node.box.lo;
            const double tol = 1e-6 * std::max({size.x, size.y, size.z}) + 1e-12;
            if (p.x < node.box.lo.x - tol || p.y < node.box.lo.y - tol ||
                p.z < node.box.lo.z - tol || p.x > node.box.hi.x + tol ||
                p.y > node.box.hi.y + tol || p.z > node.box.hi.z + tol)
                continue;
            if (node.count == 0) {
                stack[top++] = node.first;
                stack[top++] = ni + 1;
                continue;
            }
            for (uint32_t i = node.first; i < node.first + node.count; ++i) {
                const MeshTriangle& m = triangles_[i];
                const Vec3 &a = vertices_[m.vertex[0]], &b = vertices_[m.vertex[1]],
                           &c = vertices_[m.vertex[2]];
                const Vec3 n = cross(b - a, c - a);
                const double len = length(n);
                const double plane = std::fabs(dot(p - a, n)) / len;
                // The edge term below is >= 0: this one cannot win.
                if (plane >= best) continue;
                // Outside distance: for each edge, how far p lies on its
                // outer side.
                double outside = 0;
                const Vec3 corners[3] = {a, b, c};
                for (int e = 0; e < 3; ++e) {
                    const Vec3& u = corners[e];
                    const Vec3& v = corners[(e + 1) % 3];
                    const Vec3 edgeNormal = cross(v - u, n) / len;  // points out of the triangle
                    const double d = dot(p - u, edgeNormal) / std::max(length(v - u), 1e-300);
                    outside = std::max(outside, d);
                    if (plane + outside >= best) break;  // the sum only grows
                }
                const double score = plane + outside;
                if (score < best) {
                    best = score;
                    bestTri = i;
                    found = true;
                }
            }
        }
    }
    return found ? static_cast<int64_t>(bestTri) : -1;
}

Vec3 TriangleMesh::normal(const Vec3& p, int group, const Transform* toWorld) const {
    const int64_t tri = nearestTriangle(p, group);
    if (tri < 0) return toWorld ? normalize(toWorld->normal(Vec3(0, 1, 0))) : Vec3(0, 1, 0);
    return triangleNormal(static_cast<uint32_t>(tri), p, toWorld);
}

void TriangleMesh::uvAt(const Vec3& p, int group, double& u, double& v) const {
    triangleUv(nearestTriangle(p, group), p, u, v);
}

Vec3 TriangleMesh::normalAndUv(const Vec3& p, int group, const Transform* toWorld, double& u,
                               double& v) const {
    const int64_t tri = nearestTriangle(p, group);
    triangleUv(tri, p, u, v);
    if (tri < 0) return toWorld ? normalize(toWorld->normal(Vec3(0, 1, 0))) : Vec3(0, 1, 0);
    return triangleNormal(static_cast<uint32_t>(tri), p, toWorld);
}

void TriangleMesh::triangleUv(int64_t tri, const Vec3& p, double& u, double& v) const {
    u = v = 0;
    if (tri < 0) return;
    const MeshTriangle& m = triangles_[static_cast<size_t>(tri)];
    for (const int32_t i : m.uv)
        if (i < 0 || static_cast<size_t>(i) >= uvs_.size()) return;
    // Barycentric weights of p's projection onto the triangle's plane.
    const Vec3 &a = vertices_[m.vertex[0]], &b = vertices_[m.vertex[1]],
               &c = vertices_[m.vertex[2]];
    const Vec3 e1 = b - a, e2 = c - a, d = p - a;
    const double d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2);
    const double dp1 = dot(d, e1), dp2 = dot(d, e2);
    const double den = d11 * d22 - d12 * d12;
    if (den == 0) return;
    const double wb = (d22 * dp1 - d12 * dp2) / den;
    const double wc = (d11 * dp2 - d12 * dp1) / den;
    const double wa = 1 - wb - wc;
    const auto& ua = uvs_[static_cast<size_t>(m.uv[0])];
    const auto& ub = uvs_[static_cast<size_t>(m.uv[1])];
    const auto& uc = uvs_[static_cast<size_t>(m.uv[2])];
    u = ua[0] * wa + ub[0] * wb + uc[0] * wc;
    v = ua[1] * wa + ub[1] * wb + uc[1] * wc;
}

Bounds TriangleMesh::bounds(int group) const {
    Bounds b;
    for (size_t gi = 0; gi < groups_.size(); ++gi)
        if ((group == kAllGroups || static_cast<int>(gi) == group) && !groups_[gi].nodes.empty())
            b.extend(groups_[gi].nodes[0].box);
    return b;
}

bool MeshShape::inside(const Vec3& p) const {
    if (!solid_) return false;
    return mesh_->crossingCount({p, insideVector_}) % 2 == 1;
}

}  // namespace frameray::scene
