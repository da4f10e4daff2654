// POV-Ray 3.7's photon mapping of caustics, rebuilt from measurements of
// povray on small scenes (tests/conformance/scenes/photons_*.pov):
//
// Shooting. Each light whose photons block allows reflection or refraction
// shoots at each target object (photons { target }), a plain union split
// into its children (split_union on). Photons leave the light in rings
// around the direction of the target's bounding sphere (the sphere around
// its bounding box): ring k at angle k * dt from that direction, dt =
// spacing * target multiplier / distance to the sphere's centre, with
// max(1, round(2 pi sin(k dt) / dt)) photons evenly around it, rings while
// the angle is at most asin(radius / distance) — all directions when the
// light is inside the sphere. Photon counts match povray's exactly
// without jitter. Shooting stops after the first complete ring that
// missed the target, once one photon has hit it and the rings have passed
// `autostop` of the cone. Parallel lights shoot from their plane: rings of
// radius k * spacing across the sphere. jitter moves each photon by up to
// jitter / 2 of the ring spacing, hashed from its indices (povray's is
// random).
//
// Tracing. On its way to the target a photon is stopped by any other
// object except pass_through and no_shadow ones; at an object whose
// photons block says reflection / refraction on (and the light's too) it
// reflects and refracts with the tracer's own optics (fresnel, filter,
// transmit, fading, dispersion: a white photon entering a dispersive
// interior splits into its bands); every later surface with collect on
// keeps it. max_trace_level and adc_bailout are the photons block's, else
// the scene's.
//
// Light. povray's lights do not fade with distance, and neither do its
// caustics (measured: a mirror's caustic is the same at 12, 15 and 18
// units from the light): a photon carries the light's colour times its
// solid angle dt^2 times the square of the distance it has travelled, so
// that a density estimate gives the irradiance light * cos. A parallel
// light's photon carries colour * spacing^2.
//
// Gathering. At a surface the photons nearest the point are searched
// within the gather radius, at most `gather` max of them, and their light
// summed over the disc they cover (radius: the farthest one's distance
// when max were found, else the gather radius; a box filter, measured on
// the edge of a mirror's caustic). As povray 3.7 does it (facts from its
// source): the search is a sphere flattened along the normal; a photon's
// direction is kept to pi/127 in elevation and azimuth; only photons
// arriving on the side facing the viewer count (both sides when
// double_illuminate), each divided by its cosine of arrival (at least
// 0.1) and diffused with that cosine to the finish's brilliance. With
// fewer than `gather` min the search widens to three times the radius,
// kept or not by expand_thresholds as povray 3.7 does (adaptiveGather
// in photons.cpp: a dark ring around an isolated caustic). The radius is
// povray's `radius`, or estimated from the photons' mean density as
// povray does it (estimateRadius in photons.cpp).
//
// Media. With `media max_steps [, factor]` a photon that has bounced
// leaves photons along its path through scattering media (depositInMedia
// in photons.cpp), kept in a second map; the media sampling gathers them
// in a sphere (mediaPhotons) whose radius is estimated as povray 3.7 does
// it and doubled. Media on a photon's way dim it.
//
// Weights. adc_bailout is compared with povray's ray weight, not the
// photon's colour: a reflection counts twice, a filter by its largest
// component, so a photon a filter turned black goes on and is stored.
//
// Files. save_file keeps the shot maps, load_file reuses them instead of
// shooting (an animation shoots once); see render/photon_file.h.
//
// Area lights shoot from their centre, or with the light's
// `photons { area_light }` from every point of their grid, each a light
// of its own with its share of the colour and a spacing sqrt(size1 *
// size2) times wider (photon counts match povray's exactly).
//
// Shooting runs in parallel over rings; each ring's photons are kept in
// ring order, so the map is the same whatever the thread count.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "render/photon_map.h"
#include "scene/lights.h"
#include "scene/object.h"
#include "util/color.h"

namespace frameray::render {

class World;

struct PhotonStats {
    std::uint64_t shot = 0;         // photons that left the lights
    std::uint64_t stored = 0;       // photons kept on surfaces
    std::uint64_t mediaStored = 0;  // photons left in media
    std::size_t memoryBytes = 0;
    double gatherRadius = 0;
    double mediaGatherRadius = 0;
    double spacing = 0;   // the spacing used (from count when the scene gives one)
    bool loaded = false;  // read from load_file, not shot
};

class Photons {
  public:
    // Shoots the photons of world's scene (then writes them to its
    // save_file, if any), or takes them from its load_file (render/
    // photon_file.h; nothing is shot then, as in povray, and gathering
    // follows the scene's settings); null when the scene does not turn
    // photons on. Throws std::runtime_error when a file cannot be written
    // or read.
    static std::unique_ptr<const Photons> build(const World& world);

    // The light photons bring to point p of a surface whose unit normal n
    // faces the viewer (irradiance: still to be scaled by the diffuse
    // coefficient and the pigment). `scratch` is the caller's buffer.
    // With a finish's brilliance (povray diffuses each photon's light with
    // it) and `bothSides` for double_illuminate surfaces.
    RGB irradiance(const Vec3& p, const Vec3& n, double brilliance, bool bothSides,
                   std::vector<PhotonNeighbour>& scratch) const;
    RGB irradiance(const Vec3& p, const Vec3& n, std::vector<PhotonNeighbour>& scratch) const {
        return irradiance(p, n, 1.0, false, scratch);
    }

    // The media photons around p of a medium (into `found`, cleared
    // first) and the radius of the sphere they were gathered from: the
    // light they bring is the sum of their powers, each times the phase
    // function of its direction, times the scattering there, over the
    // sphere's volume. 0 when there are none.
    double mediaPhotons(const Vec3& p, std::vector<PhotonNeighbour>& found) const;
    bool hasMediaPhotons() const { return !media_.empty(); }

    const PhotonStats& stats() const { return stats_; }
    const PhotonMap& surfaceMap() const { return surface_; }
    const PhotonMap& mediaMap() const { return media_; }

    // Whether a shadow ray from `light` stops at `primitive` whatever its
    // filter and transmit (once surface photons exist): with photons on, a
    // light lights what lies behind a target refracting its photons
    // through the photons only (measured: the filtered shadow of a glass
    // sphere disappears, the caustic takes its place; povray 3.7's rule
    // needs the target and refraction on in the object or the light, off
    // in neither).
    static bool photonShadow(const scene::Light& light, const scene::Object& primitive) {
        return primitive.photons.target > 0 &&
               scene::photonsActive(primitive.photons.refraction, light.photons.refraction);
    }

    Photons(PhotonMap map, PhotonMap media, const scene::PhotonSettings& settings,
            PhotonStats stats);

  private:
    PhotonMap surface_;
    PhotonMap media_;
    double radius_ = 0;
    double mediaRadius_ = 0;
    int gatherMin_ = 20;
    int gatherMax_ = 100;
    double expandIncrease_ = 0.2;
    int expandMin_ = 40;
    PhotonStats stats_;
};

}  // namespace frameray::render
