#include "render/tracer.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <optional>

#include "render/lighting.h"
#include "render/optics.h"
#include "render/photons.h"
#include "render/texture_blend.h"
#include "scene/hit_tolerance.h"
#include "util/sample_random.h"

namespace frameray::render {

namespace {

const scene::Texture& defaultTexture() {
    static const scene::Texture kDefault;  // immutable: black pigment, default finish
    return kDefault;
}

// Distance below which a secondary ray leaving the surface point p (found
// along `ray`) ignores crossings: povray's minimum depth of a hit
// (scene/hit_tolerance.h), so a second surface closer than that to the
// first is not seen, as in povray. p = origin + t * direction is computed in
// double, so its error is a few ulps of the largest magnitude involved: of
// p itself and of the ray's origin (a camera far from a surface near the
// world origin gives |p| ~ 0 but an error ~ ulp(|origin|)); 1e-9 of that
// magnitude (~10^7 ulps) stays the floor for scenes far from the origin.
// Secondary rays have unit directions, so t is a distance.
double selfHitEpsilon(const Vec3& p, const scene::Ray& ray) {
    const double m = scene::coordinateMagnitude(p, ray.origin);
    // The last floor only keeps the epsilon positive (a scene at the origin).
    return std::max({m * 1e-9, scene::scaledTolerance(scene::kMinHitDepth, m), 1e-300});
}

// The mirror direction of the view ray about the perturbed normal n. A
// perturbed normal can send it under the surface; povray then mirrors the
// view ray about the geometric normal if the ray is behind the perturbed
// one too, else mirrors the ray back above the surface (measured:
// textures.inc Brushed_Aluminum).
Vec3 mirrorDirection(const Vec3& viewDir, const Vec3& n, const Vec3& geometric) {
    Vec3 reflected = viewDir - n * (2 * dot(viewDir, n));
    if (const double under = dot(reflected, geometric); under < 0) {
        if (dot(reflected, n) < 0)
            reflected = viewDir - geometric * (2 * dot(viewDir, geometric));
        else
            reflected = reflected - geometric * (2 * under);
    }
    return reflected;
}

// Whether two layers' normals are the same (povray's test, 1e-10 per
// component).
bool sameNormal(const Vec3& a, const Vec3& b) {
    return std::fabs(a.x - b.x) <= 1e-10 && std::fabs(a.y - b.y) <= 1e-10 &&
           std::fabs(a.z - b.z) <= 1e-10;
}

// What a reflection of `reflectivity` leaves of the light, per channel.
RGB unreflected(const RGB& reflectivity) {
    return RGB(std::max(0.0, 1.0 - reflectivity.r), std::max(0.0, 1.0 - reflectivity.g),
               std::max(0.0, 1.0 - reflectivity.b));
}

}  // namespace

// The region a primitive's surface bounds: its interior, shared with the
// other primitives of a CSG that inherited it, else its CSG tree's region,
// or the primitive itself.
InteriorStack::Region InteriorStack::of(const scene::Object& primitive) {
    if (primitive.interior)
        return {primitive.interior.get(), primitive.interior.get(), primitive.hollow};
    return {primitive.regionKey ? primitive.regionKey : &primitive, nullptr, primitive.hollow};
}

bool InteriorStack::contains(const void* key) const {
    for (int i = 0; i < size_; ++i)
        if (regions_[i].key == key) return true;
    return false;
}

double InteriorStack::ior(SpectralBand band) const {
    const Region* r = innermost();
    return r && r->interior ? dispersedIor(*r->interior, band) : 1.0;
}

bool InteriorStack::allHollow() const {
    for (int i = 0; i < size_; ++i)
        if (!regions_[i].hollow) return false;
    return true;
}

bool InteriorStack::disperses() const {
    const Region* r = innermost();
    return r && r->interior && r->interior->dispersion != 1.0;
}

void InteriorStack::push(const Region& r) {
    if (size_ < kCapacity) regions_[size_++] = r;
}

void InteriorStack::remove(const void* key) {
    for (int i = size_ - 1; i >= 0; --i) {
        if (regions_[i].key != key) continue;
        std::copy(regions_.begin() + i + 1, regions_.begin() + size_, regions_.begin() + i);
        --size_;
        return;
    }
}

Tracer::Tracer(const World& world, int quality, const Radiosity* radiosity)
    : world_(world),
      scene_(world.scene()),
      atmosphere_(world.scene(), quality >= 9),
      lighting_(LightingQuality::forQuality(quality)),
      radiosityLighting_{lighting_.shadows, false},
      secondaryRays_(quality >= 8),
      media_(quality >= 9),
      subsurface_(quality >= 9 && world.scene().globals.subsurface.has_value()),
      radiosity_(radiosity),
      quickColours_(quality < 2),
      quickColorPigments_(quality < 6),
      opaqueSky_(world.scene().renderVersion() >= 3.7 - 1e-9),
      legacyFilterOpacity_(world.scene().renderVersion() < 3.7 - 1e-9) {
    // povray starts camera rays inside every object that contains the
    // camera: a camera inside glass sees out through its ior. It lists them
    // in reverse declaration order, so the innermost (last listed) is the
    // first declared: measured with a camera inside two planes of ior 1.2
    // and 1.5, whose fresnel reflection depends on which one is current.
    for (auto it = scene_.objects.rbegin(); it != scene_.objects.rend(); ++it)
        addCameraRegions(**it);
}

// A union or merge without an interior of its own holds the camera where
// one of its children does: a camera inside a hollow sphere of media
// wrapped in a union starts in its media (measured: advanced/abyss.pov's
// camera inside `union { sphere { .. hollow interior { media .. } } }`).
void Tracer::addCameraRegions(const scene::Object& obj) {
    if (!obj.interior && obj.isCsg()) {
        // Other CSG without interiors: primitives without interiors are air.
        if (obj.op != scene::CsgOp::Union && obj.op != scene::CsgOp::Merge) return;
        if (obj.inverse || !obj.clippedBy.empty()) return;
        for (auto it = obj.children.rbegin(); it != obj.children.rend(); ++it)
            addCameraRegions(**it);
        return;
    }
    if (obj.inside(scene_.camera.location)) cameraInside_.push(InteriorStack::of(obj));
}

RGB Tracer::traceCamera(const scene::Ray& ray, RayCounts& counts, double* transmit,
                        RadiosityTask* radiosity) const {
    ++counts.camera;
    State state;
    state.inside = cameraInside_;
    state.transmit = transmit;
    state.radiosity.task = radiosity;
    state.radiosity.origin = scene_.camera.location;
    // povray's minimum hit depth applies to camera rays too: a surface
    // closer than that to the camera is not seen.
    const double m = scene::coordinateMagnitude(ray.origin, ray.origin);
    return trace(ray, scene::scaledTolerance(scene::kMinHitDepth, m) / length(ray.direction), state,
                 counts);
}

RGB Tracer::trace(const scene::Ray& ray, double tMin, const State& state, RayCounts& counts) const {
    Hit hit;
    const InteriorStack::Region* medium = state.inside.innermost();
    const bool fades = medium && medium->interior && medium->interior->fades();
    const bool found = world_.intersect(ray, tMin, scene::kInfinity, hit, state.kind);
    if (state.hitDistance)
        *state.hitDistance = found ? hit.t * length(ray.direction) : scene::kInfinity;
    if (!found) {
        if (state.transmit) {
            // Alpha output, seen straight or through surfaces: a 3.7
            // scene's sky (sky sphere over background, whose default is
            // clear) adds its opaque part and lets the rest through;
            // before 3.7, and without #version, povray makes the
            // background transparent black whatever it is (measured).
            // Fog then covers it as any colour, its transmittance passing
            // on what the sky lets through.
            const Color sky =
                opaqueSky_ ? atmosphere_.sky(normalize(ray.direction)) : Color(RGB(0.0), 0.0, 1.0);
            const Color seen = state.inside.allHollow()
                                   ? atmosphere_.along(ray, kMissDepth / length(ray.direction), sky)
                                   : sky;
            *state.transmit = seen.transmit;
            return throughMedia(ray, 0.0, true, state, seen.rgb, counts);
        }
        // No fog for a ray that leaves the scene inside an object that is
        // not hollow (measured: the sky seen from inside an inverse plane),
        // nor for a radiosity ray (below).
        RGB sky = state.inside.allHollow() && state.kind != scene::RayKind::Radiosity
                      ? atmosphere_.miss(ray).rgb
                      : atmosphere_.sky(normalize(ray.direction)).rgb;
        if (fades) sky = sky * interiorFade(*medium->interior, scene::kInfinity);
        return throughMedia(ray, 0.0, true, state, sky, counts);
    }
    if (quickColours_) {
        const scene::Object& obj = *hit.object;
        const Vec3 p = ray.at(hit.t);
        const scene::Texture& tex = obj.texture ? *obj.texture : defaultTexture();
        return quickColour(tex, p, tex.usesUv() ? obj.surfaceUv(p) : p);
    }
    RGB color;
    // The fade is that of the hit object's own interior, and only when the
    // ray is inside it: a surface of another object met inside a fading
    // glass (a cavity cut by an object with no interior of its own, which
    // gets a plain one) does not fade what it lets through (fact from
    // povray 3.7's backend/render/trace.cpp and parser/parse.cpp;
    // advanced/glasschess's carved pieces).
    const InteriorStack::Region own = InteriorStack::of(*hit.object);
    if (own.interior && own.interior->fades() && state.inside.contains(own.key)) {
        State faded = state;
        faded.fade = interiorFade(*own.interior, hit.t * length(ray.direction));
        color = shade(ray, hit, faded, counts);
    } else {
        color = shade(ray, hit, state, counts);
    }
    color = throughMedia(ray, hit.t, false, state, color, counts);
    // povray leaves out fog and rainbows along rays inside objects that
    // are not hollow (measured: a transmitting box 4 units deep in fog
    // shows the fog only in front of it and beyond it; inside a hollow
    // sky sphere the fog stays).
    if (!state.inside.allHollow()) return color;
    // povray 3.7's radiosity rays see no fog and no rainbow (measured: a
    // white plane under a grey sky in a red fog, constant or ground,
    // gathers the grey unfogged, camera rays fogged alike; a red rainbow
    // over the directions the plane gathers from leaves it grey).
    if (state.kind == scene::RayKind::Radiosity) return color;
    if (state.transmit) {
        const Color seen = atmosphere_.along(ray, hit.t, Color(color, 0.0, *state.transmit));
        *state.transmit = seen.transmit;
        return seen.rgb;
    }
    return atmosphere_.along(ray, hit.t, Color(color)).rgb;
}

RGB Tracer::throughMedia(const scene::Ray& ray, double t, bool missed, const State& state,
                         const RGB& color, RayCounts& counts) const {
    // Inside an object that is not hollow no media is sampled at all, not
    // even that of the hollow containers around it (measured: a solid glass
    // sphere inside a sphere of emitting media hides the media behind it).
    if (!media_ || !state.inside.allHollow()) return color;
    // Radiosity rays (and the rays continuing them) see no media unless the
    // radiosity block says `media on` (measured: a shell of emitting media
    // around a radiosity room, as camera/mesh_camera's demos use to give
    // reflections something to show, leaves povray's indirect light
    // unchanged).
    if (state.radiosity.ray && !radiosity_->settings().media) return color;
    MediaSet set;
    // The region the ray entered first comes first: its media's sampling
    // settings are used (measured with povray 3.7: two overlapping boxes
    // of media with samples 2 and 4 sample their common stretch as the
    // box the ray entered first says, whichever was declared first).
    // A ray that hits nothing sees no interior media, only the scene's
    // (measured: a camera inside a hollow half-space of media looking away
    // from its plane sees the background untouched; two media boxes
    // leaving the ray at one coincident face no longer show media to
    // infinity).
    // The samples' shadow rays start in the same containers (povray copies
    // the ray's interiors; World::shadowFilter).
    std::array<const scene::Interior*, InteriorStack::kCapacity> inside{};
    size_t insideCount = 0;
    for (int i = 0; i < state.inside.size() && !missed; ++i) {
        const InteriorStack::Region& r = state.inside[i];
        if (!r.interior) continue;
        set.add(r.interior->media);
        if (!r.interior->media.empty()) inside[insideCount++] = r.interior;
    }
    set.add(scene_.atmosphere.media);
    if (set.empty()) return color;
    const double speed = length(ray.direction);
    const scene::Ray unit{ray.origin, ray.direction * (1.0 / speed)};
    const double depth = missed ? kMissDepth : t * speed;
    const MediaResult m = integrateMedia(
        world_, lighting_, unit, depth, set, true, counts.mediaSamples, counts.shadow,
        std::span<const scene::Interior* const>(inside.data(), insideCount));
    if (state.transmit) {
        const RGB& k = m.transmittance;
        *state.transmit *= grey(k);
    }
    return color * m.transmittance + m.light;
}

// +Q0/+Q1 (povray 3.7, measured): every surface in the colour of its
// bottom texture layer's pigment, or that pigment's quick_color, with no
// lighting, shadows, transparency or reflection; a patterned texture
// (texture_map, checker of textures, tiles) shows its entries' colours.
RGB Tracer::quickColour(const scene::Texture& top, const Vec3& p, const Vec3& uv) const {
    const scene::Texture& bottom = top.layersBelow.empty() ? top : *top.layersBelow.back();
    const Vec3 at = bottom.uvMapping ? uv : p;
    if (bottom.map)
        return blendTextureMap(
            bottom, at, uv, [this](const scene::Texture& t, const Vec3& entry, const Vec3& uvAt) {
                return quickColour(t, entry, uvAt);
            });
    if (!bottom.pigment) return RGB(0.0);
    const scene::Pigment& pigment = *bottom.pigment;
    if (pigment.quickColor()) return pigment.quickColor()->rgb;
    scene::SurfaceInfo surface{};
    surface.uv = uv;
    return pigment.at(bottom.transform.inversePoint(at), &surface).rgb;
}

Tracer::Grain::Grain(const Vec3& p) : random(p.x, p.y, std::bit_cast<uint64_t>(p.z)) {}

// Ambient, emission, diffuse and highlights of one texture layer whose
// pigment at the point is `surface`, shaded with the normal n.
RGB Tracer::localLight(const scene::Texture& tex, const Color& surface, const scene::Object& obj,
                       const Vec3& p, const Vec3& n, const Vec3& viewDir, double eps,
                       const RGB& fade, RayCounts& counts, const RGB* gathered, bool radiosityRay,
                       std::optional<Grain>* grain) const {
    const scene::Finish& fin = *tex.finish;
    const RGB& pigment = surface.rgb;
    // What the surface lets through: filter tints by the pigment, transmit
    // passes unchanged. Ambient, emission and diffuse light are scaled by
    // the opaque rest; highlights and reflection are not (measured).
    // The rest is not clamped: filter + transmit above 1 (image maps with
    // alpha and transmit all) takes light away, as in povray.
    // Before 3.7 filter takes only its share of the pigment's brightest
    // channel away (measured with #version 3.6: rgbf <0.5, 0.5, 0.5, 1>
    // shows 0.25 of its own colour over what it filters).
    const double filterShare =
        legacyFilterOpacity_ ? surface.filter * pigment.maxComponent() : surface.filter;
    const double opacity = 1.0 - filterShare - surface.transmit;
    const RGB lit = pigment * opacity;

    // Under radiosity the gathered light takes the place of ambient light,
    // reflected as diffuse light; povray 3.7 ignores `ambient` then, older
    // scenes keep it as a glow (measured).
    RGB color = radiosity_ ? fin.emission * lit
                           : (fin.ambient * scene_.globals.ambientLight + fin.emission) * lit;
    if (radiosity_ && radiosity_->legacyAmbient())
        color += fin.ambient * scene_.globals.ambientLight * lit;
    if (gathered) color += *gathered * lit * fin.diffuse;

    const Vec3 reflected = viewDir - n * (2 * dot(viewDir, n));
    // crand: povray darkens each light's diffuse term by crand times a
    // fresh random number in [0, 1) (measured: uniform, independent per
    // light, scaled by the light and the pigment, not clamped), and every
    // texture layer below by the same colour again: the darkening adds up
    // from layer to layer, each share in the colour of the layer that
    // made it (measured: a white crand layer over a crand layer darkens
    // the lower one by both, the upper one's share unscaled by the lower
    // one's pigment, with the upper one's number). povray's
    // numbers change from render to render; these come from the point, so
    // frames stay deterministic.
    std::optional<Grain> ownGrain;
    if (!grain) grain = &ownGrain;
    if (fin.crand != 0 && !*grain) grain->emplace(p);
    size_t lightIndex = 0;
    const bool irid = fin.irid.amount != 0;
    const double filmThickness = irid ? iridFilmThickness(fin.irid, p) : 0.0;
    // A subsurface finish takes no diffuse light from the lights (nor
    // photons): the light carried under its surface replaces it
    // (tracer_subsurface.cpp). Radiosity rays see neither (povray 3.7
    // computes no subsurface light for them).
    const bool underSurface = subsurface_ && fin.subsurface;
    const double lightDiffuse = underSurface ? 0.0 : fin.diffuse;
    if (const Photons* photons = world_.photons(); photons && lightDiffuse > 0) {
        // Caustics: the photons' light, diffused as povray does
        // (render/photons.h).
        thread_local std::vector<PhotonNeighbour> scratch;
        color += photons->irradiance(p, n, fin.brilliance, obj.doubleIlluminate, scratch) * lit *
                 (fin.diffuse) * fade;
    }
    for (const scene::Light& light : LightsFor(scene_.lights, obj)) {
        const size_t index = lightIndex++;
        LightPath path;
        if (!pathToLight(light, p, path)) continue;
        const Vec3 toLight = path.toLight;
        // A light behind the surface reaches double_illuminate objects,
        // whose far side is lit as if it faced the light, and surfaces
        // with a back-side diffuse value (`diffuse A, B`), which take B of
        // it with no highlights (measured: double_illuminate wins when
        // both are given).
        Vec3 ln = n;
        double cosIncidence = dot(n, toLight);
        double diffuse = lightDiffuse;
        bool fromBehind = false;
        if (cosIncidence <= 0 && obj.doubleIlluminate) {
            ln = -n;
            cosIncidence = -cosIncidence;
        } else if (cosIncidence < 0 && fin.diffuseBack > 0) {
            cosIncidence = -cosIncidence;
            diffuse = underSurface ? 0.0 : fin.diffuseBack;
            fromBehind = true;
        }
        if (cosIncidence <= 0) continue;
        RGB lightColor =
            lightArriving(world_, light, p, path, eps,
                          radiosityRay ? radiosityLighting_ : lighting_, counts.shadow);
        if (lightColor.isBlack()) continue;
        if (irid)
            lightColor =
                lightColor * iridTint(fin.irid.amount, filmThickness, scene_.globals.iridWavelength,
                                      -dot(viewDir, n), cosIncidence);
        if (diffuse > 0) {
            double intensity =
                diffuse *
                (fin.brilliance == 1.0 ? cosIncidence : std::pow(cosIncidence, fin.brilliance));
            RGB diffuseColor = lit * intensity;
            if (*grain) {
                std::vector<RGB>& sums = (*grain)->sums;
                if (sums.size() <= index) sums.resize(index + 1, RGB(0.0));
                if (fin.crand != 0) sums[index] += pigment * (fin.crand * (*grain)->random.next());
                diffuseColor -= sums[index] * opacity;
            }
            color += lightColor * diffuseColor;
        }
        if (fromBehind) continue;
        // povray 3.7: shadowless lights give no highlights.
        if ((fin.phong > 0 || fin.specular > 0) && !light.shadowless && !radiosityRay) {
            // Metallic highlights take the pigment's colour, except where
            // the light grazes the surface.
            const RGB tint = metallicTint(fin.metallic, cosIncidence, pigment);
            if (fin.phong > 0) {
                const double c = dot(reflected, toLight);
                if (c > 0) color += lightColor * tint * (fin.phong * std::pow(c, fin.phongSize));
            }
            if (fin.specular > 0) {
                const Vec3 halfway = normalize(toLight - viewDir);
                const double c = dot(halfway, ln);
                if (c > 0)
                    color += lightColor * tint * (fin.specular * std::pow(c, 1.0 / fin.roughness));
            }
        }
    }
    return color;
}

RGB Tracer::shade(const scene::Ray& ray, const Hit& hit, const State& state,
                  RayCounts& counts) const {
    const scene::Object& obj = *hit.object;
    const Vec3 p = ray.at(hit.t);
    const Vec3 viewDir = normalize(ray.direction);
    // The hit primitive (for CSG, the child whose surface was crossed)
    // carries its complete transform and inherited texture.
    // uv_mapping's point, found only when a texture may ask for it, with
    // the normal (a mesh then searches the point's triangle once).
    const scene::Texture& outer = obj.texture ? *obj.texture : defaultTexture();
    const bool mayUseUv = !obj.componentTextures.empty() || outer.usesUv() ||
                          (obj.interiorTexture && obj.interiorTexture->usesUv());
    Vec3 surfaceUv;
    Vec3 geometric = mayUseUv ? obj.normalAndUvAt(p, surfaceUv) : obj.normalAt(p);
    // Shade the side facing the viewer; the inner side takes the
    // interior_texture when there is one.
    const bool innerSide = dot(geometric, viewDir) > 0;
    if (innerSide) geometric = -geometric;
    const scene::Texture& own = innerSide && obj.interiorTexture ? *obj.interiorTexture : outer;
    const Vec3 uv = !obj.componentTextures.empty() || own.usesUv() ? surfaceUv : Vec3(p.x, p.y, 0);
    if (obj.componentTextures.empty())
        return shadeTexture(own, ray, obj, p, p, uv, viewDir, geometric, state, counts);
    // A blob's component textures: each is shaded and the colours blended
    // (as povray 3.7 does). povray skips a texture whose weight is under
    // adc_bailout without giving its share to the others (measured: weights
    // under 1/255 leave no trace, at every threshold).
    RGB color(0.0);
    double transmitSum = 0, partTransmit = 0;
    State part = state;
    if (state.transmit) part.transmit = &partTransmit;
    obj.visitTextures(p, own, [&](const scene::Texture& t, double w) {
        if (w * state.weight < scene_.globals.adcBailout) return;
        color += shadeTexture(t, ray, obj, p, p, uv, viewDir, geometric, part, counts) * w;
        transmitSum += partTransmit * w;
    });
    if (state.transmit) *state.transmit = transmitSum;
    return color;
}

RGB Tracer::shadeTexture(const scene::Texture& top, const scene::Ray& ray, const scene::Object& obj,
                         const Vec3& p, const Vec3& texP, const Vec3& uv, const Vec3& viewDir,
                         const Vec3& geometric, const State& state, RayCounts& counts,
                         const Vec3* patternNormal, Vec3* perturbed) const {
    const SurfacePoint at{
        ray, obj, p, texP, uv, viewDir, geometric, 0.0, patternNormal ? *patternNormal : geometric};
    if (top.map) return shadeTextureMap(top, at, state, counts, perturbed);
    if (state.transmit) *state.transmit = 0.0;
    SurfacePoint here = at;
    here.eps = selfHitEpsilon(p, ray);
    const bool spawns = secondaryRays_ && state.level < scene_.globals.maxTraceLevel;
    std::optional<Crossing> crossing;
    const Layers layers = shadeLayers(top, here, spawns, state, crossing, counts);
    if (perturbed && layers.perturbed) *perturbed = layers.n;
    if (!spawns || !layers.transmits) return layers.color;
    const double throughWeight = std::max(
        {std::abs(layers.through.r), std::abs(layers.through.g), std::abs(layers.through.b)});
    if (state.weight * throughWeight < scene_.globals.adcBailout) return layers.color;
    if (!crossing) crossing = crossingOf(obj, state);
    return continueThrough(layers, throughWeight, here, *crossing, state, counts);
}

// A patterned texture: povray 3.7 shades each texture the pattern picks
// (with its own reflection and transmission) and blends the shaded colours
// by their weights (measured). It shades them last entry first, and the
// pattern of a texture map inside an entry sees, as the normal, the one
// the entries shaded before it perturbed (measured: a slope map of a bumpy
// and a plain texture, used twice in a gradient map, picks by the bumped
// normal for the lower entry; textures/patterns/slopemt_37.pov matches
// exactly this way); lighting keeps each entry's own normal.
RGB Tracer::shadeTextureMap(const scene::Texture& top, const SurfacePoint& at, const State& state,
                            RayCounts& counts, Vec3* perturbed) const {
    RGB color(0.0);
    const Vec3 q = top.transform.inversePoint(top.uvMapping ? at.uv : at.texP);
    const Vec3 entry = top.map->entryPoint(q);
    const scene::SurfaceInfo surface{at.patternNormal, at.viewDir, at.uv};
    Vec3 seen = at.patternNormal;
    double transmitSum = 0, entryTransmit = 0;
    State part = state;
    if (state.transmit) part.transmit = &entryTransmit;
    // The entries picked, shaded last first (a map picks one or two; an
    // average list may pick more).
    using Picked = std::pair<const scene::Texture*, double>;
    std::array<Picked, 4> few{};
    size_t count = 0;
    std::vector<Picked> many;
    top.map->visit(
        q,
        [&](const scene::Texture& t, double w) {
            if (count < few.size())
                few[count] = {&t, w};
            else {
                if (many.empty()) many.assign(few.begin(), few.end());
                many.emplace_back(&t, w);
            }
            ++count;
        },
        &surface);
    const Picked* picked = many.empty() ? few.data() : many.data();
    for (size_t i = count; i-- > 0;) {
        const Vec3 before = seen;
        color += shadeTexture(*picked[i].first, at.ray, at.obj, at.p, entry, at.uv, at.viewDir,
                              at.geometric, part, counts, &before, &seen) *
                 picked[i].second;
        transmitSum += entryTransmit * picked[i].second;
    }
    if (state.transmit) *state.transmit = transmitSum;
    if (perturbed) *perturbed = seen;
    return color;
}

Tracer::Crossing Tracer::crossingOf(const scene::Object& obj, const State& state) const {
    const InteriorStack::Region region = InteriorStack::of(obj);
    const bool leaving = state.inside.contains(region.key);
    Crossing c{state.inside, state.inside.ior(state.band), 1.0, 1.0};
    if (leaving)
        c.beyond.remove(region.key);
    else
        c.beyond.push(region);
    const double own = region.interior ? dispersedIor(*region.interior, state.band) : 1.0;
    c.iorBeyond = leaving ? c.beyond.ior(state.band) : own;
    c.fresnelRatio = leaving && state.inside.size() > 1 ? c.iorHere / own : c.iorBeyond / c.iorHere;
    return c;
}

// A mirrored ray's colour as an iridescent finish tints it: the film seen
// along the view ray and along the mirrored one (fact from povray 3.7's
// backend/render/trace.cpp: the reflected and the totally reflected rays are
// tinted, the photons' not).
RGB Tracer::iridReflection(const scene::Finish& fin, const SurfacePoint& at, const Vec3& n,
                           const Vec3& reflected, const State& state, const RGB& color) const {
    if (fin.irid.amount == 0 || state.kind == scene::RayKind::Photon) return color;
    return color * iridTint(fin.irid.amount, iridFilmThickness(fin.irid, at.p),
                            scene_.globals.iridWavelength, std::fabs(dot(at.viewDir, n)),
                            std::fabs(dot(reflected, n)));
}

RGB Tracer::spawnReflection(const SurfacePoint& at, const Vec3& reflected, const RGB& weightColor,
                            const State& state, RayCounts& counts) const {
    State child;
    child.level = state.level + 1;
    child.weight = state.weight * weightColor.maxComponent();
    child.kind = scene::RayKind::Reflection;
    child.inside = state.inside;
    child.band = state.band;
    child.radiosity = state.radiosity;
    if (child.weight < scene_.globals.adcBailout) return RGB(0.0);
    ++counts.reflection;
    return trace({at.p, reflected}, at.eps, child, counts);
}

// Layered textures (seed 003 5.4.5): each layer is shaded on its own; its
// ambient, diffuse and highlights are tinted by the filter and transmit of
// the layers above it, its reflection is added in full, and a fully opaque
// layer hides the ones below (all measured with povray 3.7). Whatever all
// layers let through continues the ray (continueThrough).
Tracer::Layers Tracer::shadeLayers(const scene::Texture& top, const SurfacePoint& at, bool spawns,
                                   const State& state, std::optional<Crossing>& crossing,
                                   RayCounts& counts) const {
    Layers out;
    out.n = at.geometric;
    RGB pigment(0.0);
    std::optional<RGB> radiosityHere;
    std::optional<Grain> grain;  // crand's darkening, carried down the layers
    const size_t layerCount = 1 + top.layersBelow.size();
    for (size_t i = 0; i < layerCount; ++i) {
        const scene::Texture& tex = i == 0 ? top : *top.layersBelow[i - 1];
        const scene::Finish& fin = *tex.finish;
        // A uv-mapped layer is evaluated at the surface's uv.
        const Vec3& layerP = tex.uvMapping ? at.uv : at.texP;
        const scene::SurfaceInfo unperturbed{at.geometric, at.viewDir, at.uv};
        const Vec3 n = tex.perturbNormal(layerP, at.geometric, at.uv, &unperturbed);
        out.n = n;
        if (i == 0) {
            out.topN = n;
            out.topFinish = &fin;
        }
        out.perturbed = out.perturbed || tex.normal;
        // slope and aoi see the perturbed normal facing the viewer and the
        // ray (measured: aoi follows a bumps normal).
        const scene::SurfaceInfo info{n, at.viewDir, at.uv};
        // Below +Q6 povray computes no pattern that has a quick_color: the
        // surface takes that colour, shaded as usual (measured; patterns
        // without one are still computed).
        const std::optional<Color>& quick = tex.pigment->quickColor();
        const Color surface = quickColorPigments_ && quick
                                  ? *quick
                                  : tex.pigment->at(tex.transform.inversePoint(layerP), &info);
        pigment = surface.rgb;
        // The radiosity light, gathered once for the point (with the
        // unperturbed normal: radiosity's `normal` is off) for the layers
        // that reflect diffuse light.
        const RGB* gathered = nullptr;
        if (radiosity_ && fin.diffuse > 0) {
            if (!radiosityHere)
                radiosityHere = radiosityLight(
                    at.p, radiosity_->settings().normal ? n : at.geometric, at.obj, at.eps,
                    state.weight *
                        (0.297 * surface.rgb.r + 0.589 * surface.rgb.g + 0.114 * surface.rgb.b) *
                        fin.diffuse,
                    state, counts);
            gathered = &*radiosityHere;
        }
        RGB local = localLight(tex, surface, at.obj, at.p, n, at.viewDir, at.eps, state.fade,
                               counts, gathered, state.radiosity.ray, &grain);
        if (subsurfaceActive(fin, state))
            local += subsurfaceLight(fin, surface.rgb, at, state, counts);
        out.color += i == 0 ? local : out.through * local;

        if (spawns && fin.reflection.any()) {
            const double cosView = std::clamp(-dot(at.viewDir, n), 0.0, 1.0);
            if (!crossing) crossing = crossingOf(at.obj, state);
            out.reflectivity =
                reflectance(fin.reflection, cosView, crossing->fresnelRatio, pigment);
            out.reflectedSum += out.reflectivity;
            // The reflection is not faded by the interior the ray came
            // through: povray fades only what crosses (or is totally
            // reflected at) the surface that ends the faded stretch (fact
            // from povray 3.7's backend/render/trace.cpp).
            if (!out.reflectivity.isBlack()) {
                const Vec3 reflected = mirrorDirection(at.viewDir, n, at.geometric);
                const RGB seen =
                    iridReflection(fin, at, n, reflected, state,
                                   spawnReflection(at, reflected, out.reflectivity, state, counts));
                const RGB shown =
                    out.reflectivity * reflectionExponent(seen, fin.reflection.exponent);
                out.color += shown;
                if (sameNormal(n, out.topN)) out.topReflection += shown;
            }
        } else {
            out.reflectivity = RGB(0.0);
        }

        // Negative filter or transmit subtract what lies behind (measured:
        // rgb 0.5 transmit -1 over a background B shows 1 - B), so the
        // ray continues whenever either is non-zero.
        out.transmits = surface.filter != 0 || surface.transmit != 0;
        if (!out.transmits) break;
        out.through = out.through * (pigment * surface.filter + RGB(surface.transmit));
        out.throughGrey *= surface.filter * grey(pigment) + surface.transmit;
        if (fin.conserveEnergy) out.through = out.through * (RGB(1.0) - out.reflectivity);
        if (out.through.isBlack() && i + 1 < layerCount) {
            out.transmits = false;
            break;
        }
    }
    return out;
}

// The ray that goes on through the surface's layers: straight on, bent,
// split into bands by a dispersive interior, or mirrored back inside.
RGB Tracer::continueThrough(const Layers& layers, double throughWeight, const SurfacePoint& at,
                            const Crossing& c, const State& state, RayCounts& counts) const {
    RGB color = layers.color;
    const RGB& through = layers.through;
    const Vec3& n = layers.n;
    State child;
    child.weight = state.weight * throughWeight;
    child.kind = state.kind;
    child.inside = c.beyond;
    child.band = state.band;
    child.radiosity = state.radiosity;
    double childTransmit = 0;
    if (state.transmit) child.transmit = &childTransmit;
    // What the continued ray reports, through this surface's layers.
    auto passTransmit = [&](double seen) {
        if (state.transmit) *state.transmit = layers.throughGrey * seen;
    };
    if (state.band.white() && c.iorHere != c.iorBeyond &&
        (state.inside.disperses() || c.beyond.disperses())) {
        child.level = state.level + 1;
        double seen = 0;
        const RGB sum = traceDispersed(layers, at, c, state, child, seen, counts);
        passTransmit(seen);
        return color + through * sum;
    }
    if (c.iorHere == c.iorBeyond) {
        // Straight on: povray continues the ray at the same trace level
        // (measured: max_trace_level 2 sees through any number of
        // non-refracting surfaces).
        child.level = state.level;
        ++counts.transmission;
        color += through * trace({at.p, at.viewDir}, at.eps, child, counts) * state.fade;
        passTransmit(childTransmit);
    } else if (const auto bent = refractedDirection(at.viewDir, n, c.iorHere / c.iorBeyond)) {
        child.level = state.level + 1;
        ++counts.refraction;
        color += through * trace({at.p, *bent}, at.eps, child, counts) * state.fade;
        passTransmit(childTransmit);
    } else {
        // Total internal reflection: the ray is mirrored back inside in
        // full, in place of the reflection of the layers that share the
        // top layer's normal (povray skips those then; fact from povray
        // 3.7's backend/render/trace.cpp), so the surface mirrors 100 %
        // (measured: a prism of transmit 0.5 passes 0.5 * 0.5 of the
        // light whatever its reflection value). The mirrored ray's adc
        // weight is the refracted ray's (povray's source).
        color -= layers.topReflection;
        // Mirrored as a reflection is, back above the surface when a
        // perturbed normal sends it through (measured: bumps on a water
        // surface seen from below, interior/caustic2.pov).
        const Vec3 reflected = mirrorDirection(at.viewDir, n, at.geometric);
        // Faded on the way here as the refracted ray is (measured: a
        // fading glass cone with no reflection at all; a glass block with
        // fade_distance shows its totally reflected edges as dim as its
        // face).
        color += iridReflection(*layers.topFinish, at, n, reflected, state,
                                spawnReflection(at, reflected, RGB(throughWeight), state, counts)) *
                 state.fade;
    }
    return color;
}

// A white ray bending into or out of a dispersive interior splits into the
// interior's bands, each bent by its own ior; `child` is the state the
// band rays start from, `seen` receives what they report of the
// background (alpha output).
RGB Tracer::traceDispersed(const Layers& layers, const SurfacePoint& at, const Crossing& c,
                           const State& state, State child, double& seen, RayCounts& counts) const {
    const Vec3& n = layers.n;
    const InteriorStack& dispersive = c.beyond.disperses() ? c.beyond : state.inside;
    const int bands = dispersive.innermost()->interior->dispersionSamples;
    double childTransmit = 0;
    if (state.transmit) child.transmit = &childTransmit;
    RGB sum(0.0);
    for (int k = 0; k < bands; ++k) {
        child.band = dispersionBand(k, bands);
        const double eta = state.inside.ior(child.band) / c.beyond.ior(child.band);
        const RGB weight = dispersionBandColour(k, bands);
        if (const auto bent = refractedDirection(at.viewDir, n, eta)) {
            ++counts.refraction;
            childTransmit = 0;
            sum += weight * trace({at.p, *bent}, at.eps, child, counts) * state.fade;
            seen += childTransmit / bands;
        } else {
            const RGB rest = unreflected(layers.reflectedSum);
            const Vec3 reflected = mirrorDirection(at.viewDir, n, at.geometric);
            State mirrored = child;
            mirrored.kind = scene::RayKind::Reflection;
            mirrored.inside = state.inside;
            mirrored.transmit = nullptr;
            ++counts.reflection;
            sum += weight * rest * trace({at.p, reflected}, at.eps, mirrored, counts) * state.fade;
        }
    }
    return sum;
}

}  // namespace frameray::render
