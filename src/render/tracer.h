// POV-Ray's classic recursive ray tracer for one ray: ambient, diffuse with
// brilliance, phong and specular highlights under the lights of
// render/lighting.h (shadows, area lights), reflection and transmission
// (with refraction) up to max_trace_level, cut off by adc_bailout.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "render/atmosphere.h"
#include "render/dispersion.h"
#include "render/lighting.h"
#include "render/media.h"
#include "render/radiosity.h"
#include "render/world.h"
#include "util/color.h"
#include "util/sample_random.h"

namespace frameray::render {

// Per-thread counters, summed per frame for the statistics.
struct RayCounts {
    uint64_t camera = 0;
    uint64_t shadow = 0;
    uint64_t reflection = 0;    // mirrored rays, including total internal reflection
    uint64_t refraction = 0;    // transmitted rays bent at a change of ior
    uint64_t transmission = 0;  // transmitted rays that go straight on (same ior both sides)
    uint64_t mediaSamples = 0;  // points where media were evaluated (render/media.h)
    uint64_t radiosity = 0;     // rays gathering light for radiosity samples

    RayCounts& operator+=(const RayCounts& o) {
        camera += o.camera;
        shadow += o.shadow;
        reflection += o.reflection;
        refraction += o.refraction;
        transmission += o.transmission;
        mediaSamples += o.mediaSamples;
        radiosity += o.radiosity;
        return *this;
    }
};

// The regions (objects sharing one interior) a ray travels inside,
// innermost last. povray keeps such a list per ray to know the index of
// refraction on each side of the surfaces it meets.
class InteriorStack {
  public:
    struct Region {
        const void* key =
            nullptr;  // identity: the Interior, else Object::regionKey or the primitive
        const scene::Interior* interior = nullptr;  // null: ior 1, no fading
        bool hollow = false;                        // fog reaches rays inside
    };
    static constexpr int kCapacity = 16;  // deeper nesting is treated as air
    // The region a ray enters or leaves at `primitive`'s surface.
    static Region of(const scene::Object& primitive);

    bool empty() const { return size_ == 0; }
    int size() const { return size_; }
    bool contains(const void* key) const;
    // The ior of the innermost region for a ray of `band` (dispersion.h),
    // 1 outside everything.
    double ior(SpectralBand band = {}) const;
    // Whether the innermost region disperses light.
    bool disperses() const;
    // Whether every region is hollow (or there is none): povray computes
    // fog only along such rays.
    bool allHollow() const;
    const Region* innermost() const { return size_ ? &regions_[size_ - 1] : nullptr; }
    const Region& operator[](int i) const { return regions_[i]; }
    void push(const Region& r);
    void remove(const void* key);

  private:
    std::array<Region, kCapacity> regions_{};
    int size_ = 0;
};

class Tracer {
  public:
    // `quality` is the +Q level: shadows from 4, area lights from 5,
    // reflection and transmission from 8, rainbows and fogs from 9
    // (povray 3.7).
    // `radiosity`: the frame's radiosity when it computes it (the scene
    // declares radiosity and quality is 9 or more); null otherwise.
    explicit Tracer(const World& world, int quality = 9, const Radiosity* radiosity = nullptr);

    // Colour seen along a camera ray (working colour space, unclipped).
    // With `transmit`, alpha output: the background counts as black and
    // *transmit receives how much of it shows through (povray's
    // transmittance: 1 - alpha).
    // `radiosity`: the block's access to the frame's radiosity cache, when
    // the scene has radiosity (null otherwise).
    RGB traceCamera(const scene::Ray& ray, RayCounts& counts, double* transmit = nullptr,
                    RadiosityTask* radiosity = nullptr) const;

