#include "render/photons.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <optional>

#include "render/dispersion.h"
#include "render/media.h"
#include "render/optics.h"
#include "render/photon_file.h"
#include "render/tracer.h"
#include "render/world.h"
#include "scene/hit_tolerance.h"
#include "util/hash.h"

namespace frameray::render {

namespace {

constexpr double kPi = std::numbers::pi;
// The least cosine at which a stored photon lights a surface.
constexpr double kPhotonFacing = 1e-10;

// povray 3.7 gathers surface photons and media photons alike (measured
// on a patch of evenly spaced photons, tests/conformance/scenes/
// photons_gather.pov): the photons within the gather radius, at most
// gather max (the radius then shrinking to the farthest of them). With
// fewer than gather min it searches again within three times the radius
// and keeps the wider search when the density it finds (count / radius^2)
// is less than expand_thresholds' increase above the first one's, or when
// it found some but fewer than expand_thresholds' minimum; else the first
// search stands, even when it found nothing (so a dark ring surrounds a
// caustic there). Returns the radius of the disc (sphere) the photons in
// `found` stand for. At a surface (`flatten`, its normal) the searches
// use povray's flattened distance (PhotonMap::nearest; fact from povray's
// source, lighting/photons.cpp), media searches a plain sphere.
double adaptiveGather(const PhotonMap& map, const Vec3& p, const Vec3* flatten, double radius,
                      int gatherMin, int gatherMax, double expandIncrease, int expandMin,
                      std::vector<PhotonNeighbour>& found) {
    auto gather = [&](double size, std::vector<PhotonNeighbour>& out) {
        map.nearest(p, size, gatherMax, flatten, out);
        return static_cast<int>(out.size()) == gatherMax ? std::sqrt(out.back().distance2) : size;
    };
    const double first = gather(radius, found);
    if (static_cast<int>(found.size()) >= gatherMin) return first;
    double before = static_cast<double>(found.size()) / (first * first);
    thread_local std::vector<PhotonNeighbour> wider;
    if (before == 0) {
        before = 1e-16;
        // Nothing within the radius: the wider search is kept only when it
        // finds fewer than expand_thresholds' minimum (its density, at
        // least that minimum over (3 r)^2, is always far more than the
        // increase allowed over 1e-16, as checked here), so it can stop
        // at that many (much of the floor around a caustic is so).
        const double leastAfter = expandMin / (9.0 * radius * radius);
        if (expandMin > 0 && expandMin <= gatherMax &&
            (leastAfter - before) / before >= expandIncrease) {
            map.nearest(p, 3.0 * radius, expandMin, flatten, wider);
            if (static_cast<int>(wider.size()) == expandMin) return first;  // dark
            found.swap(wider);
            return 3.0 * radius;
        }
    }
    const double widerRadius = gather(3.0 * radius, wider);
    const double after = static_cast<double>(wider.size()) / (widerRadius * widerRadius);
    const int n = static_cast<int>(wider.size());
    if ((after - before) / before < expandIncrease || (n < expandMin && n > 0)) {
        found.swap(wider);
        return widerRadius;
    }
    return first;
}

// --- targets --------------------------------------------------------------

// One object photons are shot at: a child of a split union, or a target
// itself. Its bounding sphere aims the photons; only photons whose first
// surface is its own count as hitting it for autostop (measured: a ring
// and a glass sphere inside it, one split union, shoot exactly as many
// photons as when each is a target of its own).
struct Target {
    const scene::Object* shape;
    double multiplier;
    std::vector<const scene::Object*> primitives;  // sorted
    Vec3 centre;
    double radius;
};

void collectPrimitives(const scene::Object& obj, std::vector<const scene::Object*>& out) {
    if (!obj.isCsg()) {
        out.push_back(&obj);
        return;
    }
    for (const scene::ObjectRef& child : obj.children) collectPrimitives(*child, out);
}

void addShootingShapes(const scene::Object& obj, double multiplier, std::vector<Target>& out) {
    // A union is split into its children unless it says split_union off
    // (its children's own target multipliers do not matter then).
    if (obj.isCsg() && obj.op == scene::CsgOp::Union && obj.photons.splitUnion) {
        for (const scene::ObjectRef& child : obj.children)
            addShootingShapes(*child, multiplier, out);
        return;
    }
    const scene::Bounds b = obj.surfaceBounds();
    if (b.isEmpty() || !b.isFinite()) return;  // povray cannot aim at an infinite object
    Target t{&obj, multiplier, {}, (b.lo + b.hi) * 0.5, length(b.hi - b.lo) * 0.5};
    collectPrimitives(obj, t.primitives);
    std::sort(t.primitives.begin(), t.primitives.end());
    out.push_back(std::move(t));
}

void findTargets(const scene::Object& obj, std::vector<Target>& out) {
    if (obj.photons.target > 0) {
        addShootingShapes(obj, obj.photons.target, out);
        return;
    }
    // A target inside a plain union (the union itself is no target).
    if (obj.isCsg() && obj.op == scene::CsgOp::Union)
        for (const scene::ObjectRef& child : obj.children) findTargets(*child, out);
}

bool isPartOf(const Target& t, const scene::Object* primitive) {
    return std::binary_search(t.primitives.begin(), t.primitives.end(), primitive);
}

// --- the surface seen by a photon ---------------------------------------

// What a surface does to a photon: how much it mirrors and lets through,
// and the normals to bend it with (the tracer's layer rules, reduced to
// what photons need).
struct Response {
    RGB reflect{0.0};
    RGB through{0.0};
    Vec3 reflectNormal;
    Vec3 refractNormal;
};

Response respondLayers(const scene::Texture& top, const Vec3& texP, const Vec3& uv, const Vec3& dir,
                       const Vec3& geometric, double fresnelRatio) {
    Response r;
    RGB through(1.0);
    r.reflectNormal = r.refractNormal = geometric;
    const size_t layerCount = 1 + top.layersBelow.size();
    for (size_t i = 0; i < layerCount; ++i) {
        const scene::Texture& tex = i == 0 ? top : *top.layersBelow[i - 1];
        const Vec3& layerP = tex.uvMapping ? uv : texP;
        const scene::SurfaceInfo unperturbed{geometric, dir, uv};
        const Vec3 n = tex.perturbNormal(layerP, geometric, uv, &unperturbed);
        const scene::SurfaceInfo info{n, dir, uv};
        const Color surface = tex.pigment->at(tex.transform.inversePoint(layerP), &info);
        RGB reflectivity(0.0);
        if (tex.finish->reflection.any()) {
            const double cosView = std::clamp(-dot(dir, n), 0.0, 1.0);
            reflectivity = reflectance(tex.finish->reflection, cosView, fresnelRatio, surface.rgb);
            r.reflect += reflectivity;
            if (i == 0) r.reflectNormal = n;
        }
        r.refractNormal = n;
        if (surface.filter + surface.transmit <= 0) return r;
        through = through * (surface.rgb * surface.filter + RGB(surface.transmit));
        if (tex.finish->conserveEnergy) through = through * (RGB(1.0) - reflectivity);
    }
    r.through = through;
    return r;
}

Response respond(const scene::Texture& top, const Vec3& texP, const Vec3& uv, const Vec3& dir,
                 const Vec3& geometric, double fresnelRatio) {
    if (!top.map) return respondLayers(top, texP, uv, dir, geometric, fresnelRatio);
    Response sum;
    sum.reflectNormal = sum.refractNormal = geometric;
    const Vec3 q = top.transform.inversePoint(top.uvMapping ? uv : texP);
    const Vec3 entry = top.map->entryPoint(q);
    const scene::SurfaceInfo surface{geometric, dir, uv};
    top.map->visit(
        q,
        [&](const scene::Texture& t, double w) {
            const Response part = respond(t, entry, uv, dir, geometric, fresnelRatio);
            sum.reflect += part.reflect * w;
            sum.through += part.through * w;
            sum.reflectNormal = part.reflectNormal;
            sum.refractNormal = part.refractNormal;
        },
        &surface);
    return sum;
}

// --- tracing --------------------------------------------------------------

struct Path {
    scene::Ray ray;   // unit direction
    double tMin = 0;  // crossings closer than this are the surface the photon left
    RGB power;        // the light's colour, attenuated, times what surfaces passed
    double travelled = 0;
    int level = 1;
    bool bounced = false;  // reflected or refracted at a target already
    InteriorStack inside;
    SpectralBand band;
    std::uint64_t id = 0;  // hashes the jitter of its media photons
    // povray's ray weight, which adc_bailout is compared with: the largest
    // component of each reflection and filter met, whatever the photon's
    // colour (a photon whose colour a filter has turned black goes on and
    // is stored, as povray's do: measured, a red mirror with a cyan filter
    // stores 6230 photons from 1195 shot).
    double weight = 1.0;
};

struct Tracing {
    const World& world;
    const scene::Light& light;
    const Target& target;
    double spread;  // the beam's step: angle between photons, or distance (parallel)
    bool parallel;
    int maxLevel;
    double adcBailout;
    const scene::PhotonSettings& settings;
    std::vector<Photon>& out;
    std::vector<Photon>& mediaOut;

