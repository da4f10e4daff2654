// A photon map: the photons photon shooting left on surfaces, in a
// balanced kd-tree (one array, the median of each subtree at its middle,
// split on the axis of largest extent) for the nearest-neighbour searches
// of gathering. Immutable once built; searches from any number of threads.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "util/color.h"
#include "util/vec3.h"

namespace frameray::render {

// One stored photon: where it landed, the light it carries (already
// scaled so that a density estimate gives irradiance) and the direction
// it travelled in (unit).
struct Photon {
    float position[3];
    float power[3];
    float direction[3];

    Vec3 at() const { return {position[0], position[1], position[2]}; }
    Vec3 travel() const { return {direction[0], direction[1], direction[2]}; }
    RGB light() const { return {power[0], power[1], power[2]}; }
};

// A photon found by a search and its squared distance from the point.
struct PhotonNeighbour {
    const Photon* photon;
    double distance2;
};

class PhotonMap {
  public:
    PhotonMap() = default;
    // Takes the photons in any order; the order they are given in only
    // decides ties, so the same input gives the same tree.
    explicit PhotonMap(std::vector<Photon> photons);
    // A tree another map built (photons() and axes() of it, as a photon
    // file keeps them): the same order, so the same searches and the same
    // estimated gather radius. Throws std::invalid_argument when the sizes
    // differ or an axis is not 0, 1 or 2.
    static PhotonMap fromTree(std::vector<Photon> photons, std::vector<std::uint8_t> axes);

    bool empty() const { return photons_.empty(); }
    size_t size() const { return photons_.size(); }
    // Bytes held by the map (photons and split axes).
    size_t memoryBytes() const;
    const std::vector<Photon>& photons() const { return photons_; }
    // The split axis of the node at each index of photons().
    const std::vector<std::uint8_t>& axes() const { return axis_; }

    // The `k` photons nearest to p within `maxRadius`, nearest first, into
    // `out` (cleared first). Fewer when fewer lie that close.
    void nearest(const Vec3& p, double maxRadius, int k, std::vector<PhotonNeighbour>& out) const {
        nearest(p, maxRadius, k, nullptr, out);
    }
    // The same with a flattened sphere when `flatten` (a unit normal) is
    // given, as povray 3.7 gathers at surfaces: a photon's squared
    // distance d counts as d (1 + 16 |n . (photon - p)|), so photons off
    // the surface's plane (a wall meeting a floor) count as farther.
    void nearest(const Vec3& p, double maxRadius, int k, const Vec3* flatten,
                 std::vector<PhotonNeighbour>& out) const;

  private:
    void build(size_t begin, size_t end);
    void pack();
    std::vector<Photon> photons_;
    std::vector<std::uint8_t> axis_;  // split axis of the node at each index
    // The nodes' positions and split axes packed together (what a search
    // reads), in the order of photons_.
    struct Node {
        float at[3];
        std::uint8_t axis;
    };
    std::vector<Node> nodes_;
};

}  // namespace frameray::render