  private:
    struct State {
        int level = 1;        // 1 for camera rays
        double weight = 1.0;  // how much this ray can still add to the pixel (adc_bailout)
        scene::RayKind kind = scene::RayKind::Camera;
        InteriorStack inside;
        SpectralBand band;  // white until a dispersive interior splits the ray
        // How much of the transmitted rays at this ray's hit survive the
        // interior the ray crossed to get there; the surface's ambient,
        // emission and reflection are not faded (measured: povray 3.7
        // leaves them whole), nor its lights: those are faded by their own
        // shadow rays' way out of the interior (render/world.cpp; measured:
        // with a no_shadow fading slab or water povray's back face or
        // floor keeps its whole light). Set by trace() for the one hit,
        // never inherited.
        RGB fade{1.0};
        // With alpha output (+UA), where a camera ray and the rays that
        // continue it through surfaces report how much of the background
        // shows through (missed rays then see black); null otherwise and
        // for reflected rays, which see the background as usual.
        double* transmit = nullptr;
        // Radiosity along this path: the cache access, how many radiosity
        // rays deep the ray is, whether it continues one (radiosity rays
        // see no highlights), and where its path left from and how long it
        // was there (the reuse radius grows with the distance from the eye).
        struct RadiosityPath {
            RadiosityTask* task = nullptr;
            int depth = 0;
            bool ray = false;
            Vec3 origin;
            double length = 0;
            // The quality of the radiosity ray this path continues (null
            // for camera rays): its lookups lower it to the weight they
            // found over the weight they needed.
            double* quality = nullptr;
        } radiosity;
        double* hitDistance = nullptr;  // set by trace(): how far the ray went (infinity: missed)
        // How many subsurface surfaces deep the ray is seen from
        // (render/subsurface.h: the second takes one sample of each kind).
        int subsurfaceDepth = 0;
    };

    RGB trace(const scene::Ray& ray, double tMin, const State& state, RayCounts& counts) const;
    // The media along the ray up to t (kMissDepth for a ray that hit
    // nothing) over `color`: interior media of the hollow regions the ray
    // is inside, and the scene's media where every region is hollow.
    RGB throughMedia(const scene::Ray& ray, double t, bool missed, const State& state,
                     const RGB& color, RayCounts& counts) const;
    RGB shade(const scene::Ray& ray, const Hit& hit, const State& state, RayCounts& counts) const;
    // p is where the surface is lit, texP where the texture is evaluated
    // (they differ inside a warped texture map); uv is the surface's
    // (u, v, 0) for uv_mapping.
    // `patternNormal`: the normal a texture map's pattern sees (null: the
    // geometric one); `perturbed`, when given, receives the last normal a
    // normal pattern of the texture made (untouched when none did).
    RGB shadeTexture(const scene::Texture& top, const scene::Ray& ray, const scene::Object& obj,
                     const Vec3& p, const Vec3& texP, const Vec3& uv, const Vec3& viewDir,
                     const Vec3& geometric, const State& state, RayCounts& counts,
                     const Vec3* patternNormal = nullptr, Vec3* perturbed = nullptr) const;
    // The pieces of shadeTexture. SurfacePoint is the point being shaded
    // (shadeTexture's arguments and the self-hit epsilon of rays leaving it).
    struct SurfacePoint {
        const scene::Ray& ray;
        const scene::Object& obj;
        Vec3 p, texP, uv, viewDir, geometric;
        double eps;
        Vec3 patternNormal;  // what a texture map's pattern sees as the normal
    };
    // Where a ray through the surface goes: the interiors beyond it and
    // the iors on both sides.
    struct Crossing {
        InteriorStack beyond;
        double iorHere;
        double iorBeyond;
        // The ior ratio of povray 3.7's fresnel reflection. Leaving an
        // object while inside others too, povray divides the innermost
        // region's ior (usually the object's own) by the object's, a
        // ratio of 1: no fresnel reflection from inside (measured: with
        // the camera inside a plane's half-space, a fresnel glass sphere's
        // image is the same for every max_trace_level from 3 up; alone in
        // the air, its inner reflections show). Refraction is not affected.
        double fresnelRatio;
    };
    // What the layers of a texture give: their colour, what they let
    // through (also as one grey number, for alpha output: povray counts
    // filter by the pigment's grey), the last layer's reflectivity and
    // perturbed normal, and all layers' reflectivity summed (what a total
    // internal reflection leaves to the mirrored ray).
    struct Layers {
        RGB color{0.0};
        RGB through{1.0};
        double throughGrey = 1.0;
        bool transmits = false;
        RGB reflectivity{0.0};
        RGB reflectedSum{0.0};
        Vec3 n;
        // The top layer's normal, and the reflections of the layers that
        // share it: povray drops those when the ray is totally reflected
        // inside (continueThrough).
        Vec3 topN;
        const scene::Finish* topFinish = nullptr;
        RGB topReflection{0.0};
        bool perturbed = false;  // some layer has a normal pattern
    };
    RGB shadeTextureMap(const scene::Texture& top, const SurfacePoint& at, const State& state,
                        RayCounts& counts, Vec3* perturbed) const;
    Crossing crossingOf(const scene::Object& obj, const State& state) const;
    // Subsurface light transport (render/subsurface.h, tracer_subsurface.cpp):
    // whether a finish carries light under the surface on this ray, and the
    // light it brings out at `at` for a layer of pigment `pigment`.
    bool subsurfaceActive(const scene::Finish& fin, const State& state) const;
    RGB subsurfaceLight(const scene::Finish& fin, const RGB& pigment, const SurfacePoint& at,
                        const State& state, RayCounts& counts) const;
    // `crossing` is found when a layer's reflection needs it (kept for
    // continueThrough).
    Layers shadeLayers(const scene::Texture& top, const SurfacePoint& at, bool spawns,
                       const State& state, std::optional<Crossing>& crossing,
                       RayCounts& counts) const;
    RGB spawnReflection(const SurfacePoint& at, const Vec3& reflected, const RGB& weightColor,
                        const State& state, RayCounts& counts) const;
    RGB iridReflection(const scene::Finish& fin, const SurfacePoint& at, const Vec3& n,
                       const Vec3& reflected, const State& state, const RGB& color) const;
    RGB continueThrough(const Layers& layers, double throughWeight, const SurfacePoint& at,
                        const Crossing& c, const State& state, RayCounts& counts) const;
    RGB traceDispersed(const Layers& layers, const SurfacePoint& at, const Crossing& c,
                       const State& state, State child, double& seen, RayCounts& counts) const;
    // crand's darkening of the diffuse light at one point, carried from
    // texture layer to layer (see localLight): per light, the sum of
    // crand times a fresh random number times the layer's pigment over the
    // layers shaded so far.
    struct Grain {
        explicit Grain(const Vec3& p);
        SampleRandom random;
        std::vector<RGB> sums;  // by the light's place in LightsFor
    };
    // `gathered`: the radiosity light arriving at p, when radiosity is on
    // (it replaces ambient light); `radiosityRay`: shading for a radiosity
    // ray, which sees no highlights and area lights as point lights;
    // `grain`: crand's darkening so far at this point, null when no layer
    // above has crand (made here for the first layer that has).
    RGB localLight(const scene::Texture& tex, const Color& surface, const scene::Object& obj,
                   const Vec3& p, const Vec3& n, const Vec3& viewDir, double eps, const RGB& fade,
                   RayCounts& counts, const RGB* gathered = nullptr, bool radiosityRay = false,
                   std::optional<Grain>* grain = nullptr) const;