    // Traces one photon; returns whether its first surface was the target's.
    bool trace(Path path) const;
    void store(const Path& path, const Vec3& p) const;
    double lightFade(double travelled) const;
    void cross(Path& path, double depth) const;
    void depositInMedia(const Path& path, double depth, const MediaSet& set) const;
    void interact(const Path& path, const Hit& hit, const Vec3& p) const;
    void refract(const Path& path, const Hit& hit, const Vec3& p, const Response& r,
                 const InteriorStack& beyond, double iorHere, double eps) const;
};

// Where a photon leaving p starts seeing surfaces: povray's minimum hit
// depth (scene/hit_tolerance.h), or 1e-9 of the coordinates far from the
// origin.
double photonEpsilon(const Vec3& p) {
    const double m = scene::coordinateMagnitude(p, p);
    return std::max({m * 1e-9, scene::scaledTolerance(scene::kMinHitDepth, m), 1e-300});
}

// povray keeps a photon's direction in two signed bytes (facts from its
// source, lighting/photons.cpp): towards where the photon came from, its
// elevation and its azimuth about y, each cut toward zero to a whole
// multiple of pi/127. Frameray keeps the direction that gives, so that
// grazing photons (within 1.4 degrees of a surface) and the phase
// functions of media see what povray's see. Returns the travel direction.
Vec3 coarseDirection(const Vec3& travel) {
    const double len = length(travel);
    if (!(len > 0)) return travel;
    const Vec3 back = travel * (-1.0 / len);
    const double flat = std::sqrt(back.x * back.x + back.z * back.z);
    double elevation = std::acos(std::min(1.0, flat));
    if (back.y < 0) elevation = -elevation;
    double azimuth = flat > 0 ? std::acos(std::clamp(back.x / flat, -1.0, 1.0)) : 0.0;
    if (back.z < 0) azimuth = -azimuth;
    constexpr double step = kPi / 127.0;
    const double e = std::trunc(elevation * 127.0 / kPi) * step;
    const double a = std::trunc(azimuth * 127.0 / kPi) * step;
    return -Vec3(std::cos(e) * std::cos(a), std::sin(e), std::cos(e) * std::sin(a));
}

Photon makePhoton(const Vec3& p, const RGB& power, const Vec3& travel) {
    const Vec3 direction = coarseDirection(travel);
    Photon ph{};
    ph.position[0] = static_cast<float>(p.x);
    ph.position[1] = static_cast<float>(p.y);
    ph.position[2] = static_cast<float>(p.z);
    ph.power[0] = static_cast<float>(power.r);
    ph.power[1] = static_cast<float>(power.g);
    ph.power[2] = static_cast<float>(power.b);
    ph.direction[0] = static_cast<float>(direction.x);
    ph.direction[1] = static_cast<float>(direction.y);
    ph.direction[2] = static_cast<float>(direction.z);
    return ph;
}

double Tracing::lightFade(double travelled) const {
    return light.fadeDistance > 0 && light.fadePower > 0
               ? 2.0 / (1.0 + std::pow(travelled / light.fadeDistance, light.fadePower))
               : 1.0;
}

void Tracing::store(const Path& path, const Vec3& p) const {
    const double scale =
        parallel ? spread * spread : spread * spread * path.travelled * path.travelled;
    const RGB power = path.power * (scale * lightFade(path.travelled));
    out.push_back(makePhoton(p, power, path.ray.direction));
}

// Media photons along the stretch [0, depth] of a photon that has bounced
// (povray 3.7's rule, read from its documentation and measured): the
// stretch is cut into the media's intervals (one for constant media that
// no light scatters in; spot and cylinder light volumes do not cut it
// here); an interval of length ds gets n = floor(ds / (factor * local
// spacing)) photons, the local spacing being the beam's step times the
// distance the photon has come (the step itself for parallel lights), at
// most `media` max_steps of them, the factor then widened so that they
// still cover ds; photon j lies at (j + 1/2 + jitter (u - 1/2)) / n of the
// interval and carries the light of the stretch's start times factor *
// local spacing at that point, times the spacing squared there: the light
// of a tube of space factor * spacing long.
void Tracing::depositInMedia(const Path& path, double depth, const MediaSet& set) const {
    bool scatters = false, constant = true;
    int intervals = 1;
    for (const scene::Media* m : set.media()) {
        scatters = scatters || m->scatters();
        constant = constant && m->constant();
        intervals = std::max(intervals, m->intervals);
    }
    if (!scatters) return;
    bool lit = false;
    for (const scene::Light& l : world.scene().lights) lit = lit || l.mediaInteraction;
    if (constant && !lit) intervals = 1;
    const double local = parallel ? spread : spread * path.travelled;
    const double baseFactor = settings.mediaFactor > 0 ? settings.mediaFactor : 1.0;
    if (!(local > 0)) return;
    const double ds = depth / intervals;
    std::uint64_t index = 0;
    for (int i = 0; i < intervals; ++i) {
        double factor = baseFactor;
        const double wanted = ds / (local * factor);
        int n = wanted < 1e9 ? static_cast<int>(wanted) : settings.mediaMaxSteps;
        if (n > settings.mediaMaxSteps) {
            n = settings.mediaMaxSteps;
            factor = ds / (local * n);
        }
        for (int j = 0; j < n; ++j) {
            const std::uint64_t h = splitmix64(
                path.id ^ splitmix64(++index + (static_cast<std::uint64_t>(path.level) << 48)));
            const double u = settings.jitter * (unitFromHash(h) - 0.5);
            const double t = i * ds + (j + 0.5 + u) / n * ds;
            const double travelled = path.travelled + t;
            const double length = parallel ? factor * spread : factor * spread * travelled;
            const double area =
                parallel ? spread * spread : spread * spread * travelled * travelled;
            const RGB power = path.power * (length * area * lightFade(travelled));
            mediaOut.push_back(makePhoton(path.ray.at(t), power, path.ray.direction));
        }
    }
}

// The stretch [0, depth] of the photon's ray, through the regions it is
// in: their media (where all of them are hollow, as for the tracer's rays)
// dim it and, once it has bounced, take photons; a fading interior fades
// it.
void Tracing::cross(Path& path, double depth) const {
    if (!path.inside.empty() && path.inside.allHollow()) {
        MediaSet set;
        for (int i = 0; i < path.inside.size(); ++i)
            if (const scene::Interior* in = path.inside[i].interior) set.add(in->media);
        if (!set.empty()) {
            if (path.bounced && settings.mediaMaxSteps > 0) depositInMedia(path, depth, set);
            path.power = path.power * mediaTransmittance(path.ray, depth, set);
        }
    }
    if (const InteriorStack::Region* in = path.inside.innermost();
        in && in->interior && in->interior->fades())
        path.power = path.power * interiorFade(*in->interior, depth);
    path.travelled += depth;
}

bool Tracing::trace(Path path) const {
    Hit hit;
    for (;;) {
        if (!world.intersect(path.ray, path.tMin, scene::kInfinity, hit, scene::RayKind::Photon))
            return false;
        // Photons do not see no_image and no_shadow surfaces (povray 3.7,
        // measured: a no_image or no_shadow target or floor stores no
        // photons; no_reflection changes nothing). On its way to its
        // target a photon passes pass_through objects (entering and
        // leaving their interiors) and is stopped by every other one,
        // other targets too (povray 3.7).
        if (path.bounced || isPartOf(target, hit.object)) break;
        if (!hit.object->photons.passThrough) return false;
        const Vec3 p = path.ray.at(hit.t);
        cross(path, hit.t);
        const InteriorStack::Region region = InteriorStack::of(*hit.object);
        if (path.inside.contains(region.key))
            path.inside.remove(region.key);
        else
            path.inside.push(region);
        path.ray.origin = p;
        path.tMin = photonEpsilon(p);
    }
    const Vec3 p = path.ray.at(hit.t);
    const bool onTarget = !path.bounced;
    cross(path, hit.t);
    if (path.bounced && hit.object->photons.collect) store(path, p);
    interact(path, hit, p);
    return onTarget;
}

void Tracing::interact(const Path& path, const Hit& hit, const Vec3& p) const {
    const scene::Object& obj = *hit.object;
    const bool reflects = scene::photonsActive(obj.photons.reflection, light.photons.reflection);
    const bool refracts = scene::photonsActive(obj.photons.refraction, light.photons.refraction);
    if ((!reflects && !refracts) || path.level >= maxLevel) return;
    const Vec3& dir = path.ray.direction;
    static const scene::Texture kOpaque;
    const scene::Texture& tex = obj.texture ? *obj.texture : kOpaque;
    Vec3 uv(p.x, p.y, 0);
    Vec3 geometric = tex.usesUv() ? obj.normalAndUvAt(p, uv) : obj.normalAt(p);
    if (dot(geometric, dir) > 0) geometric = -geometric;
    const InteriorStack::Region region = InteriorStack::of(obj);
    const bool leaving = path.inside.contains(region.key);
    InteriorStack beyond = path.inside;
    if (leaving)
        beyond.remove(region.key);
    else
        beyond.push(region);
    const double iorHere = path.inside.ior(path.band);
    const double own = region.interior ? dispersedIor(*region.interior, path.band) : 1.0;
    const double iorBeyond = leaving ? beyond.ior(path.band) : own;
    const double fresnelRatio =
        leaving && path.inside.size() > 1 ? iorHere / own : iorBeyond / iorHere;
    const Response r = respond(tex, p, uv, dir, geometric, fresnelRatio);
    const double eps = photonEpsilon(p);
    if (reflects && !r.reflect.isBlack()) {
        Path child = path;
        child.id = splitmix64(path.id + 1);
        child.level = path.level + 1;
        child.bounced = true;
        child.power = path.power * r.reflect;
        // povray weighs a reflected photon by the reflection twice
        // (measured: a glass with reflection 0.06 reflects no photons at
        // adc_bailout 1/255, one with 0.07 does).
        const double k = r.reflect.maxComponent();
        child.weight = path.weight * k * k;
        if (child.weight >= adcBailout) {
            const Vec3& n = r.reflectNormal;
            Vec3 reflected = dir - n * (2 * dot(dir, n));
            if (dot(reflected, geometric) < 0)
                reflected = dir - geometric * (2 * dot(dir, geometric));
            child.ray = {p, reflected};
            child.tMin = eps;
            trace(child);
        }
    }
    if (refracts && grey(r.through) > adcBailout) refract(path, hit, p, r, beyond, iorHere, eps);
}

void Tracing::refract(const Path& path, const Hit& hit, const Vec3& p, const Response& r,
                      const InteriorStack& beyond, double iorHere, double eps) const {
    const Vec3& dir = path.ray.direction;
    const Vec3& n = r.refractNormal;
    Path child = path;
    child.id = splitmix64(path.id + 2);
    child.bounced = true;
    child.inside = beyond;
    child.power = path.power * r.through;
    child.weight = path.weight * std::max(0.0, r.through.maxComponent());
    if (child.weight < adcBailout) return;
    (void)hit;
    auto bend = [&](Path& c, double eta) {
        if (const auto bent = refractedDirection(dir, n, eta)) {
            c.ray = {p, *bent};
            c.tMin = eps;
            return true;
        }
        // Total internal reflection: mirrored back inside with what the
        // reflection term did not take.
        c.inside = path.inside;
        const RGB rest(std::max(0.0, 1.0 - r.reflect.r), std::max(0.0, 1.0 - r.reflect.g),
                       std::max(0.0, 1.0 - r.reflect.b));
        c.power = path.power * r.through * rest;
        const Vec3 reflected = dir - n * (2 * dot(dir, n));
        c.ray = {p, reflected};
        c.tMin = eps;
        return true;
    };
    const double iorBeyond = beyond.ior(path.band);
    // A photon goes one level deeper at every surface it passes, bent or
    // not (povray 3.7 traces the transmitted photon as a new ray).
    child.level = path.level + 1;
    if (iorHere == iorBeyond) {
        child.ray = {p, dir};
        child.tMin = eps;
        trace(child);
        return;
    }
    if (path.band.white() && (path.inside.disperses() || beyond.disperses())) {
        // A white photon entering or leaving a dispersive interior splits
        // into the interior's bands, each bent by its own ior.
        const InteriorStack& dispersive = beyond.disperses() ? beyond : path.inside;
        const int bands = dispersive.innermost()->interior->dispersionSamples;
        for (int k = 0; k < bands; ++k) {
            Path part = child;
            part.id = splitmix64(child.id + 3 + static_cast<std::uint64_t>(k));
            part.band = dispersionBand(k, bands);
            part.power = child.power * dispersionBandColour(k, bands);
            if (bend(part, path.inside.ior(part.band) / beyond.ior(part.band))) trace(part);
        }
        return;
    }
    if (bend(child, iorHere / iorBeyond)) trace(child);
}

// --- shooting -------------------------------------------------------------

// One light shooting at one target: the cone (or, for a parallel light,
// the cylinder) of directions and how photons are laid out in it.
struct Beam {
    const scene::Light* light;
    const Target* target;
    bool parallel = false;
    Vec3 origin;               // point light: where photons leave; parallel: unused
    Vec3 u, v, w;              // w towards the target's centre (along the light for parallel)
    double step = 0;           // angle between rings (point) or distance (parallel)
    double extent = 0;         // largest angle (point) or radius (parallel)
    double planeDistance = 0;  // parallel: from the light's plane to the centre
    std::uint64_t seed = 0;

