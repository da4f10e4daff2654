#include "scene/polygon.h"

#include <cmath>

namespace frameray::scene {

Polygon::Polygon(const std::vector<std::vector<Vec3>>& loops) {
    // Newell's normal: exact for planar loops, a least-squares plane for
    // slightly bent ones, and independent of which corners are collinear.
    Vec3 n{0, 0, 0}, centre{0, 0, 0};
    size_t count = 0;
    for (const auto& loop : loops)
        for (size_t i = 0; i < loop.size(); ++i) {
            const Vec3& a = loop[i];
            const Vec3& b = loop[(i + 1) % loop.size()];
            n.x += (a.y - b.y) * (a.z + b.z);
            n.y += (a.z - b.z) * (a.x + b.x);
            n.z += (a.x - b.x) * (a.y + b.y);
            centre = centre + a;
            ++count;
            bounds_.extend(a);
        }
    const double len = std::sqrt(dot(n, n));
    if (count < 3 || !(len > 0)) {
        degenerate_ = true;
        bounds_ = {};
        return;
    }
    normal_ = n / len;
    origin_ = centre / static_cast<double>(count);
    // Any two unit axes spanning the plane.
    const Vec3 helper = std::fabs(normal_.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    axisU_ = normalize(cross(helper, normal_));
    axisV_ = cross(normal_, axisU_);
    for (const auto& loop : loops)
        for (size_t i = 0; i < loop.size(); ++i) {
            const Vec3 a = loop[i] - origin_, b = loop[(i + 1) % loop.size()] - origin_;
            edges_.push_back({dot(a, axisU_), dot(a, axisV_), dot(b, axisU_), dot(b, axisV_)});
        }
}

bool Polygon::contains(double u, double v) const {
    // Even-odd rule: count the edges a ray from (u, v) towards +u crosses.
    bool in = false;
    for (const auto& e : edges_) {
        if ((e[1] > v) == (e[3] > v)) continue;
        const double cross = e[0] + (v - e[1]) * (e[2] - e[0]) / (e[3] - e[1]);
        if (u < cross) in = !in;
    }
    return in;
}

bool Polygon::firstHit(const Ray& ray, double tMin, double tMax, double& t) const {
    if (degenerate_) return false;
    const double denom = dot(ray.direction, normal_);
    if (denom == 0) return false;
    const double hit = dot(origin_ - ray.origin, normal_) / denom;
    if (!(hit > tMin && hit < tMax)) return false;
    const Vec3 p = ray.at(hit) - origin_;
    if (!contains(dot(p, axisU_), dot(p, axisV_))) return false;
    t = hit;
    return true;
}

void Polygon::allHits(const Ray& ray, double tMin, double tMax, std::vector<double>& ts) const {
    double t;
    if (firstHit(ray, tMin, tMax, t)) ts.push_back(t);
}

}  // namespace frameray::scene
