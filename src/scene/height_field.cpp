#include "scene/height_field.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "scene/shape_math.h"

namespace frameray::scene {

namespace {

// The index of column i, row k of a row-major grid `columns` wide (in
// size_t before multiplying: a 30000² grid overflows int).
std::size_t gridIndex(int i, int k, int columns) {
    return static_cast<std::size_t>(k) * static_cast<std::size_t>(columns) +
           static_cast<std::size_t>(i);
}

constexpr double kHeightScale = 1.0 / 65536.0;

}  // namespace

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
            cells.range[gridIndex(i, k, cells.nx)] = {std::min({h[0], h[1], h[2], h[3]}),
                                                      std::max({h[0], h[1], h[2], h[3]})};
        }
    levels_.push_back(std::move(cells));
    while (levels_.back().nx > 1 || levels_.back().nz > 1) {
        const Level& below = levels_.back();
        Level up{(below.nx + 1) / 2, (below.nz + 1) / 2, {}};
        up.range.assign(static_cast<size_t>(up.nx) * static_cast<size_t>(up.nz), {65535, 0});
        for (int k = 0; k < below.nz; ++k)
            for (int i = 0; i < below.nx; ++i) {
                const auto& r = below.range[gridIndex(i, k, below.nx)];
                auto& u = up.range[gridIndex(i / 2, k / 2, up.nx)];
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
    // Every node's box is widened by kPad on each side, so that rounding
    // cannot lose a triangle lying in a box face. The same pad for every
    // node keeps a child's padded box inside its parent's: a child's stretch
    // of the ray is its parent's stretch cut by the child's half planes.
    constexpr double kPad = 2e-9;
    constexpr double kInf = kInfinity;
    const Vec3& o = ray.origin;
    const Vec3& d = ray.direction;
    const double invX = d.x != 0 ? 1 / d.x : 0, invY = d.y != 0 ? 1 / d.y : 0,
                 invZ = d.z != 0 ? 1 / d.z : 0;
    const double water = waterLevel_ > 0 ? waterLevel_ : -kInfinity;
    // Narrows [a0, a1] to where the ray's y lies within the node's heights
    // (above the water); false when nothing is left.
    auto clipHeights = [&](const std::array<uint16_t, 2>& r, double& a0, double& a1) {
        const double hiY = r[1] * kHeightScale;
        if (hiY < water) return false;
        const double loY = std::max(r[0] * kHeightScale, water) - kPad;
        if (d.y == 0) return o.y >= loY && o.y <= hiY + kPad && a0 <= a1;
        double n = (loY - o.y) * invY, f = (hiY + kPad - o.y) * invY;
        if (n > f) std::swap(n, f);
        a0 = std::max(a0, n);
        a1 = std::min(a1, f);
        return a0 <= a1;
    };
    // Cuts the ray's stretch [t0, t1] at the line coordinate = m into the
    // near side's stretch [n0[0], n1[0]] and the far side's [n0[1], n1[1]]
    // (empty when n0 > n1); each side's half plane is padded.
    auto halves = [](double origin, double dir, double inv, double m, double t0, double t1,
                     double n0[2], double n1[2]) {
        if (dir != 0) {
            const double a = (m - kPad - origin) * inv, b = (m + kPad - origin) * inv;
            // Going up, the near side ends at b and the far one starts at
            // a; going down, the other way round.
            const double nearEnd = dir > 0 ? b : a, farStart = dir > 0 ? a : b;
            n0[0] = t0, n1[0] = std::min(t1, nearEnd);
            n0[1] = std::max(t0, farStart), n1[1] = t1;
        } else {
            // Parallel: each side whole or missed (side 0 below m).
            n0[0] = n0[1] = t0;
            n1[0] = origin <= m + kPad ? t1 : -kInf;
            n1[1] = origin >= m - kPad ? t1 : -kInf;
        }
    };
    // The root: the ray's stretch over the padded unit square.
    double a0 = tMin, a1 = tMax();
    const double x1 = (width_ - 1) * sx_, z1 = (height_ - 1) * sz_;
    auto clipSlab = [&](double origin, double dir, double inv, double lo, double hi) {
        if (dir == 0) return origin >= lo - kPad && origin <= hi + kPad;
        double n = (lo - kPad - origin) * inv, f = (hi + kPad - origin) * inv;
        if (n > f) std::swap(n, f);
        a0 = std::max(a0, n);
        a1 = std::min(a1, f);
        return a0 <= a1;
    };
    const int root = static_cast<int>(levels_.size()) - 1;
    if (!clipSlab(o.x, d.x, invX, 0, x1) || !clipSlab(o.z, d.z, invZ, 0, z1) ||
        !clipHeights(levels_[static_cast<size_t>(root)].range[0], a0, a1))
        return;
    struct Entry {
        int level, i, k;
        double t0, t1;  // the ray's stretch through the node's padded box
    };
    // The walk starts at the smallest node holding the ray's whole stretch
    // (a short shadow or reflected ray skips the upper levels): the cells
    // under the stretch, widened by twice the pad, share that ancestor, and
    // no cell outside it comes within a pad of the stretch.
    int level = root, ni = 0, nk = 0;
    if (root > 0 && std::isfinite(a0) && std::isfinite(a1)) {
        const double xa = o.x + d.x * a0, xb = o.x + d.x * a1, za = o.z + d.z * a0,
                     zb = o.z + d.z * a1;
        const Level& cells = levels_[0];
        auto cell = [](double v, double spacing, int count) {
            return static_cast<int>(std::clamp(std::floor(v / spacing), 0.0, count - 1.0));
        };
        const int i0 = cell(std::min(xa, xb) - 2 * kPad, sx_, cells.nx),
                  i1 = cell(std::max(xa, xb) + 2 * kPad, sx_, cells.nx),
                  k0 = cell(std::min(za, zb) - 2 * kPad, sz_, cells.nz),
                  k1 = cell(std::max(za, zb) + 2 * kPad, sz_, cells.nz);
        level = 0;
        while (level < root && ((i0 >> level) != (i1 >> level) || (k0 >> level) != (k1 >> level)))
            ++level;
        ni = i0 >> level, nk = k0 >> level;
        if (level < root) {
            const Level& start = levels_[static_cast<size_t>(level)];
            if (!clipHeights(start.range[gridIndex(ni, nk, start.nx)], a0, a1)) return;
        }
    }
    Entry stack[3 * 32 + 4];
    int top = 0;
    stack[top++] = {level, ni, nk, a0, a1};
    while (top > 0) {
        const Entry e = stack[--top];
        // A hit found since this node was pushed may lie before its box:
        // nothing in it can be nearer (firstHit lowers tMax as it goes).
        const double limit = tMax();
        if (e.t0 > limit) continue;
        if (e.level == 0) {
            if (!visit(e.i, e.k)) return;
            continue;
        }
        const Level& below = levels_[static_cast<size_t>(e.level - 1)];
        const int half = 1 << (e.level - 1);
        const int ci = 2 * e.i, ck = 2 * e.k;
        // The ray's stretches through the children's columns (x) and rows
        // (z), the near one first; a child past the grid's edge is absent.
        double x0[2], x1[2], z0[2], z1[2];
        int nx = 1, nz = 1;
        if (ci + 1 < below.nx) {
            halves(o.x, d.x, invX, (ci + 1) * half * sx_, e.t0, std::min(e.t1, limit), x0, x1);
            nx = 2;
        } else {
            x0[0] = e.t0, x1[0] = std::min(e.t1, limit), x0[1] = kInf, x1[1] = -kInf;
        }
        if (ck + 1 < below.nz) {
            halves(o.z, d.z, invZ, (ck + 1) * half * sz_, e.t0, std::min(e.t1, limit), z0, z1);
            nz = 2;
        } else {
            z0[0] = e.t0, z1[0] = std::min(e.t1, limit), z0[1] = kInf, z1[1] = -kInf;
        }
        // Children pushed farthest first: (far, far), then the two mixed
        // ones in order of entry, then (near, near).
        const int near[2] = {d.x < 0 && nx == 2 ? 1 : 0, d.z < 0 && nz == 2 ? 1 : 0};
        auto push = [&](int a, int b) {
            if (a >= nx || b >= nz) return;
            double t0 = std::max(x0[a], z0[b]), t1 = std::min(x1[a], z1[b]);
            if (t0 > t1) return;
            const int i = ci + (a ^ near[0]), k = ck + (b ^ near[1]);
            if (!clipHeights(below.range[gridIndex(i, k, below.nx)], t0, t1)) return;
            stack[top++] = {e.level - 1, i, k, t0, t1};
        };
        push(1, 1);
        if (std::max(x0[1], z0[0]) > std::max(x0[0], z0[1])) {
            push(1, 0);
            push(0, 1);
        } else {
            push(0, 1);
            push(1, 0);
        }
        push(0, 0);
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
        return normalize(toWorld.normal(smoothNormals_[gridIndex(a, b, width_)]));
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
