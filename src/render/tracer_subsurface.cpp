// The tracer's part of subsurface light transport (render/subsurface.h):
// the sample points under and on the surface, the lights reaching them
// and the unscattered ray through the object.
#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>

#include "render/lighting.h"
#include "render/subsurface.h"
#include "render/tracer.h"
#include "util/hash.h"

namespace frameray::render {

namespace {

// povray's grey of a colour (its greyscale weights).
double greyOf(const RGB& c) {
    return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b;
}

double channel(const RGB& c, int i) {
    return i == 0 ? c.r : i == 1 ? c.g : c.b;
}
double& channel(RGB& c, int i) {
    return i == 0 ? c.r : i == 1 ? c.g : c.b;
}

// The radical inverse of i in `base` (a Halton coordinate).
double radicalInverse(uint64_t i, uint64_t base) {
    double inv = 1.0 / double(base), f = inv, r = 0.0;
    while (i > 0) {
        r += f * double(i % base);
        i /= base;
        f *= inv;
    }
    return r;
}

// Light bent into (or out of) a surface: `v` the travelling direction, `n`
// the surface's normal (either side), `eta` the ratio of the iors (from
// over to). False when the light is mirrored back whole.
bool bend(const Vec3& v, const Vec3& n, double eta, Vec3& out) {
    const Vec3 unitV = normalize(v);
    Vec3 unitN = normalize(n);
    double cosPhi = dot(unitV, unitN);
    if (cosPhi > 0)
        unitN = -unitN;
    else
        cosPhi = -cosPhi;
    const double cosThetaSqr = 1.0 + eta * eta * (cosPhi * cosPhi - 1.0);
    if (cosThetaSqr < 0.0) return false;
    out = normalize(unitV * eta + unitN * (eta * cosPhi - std::sqrt(cosThetaSqr)));
    return true;
}

constexpr double kTiny = 1e-10;  // povray's EPSILON for grazing light

// What the sampling needs of the surface point and its material.
struct Under {
    const World& world;
    const scene::Object& obj;
    const LightingQuality& lighting;
    uint64_t& shadowRays;
    Vec3 p{}, vOut{}, nOut{};  // the point, toward the viewer, its normal toward the viewer
    double eps = 0, mm = 0, eta = 1, A = 1, cosOut = 1, ftOut = 1;
    // Per channel (1/mm): reduced scattering, extinction, absorption.
    RGB sPrime{0.0}, tPrime{0.0}, absorb{0.0};
    bool usable[3] = {false, false, false};
    const LightsFor* lights = nullptr;  // the lights that light the object

