// The light that reaches a surface point from one light source, as POV-Ray
// 3.7 computes it: the direction to the light (its centre, or the reverse
// of its axis for parallel and cylinder lights), the light's attenuation
// (spot cone, cylinder, distance fade), projected_through, and shadows —
// a shadow ray through transparent surfaces for a point light, POV-Ray's
// adaptive subdivision of the sample grid for an area light.
//
// The shading model itself (diffuse, highlights) stays with the tracer;
// this file answers "how much of which light arrives here, from where".
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "render/world.h"
#include "scene/lights.h"
#include "scene/object.h"
#include "util/color.h"

namespace frameray::render {

// What +Q allows (POV-Ray: shadows from quality 4, area lights sampled
// from 5; below 5 an area light acts as a point light at its centre).
struct LightingQuality {
    bool shadows = true;
    bool areaLights = true;

    static LightingQuality forQuality(int quality) { return {quality >= 4, quality >= 5}; }
};

// The lights that shade one primitive: the scene's, its light group's
// (scene::LightGroup), or both in that order. Iterable with a range for.
class LightsFor {
  public:
    LightsFor(const std::vector<scene::Light>& scene, const scene::Object& primitive);

    class Iterator {
      public:
        Iterator(const LightsFor* list, size_t index) : list_(list), index_(index) {}
        const scene::Light& operator*() const { return list_->at(index_); }
        Iterator& operator++() {
            ++index_;
            return *this;
        }
        bool operator!=(const Iterator& o) const { return index_ != o.index_; }

      private:
        const LightsFor* list_;
        size_t index_;
    };
    Iterator begin() const { return {this, 0}; }
    Iterator end() const { return {this, first_.size() + second_.size()}; }

  private:
    const scene::Light& at(size_t i) const {
        return i < first_.size() ? first_[i] : second_[i - first_.size()];
    }
    std::span<const scene::Light> first_, second_;
};

// The way from a surface point to a light.
struct LightPath {
    Vec3 toLight;     // unit
    double distance;  // along toLight to the light (to its plane for parallel and cylinder lights)
};

// The way from `p` to `light`; false when the light cannot reach p at all
// whatever the shading (p at the light, behind a cylinder light).
bool pathToLight(const scene::Light& light, const Vec3& p, LightPath& path);

// The colour of `light` arriving at `p` along `path`: attenuated, cut by
// projected_through, and passed through whatever lies between (shadow
// rays, counted in `shadowRays`). `selfHit` is the distance below which a
// shadow ray ignores crossings (its own surface). `startInside`: the
// interiors a media sample's camera ray is in (World::shadowFilter).
RGB lightArriving(const World& world, const scene::Light& light, const Vec3& p,
                  const LightPath& path, double selfHit, const LightingQuality& quality,
                  uint64_t& shadowRays, std::span<const scene::Interior* const> startInside = {});

// The adaptive subdivision of an area light's grid, apart from the shadow
// rays: `sample(i, j)` gives the light arriving from grid point (i, j)
// (each point is asked once); returns the weighted mean POV-Ray forms.
// Corners of a block are sampled first; the block is split into quarters
// (halves that share the middle point of an even span, disjoint halves of
// an odd one) while it spans more than one cell and either
// the split level is below `adaptive` or two neighbouring corners differ
// by more than 0.1 in summed RGB; the quarters are averaged with equal
// weights, whatever their sizes. Exposed for tests.
RGB subdivideAreaGrid(int size1, int size2, int adaptive,
                      const std::function<RGB(int, int)>& sample);

}  // namespace frameray::render
