#include "render/photon_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace frameray::render {

PhotonMap::PhotonMap(std::vector<Photon> photons) : photons_(std::move(photons)) {
    axis_.assign(photons_.size(), 0);
    build(0, photons_.size());
    pack();
}

void PhotonMap::pack() {
    nodes_.resize(photons_.size());
    for (size_t i = 0; i < photons_.size(); ++i)
        nodes_[i] = {{photons_[i].position[0], photons_[i].position[1], photons_[i].position[2]},
                     axis_[i]};
}

PhotonMap PhotonMap::fromTree(std::vector<Photon> photons, std::vector<std::uint8_t> axes) {
    if (photons.size() != axes.size())
        throw std::invalid_argument("a photon tree needs one split axis per photon");
    if (std::any_of(axes.begin(), axes.end(), [](std::uint8_t a) { return a > 2; }))
        throw std::invalid_argument("a photon tree's split axis is 0, 1 or 2");
    PhotonMap map;
    map.photons_ = std::move(photons);
    map.axis_ = std::move(axes);
    map.pack();
    return map;
}

size_t PhotonMap::memoryBytes() const {
    return photons_.capacity() * sizeof(Photon) + axis_.capacity() +
           nodes_.capacity() * sizeof(Node);
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
    // For a flattened search: each axis' share of the normal, and of the
    // rest of it.
    double normalPart[3] = {0, 0, 0}, restPart[3] = {1, 1, 1};
    if (flatten) {
        const double n[3] = {flatten->x, flatten->y, flatten->z};
        for (int a = 0; a < 3; ++a) {
            normalPart[a] = std::fabs(n[a]);
            restPart[a] = std::sqrt(std::max(0.0, 1.0 - n[a] * n[a])) + 1e-12;
        }
    }
    while (top > 0) {
        const Range r = stack[--top];
        if (r.begin >= r.end || r.plane2 >= limit2) continue;
        const size_t mid = r.begin + (r.end - r.begin) / 2;
        const Node& node = nodes_[mid];
        const int axis = node.axis;
        const double d = q[axis] - node.at[axis];
        // A node as far as the limit along its axis alone is out.
        if (d * d < limit2) {
            const double dx = q[0] - node.at[0], dy = q[1] - node.at[1], dz = q[2] - node.at[2];
            double dist2 = dx * dx + dy * dy + dz * dz;
            // The flattened distance is never shorter, so the planes still
            // bound it.
            if (flatten)
                dist2 *=
                    1.0 + 16.0 * std::fabs(flatten->x * dx + flatten->y * dy + flatten->z * dz);
            if (dist2 < limit2) {
                const Photon* photon = &photons_[mid];
                if (out.size() < wanted) {
                    out.push_back({photon, dist2});
                    std::push_heap(out.begin(), out.end(), farther);
                } else {
                    std::pop_heap(out.begin(), out.end(), farther);
                    out.back() = {photon, dist2};
                    std::push_heap(out.begin(), out.end(), farther);
                }
                if (out.size() == wanted) limit2 = out.front().distance2;
            }
        }
        // Visit the near side last (it is popped first); the far side only
        // while the splitting plane is within the search radius. A
        // flattened search bounds the far side better: its photons lie at
        // least |d| along the axis, so at least |n_a| |d| - |n_rest| R off
        // the surface's plane (R: the search radius now, which only
        // shrinks), which stretches their distance as nearest() does.
        double plane2 = d * d;
        if (flatten) {
            const double off = normalPart[axis] * std::fabs(d) - restPart[axis] * std::sqrt(limit2);
            if (off > 0) plane2 *= 1.0 + 16.0 * off * (1.0 - 1e-12);
        }
        const Range nearSide =
            d < 0 ? Range{r.begin, mid, r.plane2} : Range{mid + 1, r.end, r.plane2};
        const Range farSide = d < 0 ? Range{mid + 1, r.end, plane2} : Range{r.begin, mid, plane2};
        if (plane2 < limit2) stack[top++] = farSide;
        stack[top++] = nearSide;
    }
    std::sort_heap(out.begin(), out.end(), farther);
}

}  // namespace frameray::render
