#include "scene/height_field.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "scene/shape_math.h"

namespace frameray::scene {

namespace {
constexpr double kHeightScale = 1.0 / 65536.0;
}

double HeightField::sample(int i, int k) const {
    i = std::clamp(i, 0, width_ - 1);
    k = std::clamp(k, 0, height_ - 1);
    return heights_[static_cast<size_t>(height_ - 1 - k) * static_cast<size_t>(width_) +
                    static_cast<size_t>(i)] *
           kHeightScale;
}

Vec3 HeightField::vertexNormal(int i, int k) const {
    // povray 3.7's smooth normals (fitted exactly to its trace() output):
    // in grid space (x, z in samples, y in 16-bit height units) the unit
    // normals of the four quadrants between the vertex and its neighbours
    // (east, north, west, south; quadrants with a neighbour off the grid
    // left out) are summed and made unit length, then stored as 16-bit
    // integers (times 32767, truncated). Carried to object space, unscaled,
    // where normal() blends them.
    auto grid = [&](int a, int b) { return Vec3(a, sample(a, b) * 65536.0, b); };
    const Vec3 p = grid(i, k);
    const int di[4] = {1, 0, -1, 0}, dk[4] = {0, 1, 0, -1};
    Vec3 sum;
    for (int q = 0; q < 4; ++q) {
        const int a1 = i + di[q], b1 = k + dk[q], a2 = i + di[(q + 1) % 4],
                  b2 = k + dk[(q + 1) % 4];
        if (a1 < 0 || a1 >= width_ || b1 < 0 || b1 >= height_ || a2 < 0 || a2 >= width_ || b2 < 0 ||
            b2 >= height_)
            continue;
        Vec3 n = cross(grid(a2, b2) - p, grid(a1, b1) - p);
        if (n.y < 0) n = -n;
        sum += normalize(n);
    }
    if (dot(sum, sum) == 0) return Vec3(0, 1, 0);
    const Vec3 unit = normalize(sum);
    const Vec3 stored(std::trunc(unit.x * 32767), std::trunc(unit.y * 32767),
                      std::trunc(unit.z * 32767));
    return Vec3(stored.x * (width_ - 1), stored.y * 65536.0, stored.z * (height_ - 1));
}

HeightField::HeightField(int width, int height, std::vector<uint16_t> heights, bool smooth,
                         double waterLevel)
    : width_(width),
      height_(height),
      heights_(std::move(heights)),
      sx_(1.0 / (width - 1)),
      sz_(1.0 / (height - 1)),
      waterLevel_(waterLevel) {
    if (smooth) {
        smoothNormals_.reserve(heights_.size());
        for (int k = 0; k < height_; ++k)
            for (int i = 0; i < width_; ++i) smoothNormals_.push_back(vertexNormal(i, k));
    }
    // The quadtree, bottom up.
    Level cells{width_ - 1, height_ - 1, {}};
    cells.range.resize(static_cast<size_t>(cells.nx) * static_cast<size_t>(cells.nz));
    for (int k = 0; k < cells.nz; ++k)
        for (int i = 0; i < cells.nx; ++i) {
            const uint16_t h[4] = {raw(i, k), raw(i + 1, k), raw(i, k + 1), raw(i + 1, k + 1)};
            cells.range[static_cast<size_t>(k * cells.nx + i)] = {
                std::min({h[0], h[1], h[2], h[3]}), std::max({h[0], h[1], h[2], h[3]})};
        }
    levels_.push_back(std::move(cells));
    while (levels_.back().nx > 1 || levels_.back().nz > 1) {
        const Level& below = levels_.back();
        Level up{(below.nx + 1) / 2, (below.nz + 1) / 2, {}};
        up.range.assign(static_cast<size_t>(up.nx) * static_cast<size_t>(up.nz), {65535, 0});
        for (int k = 0; k < below.nz; ++k)
            for (int i = 0; i < below.nx; ++i) {
                const auto& r = below.range[static_cast<size_t>(k * below.nx + i)];
                auto& u = up.range[static_cast<size_t>((k / 2) * up.nx + i / 2)];
                u[0] = std::min(u[0], r[0]);
                u[1] = std::max(u[1], r[1]);
            }
        levels_.push_back(std::move(up));
    }
    const auto& top = levels_.back().range[0];
    bounds_ = {{0, top[0] / 65536.0, 0}, {1, top[1] / 65536.0, 1}};
    if (waterLevel_ > 0) bounds_.lo.y = std::max(bounds_.lo.y, std::min(waterLevel_, bounds_.hi.y));
}

bool HeightField::hitCell(int i, int k, const Ray& ray, double tMin, double tMax, double hits[2],
                          int& count) const {
    // The cell's two triangles (shape_math.h's test: edges included, so
    // neighbours leave no crack).
    const Vec3 c00 = corner(i, k), c10 = corner(i + 1, k), c01 = corner(i, k + 1),
               c11 = corner(i + 1, k + 1);
    const Vec3 tri[2][3] = {{c00, c10, c01}, {c10, c11, c01}};
    count = 0;
    for (const auto& t : tri) {
        double h;
        if (!detail::hitTriangle(ray, t[0], t[1], t[2], tMin, tMax, h)) continue;
        if (waterLevel_ > 0 && ray.origin.y + ray.direction.y * h < waterLevel_) continue;
        hits[count++] = h;
    }
    return count > 0;
}

template <typename Visit, typename Limit>
void HeightField::traverse(const Ray& ray, double tMin, Limit tMax, Visit visit) const {
    Vec3 inv;
    bool flat[3];
    for (int a = 0; a < 3; ++a) {
        flat[a] = ray.direction[a] == 0;
        inv[a] = flat[a] ? 0 : 1 / ray.direction[a];
    }
    const double water = waterLevel_ > 0 ? waterLevel_ : -kInfinity;
    // Entry distance of the ray into a node's box, or false.
    auto enter = [&](int level, int i, int k, double& t0) {
        const Level& l = levels_[static_cast<size_t>(level)];
        const auto& r = l.range[static_cast<size_t>(k * l.nx + i)];
        const double hiY = r[1] / 65536.0;
        if (hiY < water) return false;
        const int span = 1 << level;
        const double lo[3] = {i * span * sx_, std::max(r[0] / 65536.0, water), k * span * sz_};
        const double hi[3] = {std::min(i * span + span, width_ - 1) * sx_, hiY,
                              std::min(k * span + span, height_ - 1) * sz_};
        double a0 = tMin, a1 = tMax();
        for (int a = 0; a < 3; ++a) {
            // A relative pad keeps rounding from losing a triangle lying
            // in a box face.
            const double pad = 1e-9 * (hi[a] - lo[a] + 1.0);
            if (flat[a]) {
                if (ray.origin[a] < lo[a] - pad || ray.origin[a] > hi[a] + pad) return false;
                continue;
            }
            double n = (lo[a] - pad - ray.origin[a]) * inv[a];
            double f = (hi[a] + pad - ray.origin[a]) * inv[a];
            if (n > f) std::swap(n, f);
            a0 = std::max(a0, n);
            a1 = std::min(a1, f);
            if (a0 > a1) return false;
        }
        t0 = a0;
        return true;
    };
    struct Entry {
        int level, i, k;
        double t;  // where the ray enters the node's (padded) box
    };
    Entry stack[4 * 32 + 4];
    int top = 0;
    const int root = static_cast<int>(levels_.size()) - 1;
    double t0;
    if (!enter(root, 0, 0, t0)) return;
    stack[top++] = {root, 0, 0, t0};
    while (top > 0) {
        const Entry e = stack[--top];
        // A hit found since this node was pushed may lie before its box:
        // nothing in it can be nearer (firstHit lowers tMax as it goes).
        if (e.t > tMax()) continue;
        if (e.level == 0) {
            if (!visit(e.i, e.k)) return;
            continue;
        }
        // Children, nearest pushed last so it is visited first.
        const Level& below = levels_[static_cast<size_t>(e.level - 1)];
        struct Child {
            int i, k;
            double t;
        } kids[4];
        int n = 0;
        for (int dk = 0; dk < 2; ++dk)
            for (int di = 0; di < 2; ++di) {
                const int ci = 2 * e.i + di, ck = 2 * e.k + dk;
                if (ci >= below.nx || ck >= below.nz) continue;
                double t;
                if (enter(e.level - 1, ci, ck, t)) kids[n++] = {ci, ck, t};
            }
        for (int a = 1; a < n; ++a)  // farthest first (at most four)
            for (int b = a; b > 0 && kids[b - 1].t < kids[b].t; --b)
                std::swap(kids[b - 1], kids[b]);
        for (int c = 0; c < n; ++c) stack[top++] = {e.level - 1, kids[c].i, kids[c].k, kids[c].t};
    }
}

bool HeightField::firstHit(const Ray& ray, double tMin, double tMax, double& t) const {
    bool found = false;
    traverse(
        ray, tMin, [&] { return tMax; },
        [&](int i, int k) {
            double hits[2];
            int count;
            if (hitCell(i, k, ray, tMin, tMax, hits, count)) {
                for (int c = 0; c < count; ++c) tMax = std::min(tMax, hits[c]);
                found = true;
            }
            return true;
        });
    if (found) t = tMax;
    return found;
}

void HeightField::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const {
    const size_t from = ts.size();
    traverse(
        ray, tMin, [&] { return tMax; },
        [&](int i, int k) {
            double hits[2];
            int count;
            if (hitCell(i, k, ray, tMin, tMax, hits, count))
                for (int c = 0; c < count; ++c) ts.push_back(hits[c]);
            return true;
        });
    std::sort(ts.begin() + static_cast<std::ptrdiff_t>(from), ts.end());
}

Vec3 HeightField::flatNormal(const Vec3& p) const {
    const double fx = std::clamp(p.x, 0.0, 1.0) * (width_ - 1),
                 fz = std::clamp(p.z, 0.0, 1.0) * (height_ - 1);
    const int i = std::clamp(static_cast<int>(std::floor(fx)), 0, width_ - 2);
    const int k = std::clamp(static_cast<int>(std::floor(fz)), 0, height_ - 2);
    const Vec3 c00 = corner(i, k), c10 = corner(i + 1, k), c01 = corner(i, k + 1),
               c11 = corner(i + 1, k + 1);
    // Upward (+y), as povray's trace() reports it, whichever side a ray
    // comes from.
    const Vec3 n =
        triangleOf(fx - i, fz - k) == 0 ? cross(c01 - c00, c10 - c00) : cross(c01 - c10, c11 - c10);
    return normalize(n);
}

double HeightField::heightAt(double x, double z) const {
    const double fx = x * (width_ - 1), fz = z * (height_ - 1);
    const int i = std::clamp(static_cast<int>(std::floor(fx)), 0, width_ - 2);
    const int k = std::clamp(static_cast<int>(std::floor(fz)), 0, height_ - 2);
    const double u = fx - i, v = fz - k;
    // The cell's two triangles meet on the line u + v = 1.
    if (u + v <= 1)
        return sample(i, k) + (sample(i + 1, k) - sample(i, k)) * u +
               (sample(i, k + 1) - sample(i, k)) * v;
    return sample(i + 1, k + 1) + (sample(i, k + 1) - sample(i + 1, k + 1)) * (1 - u) +
           (sample(i + 1, k) - sample(i + 1, k + 1)) * (1 - v);
}

Vec3 HeightField::normal(const Vec3& p) const {
    return worldNormal(p, Transform());
}

Vec3 HeightField::worldNormal(const Vec3& p, const Transform& toWorld) const {
    if (smoothNormals_.empty()) return normalize(toWorld.normal(flatNormal(p)));
    // povray makes the four corner normals of the cell unit length after
    // the object's transform and blends them bilinearly, whichever of the
    // cell's triangles was hit (fitted to its trace(), scaled and not).
    const double fx = std::clamp(p.x, 0.0, 1.0) * (width_ - 1),
                 fz = std::clamp(p.z, 0.0, 1.0) * (height_ - 1);
    const int i = std::clamp(static_cast<int>(std::floor(fx)), 0, width_ - 2);
    const int k = std::clamp(static_cast<int>(std::floor(fz)), 0, height_ - 2);
    const double u = fx - i, v = fz - k;
    auto at = [&](int a, int b) {
        return normalize(toWorld.normal(smoothNormals_[static_cast<size_t>(b * width_ + a)]));
    };
    const Vec3 n = at(i, k) * ((1 - u) * (1 - v)) + at(i + 1, k) * (u * (1 - v)) +
                   at(i, k + 1) * ((1 - u) * v) + at(i + 1, k + 1) * (u * v);
    return dot(n, n) > 0 ? normalize(n) : normalize(toWorld.normal(flatNormal(p)));
}

bool HeightField::inside(const Vec3& p) const {
    if (p.x < 0 || p.x > 1 || p.z < 0 || p.z > 1) return false;
    return p.y < heightAt(p.x, p.z);
}

}  // namespace frameray::scene