    bool sameMaterial(const scene::Object* other) const {
        const scene::Interior* in = obj.interior.get();
        return other && (other == &obj || (in && other->interior.get() == in));
    }
    // A shadow ray's margin at a point of the surface.
    double margin(const Vec3& q) const {
        return std::max(eps, 1e-9 * std::max({std::fabs(q.x), std::fabs(q.y), std::fabs(q.z)}));
    }
    template <class F>
    void forLights(F&& f) const {
        for (const scene::Light& l : *lights) f(l);
    }
    // The light of `light` arriving at q on the surface (normal nq), and the
    // cosine it arrives at; false when none arrives.
    bool arrivingAt(const scene::Light& light, const Vec3& q, const Vec3& nq, RGB& arriving,
                    double& cosIn) const {
        LightPath path;
        if (!pathToLight(light, q, path)) return false;
        cosIn = std::fabs(dot(nq, path.toLight));
        if (cosIn < kTiny) return false;
        arriving = lightArriving(world, light, q, path, margin(q), lighting, shadowRays);
        return !arriving.isBlack();
    }
};

// The diffuse term: points of the surface found from a base point below
// it, each adding the lights arriving there through the dipole.
RGB diffuseTerm(const Under& u, int samples, uint64_t seed) {
    const double tMean = greyOf(u.absorb) + greyOf(u.sPrime);
    if (!(tMean > 0) || !std::isfinite(tMean)) return RGB(0.0);
    const double freePath = 1.0 / (tMean * u.mm);  // scene units
    const Vec3 inward = -u.nOut;
    Vec3 base = u.p + inward * freePath;
    Hit back;
    if (u.world.intersect({u.p, inward}, u.eps, 2 * freePath, back, scene::RayKind::Any))
        base = u.sameMaterial(back.object) ? u.p + inward * (back.t / 2)
                                           : u.p + inward * std::min(freePath, back.t - kTiny);
    const double shiftU = unitFromHash(fmix64(seed + 1)), shiftV = unitFromHash(fmix64(seed + 2));
    RGB total(0.0);
    int found = 0;
    for (int i = 0; i < samples; ++i) {
        const double a = std::fmod(radicalInverse(uint64_t(i) + 1, 2) + shiftU, 1.0);
        const double b = std::fmod(radicalInverse(uint64_t(i) + 1, 3) + shiftV, 1.0);
        const double z = 1.0 - 2.0 * a, r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double phi = 2.0 * std::numbers::pi * b;
        const Vec3 dir(r * std::cos(phi), r * std::sin(phi), z);
        Hit in;
        if (!u.world.intersect({base, dir}, 0.0, scene::kInfinity, in, scene::RayKind::Any))
            continue;
        const Vec3 pIn = base + dir * in.t;
        const Vec3 nIn = in.object->normalAt(pIn);
        const double cosPhi = std::max(std::fabs(dot(dir, nIn)), 0.01);
        const double area = 4.0 * std::numbers::pi * (in.t * u.mm) * (in.t * u.mm) / cosPhi;
        ++found;
        if (!u.sameMaterial(in.object)) continue;
        const double distSqr = dot(pIn - u.p, pIn - u.p) * u.mm * u.mm;
        u.forLights([&](const scene::Light& light) {
            RGB arriving;
            double cosIn = 0;
            if (!u.arrivingAt(light, pIn, nIn, arriving, cosIn)) return;
            const double ft = subsurface::fresnelTransmittance(cosIn, u.eta) * u.ftOut;
            for (int c = 0; c < 3; ++c) {
                if (!u.usable[c]) continue;
                const double rd =
                    subsurface::dipole(distSqr, channel(u.sPrime, c), channel(u.absorb, c), u.A);
                channel(total, c) += channel(arriving, c) * cosIn * ft * rd * area;
            }
        });
    }
    return found > 0 ? total * (1.0 / found) : total;
}

// Light scattered once at `point`, `sOut` mm down the refracted eye ray,
// in channel c: each light through where the straight way to it leaves
// the object.
double singleAt(const Under& u, const Vec3& point, double sOut, double cosOutPrime, int c) {
    const double tc = channel(u.tPrime, c);
    double lo = 0.0;
    u.forLights([&](const scene::Light& light) {
        LightPath toward;
        if (!pathToLight(light, point, toward)) return;
        Hit out;
        if (!u.world.intersect({point, toward.toLight}, 0.0, scene::kInfinity, out,
                               scene::RayKind::Any) ||
            !u.sameMaterial(out.object))
            return;
        const Vec3 xi = point + toward.toLight * out.t;
        const Vec3 nXi = out.object->normalAt(xi);
        RGB arriving;
        double cosIn = 0;
        if (!u.arrivingAt(light, xi, nXi, arriving, cosIn)) return;
        const double cosInPrimeSqr = 1.0 - (1.0 - cosIn * cosIn) / (u.eta * u.eta);
        if (cosInPrimeSqr < 0.0) return;
        const double cosInPrime = std::sqrt(cosInPrimeSqr);
        if (cosInPrime <= kTiny) return;
        const double sIn = length(point - xi) * u.mm * cosIn / cosInPrime;
        const double ft = subsurface::fresnelTransmittance(cosIn, u.eta) * u.ftOut;
        const double G = std::fabs(cosOutPrime / cosInPrime);
        const double phase = 0.25;  // isotropic, without the 1/pi
        const double factor = channel(u.sPrime, c) * ft * phase / (tc + G * tc) *
                              std::exp(-sIn * tc) * std::exp(-sOut * tc);
        lo += channel(arriving, c) * cosIn * factor;
    });
    return lo;
}

}  // namespace

bool Tracer::subsurfaceActive(const scene::Finish& fin, const State& state) const {
    return subsurface_ && fin.subsurface && !state.radiosity.ray;
}

RGB Tracer::subsurfaceLight(const scene::Finish& fin, const RGB& pigment, const SurfacePoint& at,
                            const State& state, RayCounts& counts) const {
    const scene::GlobalSettings& g = scene_.globals;
    if (state.subsurfaceDepth >= 2) return RGB(0.0);
    const int samplesDiffuse = state.subsurfaceDepth == 1 ? 1 : g.subsurface->samplesDiffuse;
    const int samplesSingle = state.subsurfaceDepth == 1 ? 1 : g.subsurface->samplesSingle;
    const LightsFor lights(scene_.lights, at.obj);
    Under u{world_, at.obj, lighting_, counts.shadow};
    u.p = at.p;
    u.eps = at.eps;
    u.mm = g.mmPerUnit;
    u.vOut = -normalize(at.viewDir);
    u.nOut = dot(at.geometric, u.vOut) < 0 ? -at.geometric : at.geometric;
    const Crossing crossing = crossingOf(at.obj, state);
    u.eta = crossing.iorBeyond / crossing.iorHere;
    const double fdr = subsurface::diffuseFresnelReflectance(u.eta);
    u.A = (1.0 + fdr) / (1.0 - fdr);
    u.cosOut = std::clamp(dot(u.vOut, u.nOut), -1.0, 1.0);
    u.ftOut = subsurface::fresnelTransmittance(u.cosOut, u.eta);
    const double ior = at.obj.interior ? at.obj.interior->ior : 1.0;
    for (int c = 0; c < 3; ++c) {
        const double alpha = subsurface::reducedAlbedo(channel(pigment, c) * fin.diffuse, ior);
        const double s = 1.0 / channel(fin.translucency, c);
        const double t = s / alpha;
        u.usable[c] = alpha > 0 && std::isfinite(s) && std::isfinite(t);
        if (u.usable[c]) {
            channel(u.sPrime, c) = s;
            channel(u.tPrime, c) = t;
            channel(u.absorb, c) = t - s;
        } else {
            channel(u.sPrime, c) = 0.0;
            channel(u.tPrime, c) = scene::kInfinity;  // no light passes
            channel(u.absorb, c) = 0.0;
        }
    }
    u.lights = &lights;

    // Numbers for this point: povray draws them from running sequences;
    // ours come from the point, so frames repeat.
    const uint64_t seed =
        fmix64(std::bit_cast<uint64_t>(at.p.x) ^
               fmix64(std::bit_cast<uint64_t>(at.p.y) ^ fmix64(std::bit_cast<uint64_t>(at.p.z))));
    RGB total = diffuseTerm(u, samplesDiffuse, seed);

    // Single scattering and the unscattered light, along the refracted
    // eye ray.
    Vec3 refracted;
    if (!bend(-u.vOut, u.nOut, 1.0 / u.eta, refracted)) return total;
    Hit exit;
    const bool exits =
        world_.intersect({at.p, refracted}, at.eps, scene::kInfinity, exit, scene::RayKind::Any);
    const double dist = exits ? exit.t * u.mm : scene::kInfinity;
    const double cosOutPrime = std::sqrt(1.0 - (1.0 - u.cosOut * u.cosOut) / (u.eta * u.eta));
    uint64_t draws = 0;
    for (int i = 0; i < samplesSingle; ++i) {
        for (int c = 0; c < 3; ++c) {
            const double e = unitFromHash(fmix64(seed ^ fmix64(++draws * 0x9E3779B97F4A7C15ULL)));
            if (!u.usable[c]) continue;
            const double sOut = std::fabs(std::log(e)) / channel(u.tPrime, c);
            if (!(sOut < dist)) continue;
            const Vec3 point = at.p + refracted * (sOut / u.mm);
            channel(total, c) += singleAt(u, point, sOut, cosOutPrime, c) / samplesSingle;
        }
    }

    // Unscattered: straight through the object and out of its far side.
    RGB att(0.0);
    for (int c = 0; c < 3; ++c)
        if (u.usable[c]) channel(att, c) = std::exp(-channel(u.tPrime, c) * dist);
    const double weight = att.maxComponent();
    if (!exits || !(weight > g.adcBailout) || !u.sameMaterial(exit.object)) return total;
    const Vec3 pExit = at.p + refracted * exit.t;
    Vec3 nExit = exit.object->normalAt(pExit);
    if (dot(refracted, nExit) > 0) nExit = -nExit;
    Vec3 onward;
    if (!bend(refracted, nExit, u.eta, onward)) return total;
    State child;
    child.level = state.level + 1;
    child.weight = weight;
    child.kind = scene::RayKind::Camera;
    child.inside = state.inside;
    child.band = state.band;
    child.radiosity = state.radiosity;
    child.subsurfaceDepth = state.subsurfaceDepth + 1;
    if (child.level > g.maxTraceLevel) return total;
    return total + trace({pExit, onward}, u.margin(pExit), child, counts) * att;
}

}  // namespace frameray::render
