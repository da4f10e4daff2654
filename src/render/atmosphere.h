// How a traced ray sees the atmosphere, as POV-Ray 3.7 computes it: the
// sky sphere layered over the background for a ray that hits nothing, then
// rainbows and fogs over the stretch of the ray up to what it hit (or an
// "infinite" stretch for a miss).
//
// Every function works on one ray and keeps no state, so the tracer calls
// them for rays of every depth (camera, reflected, refracted). POV-Ray
// applies rainbows and fogs only to rays travelling through the open
// atmosphere (not inside a non-hollow object) and only from quality 9 up;
// the tracer decides that and says so through `volumetric`.
//
// Colours carry filter and transmit as POV-Ray's rays do: the transmit
// part is what a +UA alpha channel would show through (the RGB part is
// already weighted by coverage); without an alpha channel only .rgb is
// used.
#pragma once

#include <span>
#include <utility>

#include "scene/ray.h"
#include "scene/scene.h"
#include "util/color.h"

namespace frameray::render {

// The depth POV-Ray gives a ray that hits nothing (its BOUND_HUGE).
inline constexpr double kMissDepth = 2.0e10;

class AtmosphereView {
  public:
    // `volumetric`: rainbows and fogs are computed (POV-Ray: +Q9 and up).
    AtmosphereView(const scene::Scene& scene, bool volumetric);

    // Colour of a ray that leaves the scene: the sky, then rainbows and
    // fogs over kMissDepth.
    Color miss(const scene::Ray& ray) const;
    // The colour `seen` at ray.at(t) (t in the ray's own parameter units;
    // the direction need not be unit length) after the rainbows and fogs
    // between the ray's origin and that point.
    Color along(const scene::Ray& ray, double t, const Color& seen) const;

    // Whether along() can change anything: callers may skip it otherwise.
    bool changesHits() const { return volumetric_; }

    // The parts, for tests and for callers that already have a unit
    // direction. `depth` is a distance along `unitDirection`.
    Color sky(const Vec3& unitDirection) const;
    Color throughRainbows(const Vec3& unitDirection, double depth, const Color& seen) const;
    Color throughFogs(const Vec3& origin, const Vec3& unitDirection, double depth,
                      const Color& seen) const;

  private:
    const scene::Scene& scene_;
    bool volumetric_;
};

// How much of a light's colour crosses the scene's fogs over `depth`
// along a unit direction: a light with media_attenuation is dimmed by the
// fogs' transmittance alone, their colour adds nothing (measured: a white
// plane lit through fog { distance 10 } from 10 units away gets exp(-1)
// of the light, whatever the fog's colour).
// `without`: stretches (start point, length) of that path where there is
// no fog (inside objects that are not hollow).
double fogLightTransmittance(const scene::Scene& scene, const Vec3& origin,
                             const Vec3& unitDirection, double depth,
                             std::span<const std::pair<Vec3, double>> without = {});

}  // namespace frameray::render