    int rings() const { return static_cast<int>(std::floor(extent / step + 1e-9)) + 1; }
    int ringSize(int k) const {
        const double around = parallel ? 2 * kPi * k : 2 * kPi * std::sin(k * step) / step;
        return std::max(1, static_cast<int>(std::lround(around)));
    }
};

void frame(const Vec3& w, Vec3& u, Vec3& v) {
    const Vec3 helper = std::fabs(w.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    u = normalize(cross(helper, w));
    v = cross(w, u);
}

std::optional<Beam> aim(const scene::Light& light, const Target& target, double spacing,
                        std::uint64_t seed) {
    Beam b;
    b.light = &light;
    b.target = &target;
    b.seed = seed;
    const double s = spacing * target.multiplier;
    if (light.parallel || light.kind == scene::LightKind::Cylinder) {
        b.parallel = true;
        b.w = light.axis();
        frame(b.w, b.u, b.v);
        b.step = s;
        b.extent = target.radius;
        b.planeDistance = dot(target.centre - light.position, b.w);
        b.origin = target.centre - b.w * b.planeDistance;
        return b;
    }
    const Vec3 toCentre = target.centre - light.position;
    const double d = length(toCentre);
    if (d <= 0) return std::nullopt;
    b.origin = light.position;
    b.w = toCentre / d;
    frame(b.w, b.u, b.v);
    b.step = s / d;
    b.extent = d <= target.radius ? kPi : std::asin(target.radius / d);
    return b;
}

// The photon j of ring k of a beam.
scene::Ray photonRay(const Beam& b, int k, int j, int n, double jitter) {
    const std::uint64_t h = splitmix64(
        b.seed ^ splitmix64((static_cast<std::uint64_t>(k) << 32) ^ static_cast<std::uint64_t>(j)));
    const double jr = jitter * (unitFromHash(h) - 0.5);
    const double jp = jitter * (unitFromHash(splitmix64(h)) - 0.5);
    const double dPhi = 2 * kPi / n;
    const double phi = (j + jp) * dPhi;
    if (b.parallel) {
        const double rho = std::max(0.0, (k + (k > 0 ? jr : 0.0)) * b.step);
        const Vec3 o = b.origin + (b.u * std::cos(phi) + b.v * std::sin(phi)) * rho;
        return {o, b.w};
    }
    const double theta = std::max(0.0, (k + (k > 0 ? jr : 0.0)) * b.step);
    const Vec3 d =
        (b.u * std::cos(phi) + b.v * std::sin(phi)) * std::sin(theta) + b.w * std::cos(theta);
    return {b.origin, normalize(d)};
}

struct RingResult {
    std::vector<Photon> photons;
    std::vector<Photon> media;
    std::uint64_t shot = 0;
    bool hit = false;
};

struct Shooter {
    const World& world;
    const scene::PhotonSettings& settings;
    int maxLevel;
    double adcBailout;

    RingResult ring(const Beam& b, int k) const;
    void shoot(const Beam& b, std::vector<Photon>& out, std::vector<Photon>& media,
               std::uint64_t& shot) const;
};

RingResult Shooter::ring(const Beam& b, int k) const {
    RingResult result;
    const scene::Light& light = *b.light;
    const int n = b.ringSize(k);
    const Tracing tracing{world,    light,      *b.target, b.step,         b.parallel,
                          maxLevel, adcBailout, settings,  result.photons, result.media};
    for (int j = 0; j < n; ++j) {
        const scene::Ray ray = photonRay(b, k, j, n, settings.jitter);
        // The spot cone and cylinder edge weigh each photon; the fading
        // with distance is applied where it lands.
        const double shape = light.kind == scene::LightKind::Point && !light.parallel
                                 ? 1.0
                                 : light.attenuation(b.parallel ? ray.origin + b.w * b.planeDistance
                                                                : ray.origin + ray.direction,
                                                     light.fadeDistance);
        ++result.shot;
        if (shape <= 0) continue;
        Path path;
        path.ray = ray;
        path.power = light.color * shape;
        path.id = splitmix64(b.seed ^ splitmix64((static_cast<std::uint64_t>(k) << 32) ^
                                                 static_cast<std::uint64_t>(j) ^ 0x5bd1e995ULL));
        if (tracing.trace(path)) result.hit = true;
    }
    return result;
}

void Shooter::shoot(const Beam& b, std::vector<Photon>& out, std::vector<Photon>& media,
                    std::uint64_t& shot) const {
    const int rings = b.rings();
    bool hitOnce = false;
    // Rings run in parallel a batch at a time; whether to go on is decided
    // ring by ring in order afterwards, so the photons kept do not depend
    // on the thread count.
    constexpr int kBatch = 16;
    std::vector<RingResult> batch(kBatch);
    for (int first = 0; first < rings; first += kBatch) {
        const int count = std::min(kBatch, rings - first);
        tbb::parallel_for(0, count,
                          [&](int i) { batch[static_cast<size_t>(i)] = ring(b, first + i); });
        for (int i = 0; i < count; ++i) {
            RingResult& r = batch[static_cast<size_t>(i)];
            out.insert(out.end(), r.photons.begin(), r.photons.end());
            media.insert(media.end(), r.media.begin(), r.media.end());
            shot += r.shot;
            const int k = first + i;
            // povray's autostop: a complete ring without a hit ends the
            // beam once a photon has hit and the rings are past the
            // autostop fraction of the cone.
            if (!r.hit && hitOnce && k * b.step >= settings.autostop * b.extent) return;
            hitOnce = hitOnce || r.hit;
        }
    }
}

bool shoots(const scene::Light& light) {
    return light.photons.refraction != scene::PhotonToggle::Off ||
           light.photons.reflection != scene::PhotonToggle::Off;
}

// Whether a light shoots at an object: the two together turn refraction
// or reflection on (povray 3.7 skips the pair otherwise, also when it
// turns `count` into a spacing).
bool shootsAt(const scene::Light& light, const scene::Object& target) {
    const scene::ObjectPhotons& o = target.photons;
    return scene::photonsActive(o.refraction, light.photons.refraction) ||
           scene::photonsActive(o.reflection, light.photons.reflection);
}
bool shootsAt(const scene::Light& light, const Target& t) {
    return shootsAt(light, *t.shape);
}

// The objects that say target, unsplit: a target's own, or inside any
// CSG that is none (povray looks into every compound object).
void findWholeTargets(const scene::Object& obj, std::vector<const scene::Object*>& out) {
    if (obj.photons.target > 0) {
        out.push_back(&obj);
        return;
    }
    if (obj.isCsg())
        for (const scene::ObjectRef& child : obj.children) findWholeTargets(*child, out);
}

// The spacing povray 3.7 derives from `count` (its documented guess, not
// the photons it then shoots): each light and whole target that shoot
// together expect pi (r / (m s))^2 photons, r the radius of the sphere
// around the target's bounding box and m its spacing multiplier, times 1.5
// when both refraction and reflection are on, times 3 (both) or 2
// (refraction only) when the target collects photons, times 1/2; the
// spacing s makes their sum `count`. (Measured with povray: count 10000
// shoots 4403 photons at a target with refraction and reflection on, and
// 20289 at one with reflection only.)
double spacingForCount(const scene::Scene& scene, int count) {
    std::vector<const scene::Object*> targets;
    for (const scene::ObjectRef& obj : scene.objects) findWholeTargets(*obj, targets);
    double sum = 0;
    for (const scene::Light& light : scene.lights) {
        if (!shoots(light)) continue;
        for (const scene::Object* t : targets) {
            const scene::Bounds b = t->surfaceBounds();
            if (b.isEmpty() || !b.isFinite()) continue;
            const bool refracts =
                scene::photonsActive(t->photons.refraction, light.photons.refraction);
            const bool reflects =
                scene::photonsActive(t->photons.reflection, light.photons.reflection);
            if (!refracts && !reflects) continue;
            const double r = length(b.hi - b.lo) * 0.5 / t->photons.target;
            double x = kPi * r * r;
            if (refracts && reflects) x *= 1.5;
            if (t->photons.collect && refracts) x *= reflects ? 3 : 2;
            sum += 0.5 * x;
        }
    }
    return sum > 0 ? std::sqrt(sum / count) : 1.0;
}

// What shoots photons: each light, or with `photons { area_light }` each
// point of an area light's grid as a light of its own, with its share of
// the colour, its beams spaced sqrt(size1 * size2) times wider (measured:
// povray's photon count for a 3x3 and a 4x2 grid is exactly the sum of
// such beams from the grid points, and the caustic keeps its brightness).
struct Emitter {
    scene::Light light;
    double spacingScale = 1;
    std::uint64_t index = 0;  // seeds its beams
};

std::vector<Emitter> emitters(const std::vector<scene::Light>& lights) {
    std::vector<Emitter> out;
    for (size_t li = 0; li < lights.size(); ++li) {
        const scene::Light& light = lights[li];
        if (!shoots(light)) continue;
        const std::uint64_t base = static_cast<std::uint64_t>(li) << 20;
        const scene::AreaLight& a = light.area;
        const bool spread = light.isArea && light.photons.areaLight && !light.parallel &&
                            light.kind != scene::LightKind::Cylinder && a.size1 * a.size2 > 1;
        if (!spread) {
            out.push_back({light, 1.0, base});
            continue;
        }
        const int n = a.size1 * a.size2;
        for (int j = 0; j < a.size2; ++j)
            for (int i = 0; i < a.size1; ++i) {
                Emitter e{light, std::sqrt(static_cast<double>(n)),
                          base + static_cast<std::uint64_t>(j * a.size1 + i) + 1};
                e.light.isArea = false;
                e.light.color = light.color * (1.0 / n);
                e.light.position = light.position + a.gridOffset(i, j, a.axis1, a.axis2);
                // A spotlight's point_at moves with its grid point.
                e.light.pointAt = light.pointAt + (e.light.position - light.position);
                out.push_back(std::move(e));
            }
    }
    return out;
}

// The surface map's gather radius, as povray 3.7 estimates it (the media
// map's rule below, with discs for spheres; measured: povray's estimate
// gives the same image as an explicit radius of 0.002, 0.0105, 0.021,
// 0.12 and 0.40 on caustics whose estimate here is 0.0019, 0.0107,
// 0.024, 0.10 and 0.26). povray takes its samples at random, so its
// radius scatters from scene to scene around the rule's expected value
// (0.22 to 0.75 over fifteen random draws on the last of those scenes);
// this takes up to 4000 evenly spaced photons of the map (the tree's
// order spreads them over it) to come close to that expected value:
// around each the density of the gather max photons nearest it, n / (pi
// r^2); their mean; the radius of a disc holding gather max photons at
// that density; widened by 1 + 20 f, f the fraction of samples whose
// density within that radius lies between 5 % and 70 % of the mean.
double estimateRadius(const PhotonMap& map, int gatherMax) {
    if (map.empty()) return 0;
    const size_t n = map.size();
    const size_t samples = std::min<size_t>(n, 4000);
    // The density around each sample (-1: none found), in parallel; each
    // sample has its own slot, so the result does not depend on threads.
    auto densities = [&](double limit, size_t offset) {
        std::vector<double> out(samples, -1.0);
        tbb::parallel_for(size_t{0}, samples, [&](size_t i) {
            thread_local std::vector<PhotonNeighbour> found;
            const Vec3 at = map.photons()[(i * n + offset) / samples % n].at();
            map.nearest(at, limit, gatherMax, found);
            if (found.empty()) return;
            const double r = static_cast<int>(found.size()) == gatherMax
                                 ? std::sqrt(found.back().distance2)
                                 : limit;
            if (r > 0) out[i] = static_cast<double>(found.size()) / (kPi * r * r);
        });
        return out;
    };
    double sum = 0;
    size_t counted = 0;
    for (const double d : densities(scene::kInfinity, 0))
        if (d >= 0) {
            sum += d;
            ++counted;
        }
    if (counted == 0) return 0;
    const double mean = sum / static_cast<double>(counted);
    if (!(mean > 0) || !std::isfinite(mean)) return 0;
    const double radius = std::sqrt(static_cast<double>(gatherMax) / (kPi * mean));
    // A second set of samples, offset from the first.
    size_t sparse = 0;
    for (const double d : densities(radius, n / 2))
        if (d >= 0 && d < 0.7 * mean && d > 0.05 * mean) ++sparse;
    return radius * (1.0 + 20.0 * static_cast<double>(sparse) / static_cast<double>(samples));
}

// The media map's gather radius, as povray 3.7 estimates it (its
// documented rule, with evenly spaced photons where povray picks them at
// random): around N samples (5 % of the photons, 100 to 1000) the density
// of the gather max photons nearest each, 3 n / (4 pi r^3); their mean;
// the radius of a sphere holding gather max photons at that density;
// widened by 1 + 20 f, f the fraction of samples whose density within that
// radius lies between 5 % and 70 % of the mean.
double estimateMediaRadius(const PhotonMap& map, int gatherMax) {
    if (map.empty()) return 0;
    const size_t n = map.size();
    const size_t samples = std::clamp<size_t>(n / 20, 100, 1000);
    std::vector<PhotonNeighbour> found;
    auto density = [&](const Vec3& at, double limit) {
        map.nearest(at, limit, gatherMax, found);
        if (found.empty()) return -1.0;
        const double r =
            static_cast<int>(found.size()) == gatherMax ? std::sqrt(found.back().distance2) : limit;
        if (!(r > 0)) return -1.0;
        return 3.0 * static_cast<double>(found.size()) / (4.0 * kPi * r * r * r);
    };
    double sum = 0;
    for (size_t i = 0; i < samples; ++i) {
        const double d = density(map.photons()[i * n / samples].at(), 1e7);
        sum += d >= 0 ? d : (i > 0 ? sum / static_cast<double>(i) : 0.0);
    }
    const double mean = sum / static_cast<double>(samples);
    if (!(mean > 0)) return 0;
    double radius = std::pow(3.0 * gatherMax / (mean * kPi * 4.0), 0.3333);
    size_t sparse = 0;
    for (size_t i = 0; i < samples; ++i) {
        // A second set of samples, offset from the first.
        const double d = density(map.photons()[(i * n + n / 2) / samples % n].at(), radius);
        if (d >= 0 && d < 0.7 * mean && d > 0.05 * mean) ++sparse;
    }
    radius *= 1.0 + 20.0 * static_cast<double>(sparse) / static_cast<double>(samples);
    return radius;
}

}  // namespace

Photons::Photons(PhotonMap map, PhotonMap media, const scene::PhotonSettings& settings,
                 PhotonStats stats)
    : surface_(std::move(map)),
      media_(std::move(media)),
      gatherMin_(settings.gatherMin),
      gatherMax_(std::max(1, settings.gatherMax)),
      expandIncrease_(settings.expandIncrease),
      expandMin_(settings.expandMin),
      stats_(stats) {
    radius_ = settings.radius > 0 ? settings.radius * settings.radiusMultiplier
                                  : estimateRadius(surface_, gatherMax_);
    if (!media_.empty()) {
        // povray doubles the media radius, whether given or estimated.
        mediaRadius_ = 2.0 * settings.mediaRadiusMultiplier *
                       (settings.mediaRadius > 0 ? settings.mediaRadius
                                                 : estimateMediaRadius(media_, gatherMax_));
    }
    stats_.gatherRadius = radius_;
    stats_.mediaGatherRadius = mediaRadius_;
    stats_.stored = surface_.size();
    stats_.mediaStored = media_.size();
    stats_.memoryBytes = surface_.memoryBytes() + media_.memoryBytes();
}

std::unique_ptr<const Photons> Photons::build(const World& world) {
    const scene::Scene& scene = world.scene();
    if (!scene.globals.photons) return nullptr;
    const scene::PhotonSettings& settings = *scene.globals.photons;
    if (settings.loaded) {
        PhotonMaps maps = decodePhotonFile(*settings.loaded, settings.loadFile);
        PhotonStats stats;
        stats.loaded = true;
        return std::make_unique<const Photons>(std::move(maps.surface), std::move(maps.media),
                                               settings, stats);
    }
    std::vector<Target> targets;
    for (const scene::ObjectRef& obj : scene.objects) findTargets(*obj, targets);
    PhotonStats stats;
    const std::vector<Emitter> sources = emitters(scene.lights);
    double spacing = settings.spacing > 0 ? settings.spacing : 1.0;
    if (settings.count > 0) spacing = spacingForCount(scene, settings.count);
    stats.spacing = spacing;
    const Shooter shooter{
        world, settings,
        settings.maxTraceLevel > 0 ? settings.maxTraceLevel : scene.globals.maxTraceLevel,
        settings.adcBailout >= 0 ? settings.adcBailout : scene.globals.adcBailout};
    std::vector<Photon> photons, media;
    for (const Emitter& e : sources)
        for (size_t ti = 0; ti < targets.size(); ++ti) {
            if (!shootsAt(e.light, targets[ti])) continue;
            const std::uint64_t seed = splitmix64((e.index << 16) + ti);
            if (const auto beam = aim(e.light, targets[ti], spacing * e.spacingScale, seed))
                shooter.shoot(*beam, photons, media, stats.shot);
        }
    auto built = std::make_unique<const Photons>(PhotonMap(std::move(photons)),
                                                 PhotonMap(std::move(media)), settings, stats);
    if (!settings.saveFile.empty())
        writePhotonFile(settings.saveFile, built->surfaceMap(), built->mediaMap());
    return built;
}

RGB Photons::irradiance(const Vec3& p, const Vec3& n, double brilliance, bool bothSides,
                        std::vector<PhotonNeighbour>& scratch) const {
    if (surface_.empty() || radius_ <= 0) return RGB(0.0);
    const double radius = adaptiveGather(surface_, p, &n, radius_, gatherMin_, gatherMax_,
                                         expandIncrease_, expandMin_, scratch);
    if (scratch.empty() || !(radius > 0)) return RGB(0.0);
    RGB sum(0.0);
    for (const PhotonNeighbour& f : scratch) {
        // The cosine towards where the photon came from (its stored,
        // coarse direction): a photon lights the side it arrived on only,
        // both sides of a double_illuminate surface.
        const double c = -dot(f.photon->travel(), n);
        if (!bothSides && c < kPhotonFacing) continue;
        // povray divides the photon's light by that cosine (at least 0.1)
        // and diffuses it with the cosine to the brilliance: a grazing
        // photon gives less, and brilliance counts (facts from povray's
        // source, render/trace.cpp).
        const double a = std::fabs(c);
        const double shaded = brilliance == 1.0 ? a : std::pow(a, brilliance);
        sum += f.photon->light() * (shaded / std::clamp(c, 0.1, 1.0));
    }
    return sum * (1.0 / (kPi * radius * radius));
}

// The media photons, gathered as surface photons are (adaptiveGather).
double Photons::mediaPhotons(const Vec3& p, std::vector<PhotonNeighbour>& found) const {
    found.clear();
    if (media_.empty() || !(mediaRadius_ > 0)) return 0;
    return adaptiveGather(media_, p, nullptr, mediaRadius_, gatherMin_, gatherMax_, expandIncrease_,
                          expandMin_, found);
}

}  // namespace frameray::render