    // --- radiosity (tracer_radiosity.cpp) ---
    // The light that other surfaces send to p (normal n, facing the
    // viewer): interpolated from the cache, or a new sample gathered.
    // `weight`: how much of it can reach the pixel (the ray's weight times
    // the surface's diffuse colour, as a grey).
    RGB radiosityLight(const Vec3& p, const Vec3& n, const scene::Object& obj, double eps,
                       double weight, const State& state, RayCounts& counts) const;
    // A new sample at p; `keep` says whether it may join the cache.
    RadiositySample gatherSample(const Vec3& p, const Vec3& n, const scene::Object& obj, double eps,
                                 const State& state, RayCounts& counts, bool& keep) const;

    // +Q0/+Q1: the colour of texture `top` at p with no lighting at all.
    RGB quickColour(const scene::Texture& top, const Vec3& p, const Vec3& uv) const;

    const World& world_;
    const scene::Scene& scene_;
    AtmosphereView atmosphere_;
    LightingQuality lighting_;
    LightingQuality radiosityLighting_;  // lighting_ without area-light sampling
    bool secondaryRays_;
    bool media_;       // +Q9 and up, and the scene has media somewhere
    bool subsurface_;  // +Q9 and up, and global_settings has a subsurface block
    const Radiosity* radiosity_ = nullptr;  // set when the frame computes radiosity
    bool quickColours_;                     // +Q0, +Q1
    bool quickColorPigments_;  // up to +Q5: a pigment's quick_color replaces its pattern
    bool opaqueSky_;           // alpha output sees the sky's own transmit (3.7 scenes)
    // Before 3.7 a filtering pigment's own colour is weighed by 1 - filter *
    // max(colour) - transmit, not 1 - filter - transmit (localLight).
    bool legacyFilterOpacity_;
    InteriorStack cameraInside_;  // regions containing the camera
    void addCameraRegions(const scene::Object& obj);
};

}  // namespace frameray::render
