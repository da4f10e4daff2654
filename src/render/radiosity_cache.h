// The irradiance cache of one frame's radiosity: the samples gathered so
// far (where, facing which way, how much light arrived, how far it may be
// reused) and a loose octree that finds the samples whose reuse radius
// reaches a point. Not thread-safe for writing: render/radiosity.h decides
// who inserts when, so that the samples never depend on the thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "util/color.h"
#include "util/vec3.h"

namespace frameray::render {

struct RadiositySample {
    Vec3 point;
    Vec3 normal;  // unit, on the side the light was gathered
    RGB irradiance;
    // How far from `point` the sample may be reused: the rays' harmonic
    // mean distance, kept within minimum_reuse and maximum_reuse times the
    // distance from the eye.
    double radius = 0;
    int depth = 0;  // 0: seen from the camera; n: gathered for a radiosity ray n bounces deep
    // The nearest surface the rays met: how far, and which way (unit). The
    // reuse radius shrinks toward it. nearest <= 0: unknown (a sample read
    // from a file), the radius holds every way.
    double nearest = 0;
    Vec3 toNearest;
    // Which pretrace pass gathered the sample (0: the final pass) and in
    // which tile of it: a lookup ignores the samples other tiles of its own
    // pass gathered (povray's rule for reproducible renders).
    int pass = 0;
    int tile = 0;
    // The mean quality of the sample's rays (povray 3.7): a ray whose own
    // lookup, one bounce deeper, found little weight to reuse counts less,
    // and so does a sample made of such rays when it is looked up.
    double quality = 1;
};

class RadiosityOctree {
  public:
    // Stores sample `index` whose influence reaches `reach` from `center`.
    void insert(std::uint32_t index, const Vec3& center, double reach);

    // Calls visit(index) for every sample whose influence may reach p (a
    // superset: the caller applies the exact test).
    template <typename Visit>
    void query(const Vec3& p, Visit&& visit) const {
        if (nodes_.empty()) return;
        queryNode(0, origin_, size_, p, visit);
    }

    bool empty() const { return nodes_.empty(); }

  private:
    struct Node {
        std::int32_t child[8] = {-1, -1, -1, -1, -1, -1, -1, -1};
        std::vector<std::uint32_t> samples;
    };

    // Grows the root cube until it holds `p` and is at least `size` wide.
    void growToHold(const Vec3& p, double size);

    template <typename Visit>
    void queryNode(std::int32_t node, const Vec3& origin, double size, const Vec3& p,
                   Visit& visit) const {
        // The node's loose bounds: its cell widened by half its size, which
        // holds every sample stored in it with its whole reach.
        const double half = size * 0.5;
        if (p.x < origin.x - half || p.y < origin.y - half || p.z < origin.z - half ||
            p.x > origin.x + size + half || p.y > origin.y + size + half ||
            p.z > origin.z + size + half)
            return;
        const Node& n = nodes_[static_cast<size_t>(node)];
        for (const std::uint32_t s : n.samples) visit(s);
        for (int k = 0; k < 8; ++k) {
            if (n.child[k] < 0) continue;
            const Vec3 o(origin.x + ((k & 1) ? half : 0), origin.y + ((k & 2) ? half : 0),
                         origin.z + ((k & 4) ? half : 0));
            queryNode(n.child[k], o, half, p, visit);
        }
    }

    std::vector<Node> nodes_;  // nodes_[0] is the root
    Vec3 origin_;              // the root cell's lowest corner
    double size_ = 0;          // the root cell's width
};

}  // namespace frameray::render
