#include "render/photon_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace frameray::render {

PhotonMap::PhotonMap(std::vector<Photon> photons) : photons_(std::move(photons)) {
    axis_.assign(photons_.size(), 0);
    build(0, photons_.size());
}

PhotonMap PhotonMap::fromTree(std::vector<Photon> photons, std::vector<std::uint8_t> axes) {
    if (photons.size() != axes.size())
        throw std::invalid_argument("a photon tree needs one split axis per photon");
    if (std::any_of(axes.begin(), axes.end(), [](std::uint8_t a) { return a > 2; }))
        throw std::invalid_argument("a photon tree's split axis is 0, 1 or 2");
    PhotonMap map;
    map.photons_ = std::move(photons);
    map.axis_ = std::move(axes);
    return map;
}

size_t PhotonMap::memoryBytes() const {
    return photons_.capacity() * sizeof(Photon) + axis_.capacity();
}

void PhotonMap::build(size_t begin, size_t end) {
    // Recursion depth is log2 of the photon count.
    if (end - begin <= 1) return;
    float lo[3] = {photons_[begin].position[0], photons_[begin].position[1],
                   photons_[begin].position[2]};
    float hi[3] = {lo[0], lo[1], lo[2]};
    for (size_t i = begin + 1; i < end; ++i)
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], photons_[i].position[a]);
            hi[a] = std::max(hi[a], photons_[i].position[a]);
        }
    int axis = 0;
    for (int a = 1; a < 3; ++a)
        if (hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
    const size_t mid = begin + (end - begin) / 2;
    std::nth_element(
        photons_.begin() + static_cast<std::ptrdiff_t>(begin),
        photons_.begin() + static_cast<std::ptrdiff_t>(mid),
        photons_.begin() + static_cast<std::ptrdiff_t>(end),
        [axis](const Photon& a, const Photon& b) { return a.position[axis] < b.position[axis]; });
    axis_[mid] = static_cast<std::uint8_t>(axis);
    build(begin, mid);
    build(mid + 1, end);
}

void PhotonMap::nearest(const Vec3& p, double maxRadius, int k, const Vec3* flatten,
                        std::vector<PhotonNeighbour>& out) const {
    out.clear();
    if (photons_.empty() || k <= 0) return;
    double limit2 = maxRadius * maxRadius;
    const double q[3] = {p.x, p.y, p.z};
    auto farther = [](const PhotonNeighbour& a, const PhotonNeighbour& b) {
        return a.distance2 < b.distance2;
    };
    // An explicit stack of [begin, end) ranges still to visit, each with the
    // squared distance to the plane that cut it off (0 for the near side):
    // at most two entries per level of a tree less than 64 deep.
    struct Range {
        size_t begin, end;
        double plane2;
    };
    Range stack[128];
    int top = 0;
    stack[top++] = {0, photons_.size(), 0.0};
    const size_t wanted = static_cast<size_t>(k);
    while (top > 0) {
        const Range r = stack[--top];
        if (r.begin >= r.end || r.plane2 >= limit2) continue;
        const size_t mid = r.begin + (r.end - r.begin) / 2;
        const Photon& node = photons_[mid];
        const int axis = axis_[mid];
        const double d = q[axis] - node.position[axis];
        const double dx = q[0] - node.position[0], dy = q[1] - node.position[1],
                     dz = q[2] - node.position[2];
        double dist2 = dx * dx + dy * dy + dz * dz;
        // The flattened distance is never shorter, so the planes still
        // bound it.
        if (flatten)
            dist2 *= 1.0 + 16.0 * std::fabs(flatten->x * dx + flatten->y * dy + flatten->z * dz);
        if (dist2 < limit2) {
            if (out.size() < wanted) {
                out.push_back({&node, dist2});
                std::push_heap(out.begin(), out.end(), farther);
            } else {
                std::pop_heap(out.begin(), out.end(), farther);
                out.back() = {&node, dist2};
                std::push_heap(out.begin(), out.end(), farther);
            }
            if (out.size() == wanted) limit2 = out.front().distance2;
        }
        // Visit the near side last (it is popped first); the far side only
        // while the splitting plane is within the search radius.
        const double plane2 = d * d;
        const Range nearSide =
            d < 0 ? Range{r.begin, mid, r.plane2} : Range{mid + 1, r.end, r.plane2};
        const Range farSide = d < 0 ? Range{mid + 1, r.end, plane2} : Range{r.begin, mid, plane2};
        if (plane2 < limit2) stack[top++] = farSide;
        stack[top++] = nearSide;
    }
    std::sort_heap(out.begin(), out.end(), farther);
}

}  // namespace frameray::render
