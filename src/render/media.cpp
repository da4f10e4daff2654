#include "render/media.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <vector>

#include "render/photons.h"
#include "util/hash.h"

namespace frameray::render {

namespace {

// What one sample point holds: the light it sends toward the viewer per
// unit length (emission plus in-scattered light) and its extinction.
struct Sample {
    RGB light{0.0};
    RGB extinction{0.0};

    Sample& operator+=(const Sample& o) {
        light += o.light;
        extinction += o.extinction;
        return *this;
    }
    Sample operator*(double s) const { return {light * s, extinction * s}; }
    Sample operator+(const Sample& o) const { return {light + o.light, extinction + o.extinction}; }
};

// Where the ray [0, depth] crosses the volume a spot or cylinder light
// lights (its falloff cone or cylinder): adds the crossings to `cuts`.
void lightVolumeCrossings(const scene::Light& light, const scene::Ray& ray, double depth,
                          std::vector<double>& cuts) {
    const Vec3 axis = light.axis();
    const Vec3 rel = ray.origin - light.position;
    const Vec3& d = ray.direction;
    double a, b, c;
    if (light.kind == scene::LightKind::Cylinder) {
        // |rel + t d|^2 - ((rel + t d) . axis)^2 = falloff^2
        const double r = std::max(light.falloff, light.radius);
        const double da = dot(d, axis), ra = dot(rel, axis);
        a = dot(d, d) - da * da;
        b = 2.0 * (dot(rel, d) - ra * da);
        c = dot(rel, rel) - ra * ra - r * r;
    } else {
        // ((rel + t d) . axis)^2 = cos^2 * |rel + t d|^2, forward nappe only
        const double angle = std::max(light.falloff, light.radius) * std::numbers::pi / 180.0;
        const double k = std::cos(angle);
        const double da = dot(d, axis), ra = dot(rel, axis);
        a = da * da - k * k * dot(d, d);
        b = 2.0 * (ra * da - k * k * dot(rel, d));
        c = ra * ra - k * k * dot(rel, rel);
    }
    auto keep = [&](double t) {
        if (!(t > 0 && t < depth)) return;
        if (light.kind == scene::LightKind::Spot && dot(rel + d * t, axis) < 0) return;
        cuts.push_back(t);
    };
    if (std::fabs(a) < 1e-12) {
        if (std::fabs(b) > 1e-12) keep(-c / b);
        return;
    }
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0) return;
    const double q = std::sqrt(disc);
    keep((-b - q) / (2.0 * a));
    keep((-b + q) / (2.0 * a));
}

bool insideLightVolume(const scene::Light& light, const Vec3& p) {
    const Vec3 rel = p - light.position;
    const Vec3 axis = light.axis();
    const double along = dot(rel, axis);
    if (light.kind == scene::LightKind::Cylinder) {
        const double r = std::max(light.falloff, light.radius);
        return dot(rel, rel) - along * along <= r * r;
    }
    const double len = length(rel);
    const double angle = std::max(light.falloff, light.radius) * std::numbers::pi / 180.0;
    return len > 0 && along / len >= std::cos(angle);
}

// Evaluates and subdivides the media along one ray.
class Sampler {
  public:
    Sampler(const World* world, const LightingQuality& quality, const scene::Ray& ray,
            const MediaSet& set, bool lights, uint64_t& samples, uint64_t& shadowRays)
        : world_(world),
          quality_(quality),
          ray_(ray),
          media_(set.media()),
          settings_(*media_.front()),
          lights_(lights && world && anyScatters()),
          samples_(samples),
          shadowRays_(shadowRays) {
        seed_ = fmix64(std::bit_cast<uint64_t>(ray.origin.x) ^
                       fmix64(std::bit_cast<uint64_t>(ray.origin.y + 3.0 * ray.direction.x) ^
                              fmix64(std::bit_cast<uint64_t>(ray.origin.z + 5.0 * ray.direction.y) ^
                                     std::bit_cast<uint64_t>(ray.direction.z))));
    }

    MediaResult run(double depth) const;

  private:
    bool anyScatters() const {
        for (const scene::Media* m : media_)
            if (m->scatters()) return true;
        return false;
    }
    // Whether the light and extinction are the same all along the stretch:
    // no density and no light scattered (measured with povray 3.7: constant
    // emitting and absorbing media are sampled over one interval whatever
    // `intervals` says, but scattering media over the intervals asked for:
    // advanced/abyss.pov's constant `intervals 3` Henyey-Greenstein media).
    bool constant() const {
        if (lights_) return false;
        for (const scene::Media* m : media_)
            if (!m->constant()) return false;
        return true;
    }
    Sample at(double t) const;
    RGB inScattered(const Vec3& p, const RGB* scattering) const;
    RGB photonScattered(const Vec3& p, const RGB* scattering) const;
    // `scale`: the interval's length, which the light differences are
    // multiplied by before they are compared with aa_threshold.
    Sample segment(double a, double b, const Sample& va, const Sample& vb, int level,
                   double scale) const;
    double jittered(double t, double spacing, uint64_t index) const;
    struct Piece {
        double from, to;
        int intervals;  // -1 while a lit piece waits for its share
    };
    void pieces(double depth, std::vector<Piece>& out) const;
    bool hasVolumeLights() const {
        if (!lights_) return false;
        for (const scene::Light& light : world_->scene().lights)
            if (light.mediaInteraction && !light.parallel &&
                (light.kind == scene::LightKind::Spot || light.kind == scene::LightKind::Cylinder))
                return true;
        return false;
    }

    const World* world_;
    const LightingQuality& quality_;
    const scene::Ray& ray_;
    std::span<const scene::Media* const> media_;
    const scene::Media& settings_;
    bool lights_;
    uint64_t seed_ = 0;
    uint64_t& samples_;
    uint64_t& shadowRays_;
    mutable std::vector<PhotonNeighbour> photonScratch_;
};

RGB Sampler::inScattered(const Vec3& p, const RGB* scattering) const {
    RGB sum(0.0);
    const scene::Scene& scene = world_->scene();
    // A point in open space: shadow rays start right at it.
    const double selfHit =
        std::max(1e-9 * std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}), 1e-300);
    for (const scene::Light& light : scene.lights) {
        if (!light.mediaInteraction) continue;
        LightPath path;
        if (!pathToLight(light, p, path)) continue;
        const RGB arriving = lightArriving(*world_, light, p, path, selfHit, quality_, shadowRays_);
        if (arriving.isBlack()) continue;
        // Light travels along -toLight; the viewer is back along the ray.
        // Several media along the stretch scatter their summed scattering
        // with the mean of their phase functions, the media that do not
        // scatter counting as isotropic (measured with povray 3.7: a Mie
        // slab overlapping a purely absorbing box scatters (p + 1) / 2 of
        // the light there).
        const double c = dot(path.toLight, ray_.direction);
        double phase = 0;
        RGB scattered(0.0);
        for (size_t i = 0; i < media_.size(); ++i) {
            phase += media_[i]->phase(c);
            scattered += scattering[i];
        }
        sum += arriving * scattered * (phase / double(media_.size()));
    }
    return sum;
}

// The light media photons scatter toward the viewer at p (povray 3.7,
// lit or not by the lights): each photon gathered around p scattered with
// the phase function of its direction as a light's is, summed over the
// volume of the sphere they were gathered from.
RGB Sampler::photonScattered(const Vec3& p, const RGB* scattering) const {
    const Photons* photons = world_->photons();
    if (!photons || !photons->hasMediaPhotons()) return RGB(0.0);
    const double r = photons->mediaPhotons(p, photonScratch_);
    if (photonScratch_.empty() || !(r > 0)) return RGB(0.0);
    RGB scattered(0.0);
    for (size_t i = 0; i < media_.size(); ++i) scattered += scattering[i];
    RGB sum(0.0);
    for (const PhotonNeighbour& f : photonScratch_) {
        // Towards where the photon came from, as a light's direction.
        const double c = -dot(f.photon->travel(), ray_.direction);
        double phase = 0;
        for (const scene::Media* m : media_) phase += m->phase(c);
        sum += f.photon->light() * (phase / double(media_.size()));
    }
    return sum * scattered * (3.0 / (4.0 * std::numbers::pi * r * r * r));
}

Sample Sampler::at(double t) const {
    ++samples_;
    const Vec3 p = ray_.at(t);
    Sample s;
    std::array<RGB, MediaSet::kCapacity> scattering{};
    bool scatters = false;
    for (size_t i = 0; i < media_.size(); ++i) {
        const scene::Media& m = *media_[i];
        const RGB density = m.densityAt(p);
        if (density.isBlack()) continue;
        s.light += m.emission * density;
        s.extinction += m.absorption * density;
        if (m.scatters()) {
            const RGB sc = m.scattering * density;
            s.extinction += sc * m.extinction;
            scattering[i] = sc;
            scatters = true;
        }
    }
    if (lights_ && scatters) {
        s.light += inScattered(p, scattering.data());
        s.light += photonScattered(p, scattering.data());
    }
    return s;
}

// The mean over [a, b] given its end points. Below aa_level a half whose
// end points' light differs by aa_threshold or more, once multiplied by
// the interval's length (measured: halving the interval doubles the
// density at which povray starts to split), is split in turn; a half that
// does not differ counts as the mean of its two ends with the outer end
// weighed twice (measured with povray 3.7 on emitting slabs whose density
// grows as a power of the depth: a one-sided split gives exactly that).
Sample Sampler::segment(double a, double b, const Sample& va, const Sample& vb, int level,
                        double scale) const {
    const double m = 0.5 * (a + b);
    const Sample vm = at(m);
    const bool left = level < settings_.aaLevel &&
                      summedDifference(va.light, vm.light) * scale >= settings_.aaThreshold;
    const bool right = level < settings_.aaLevel &&
                       summedDifference(vm.light, vb.light) * scale >= settings_.aaThreshold;
    if (left || right) {
        Sample sum = left ? segment(a, m, va, vm, level + 1, scale) : (va * 2.0 + vm) * (1.0 / 3.0);
        sum += right ? segment(m, b, vm, vb, level + 1, scale) : (vm + vb * 2.0) * (1.0 / 3.0);
        return sum * 0.5;
    }
    Sample sum = va;
    sum += vm;
    sum += vb;
    return sum * (1.0 / 3.0);
}

double Sampler::jittered(double t, double spacing, uint64_t index) const {
    if (settings_.jitter <= 0) return t;
    const uint64_t h = fmix64(seed_ ^ fmix64(index * 0x9E3779B97F4A7C15ULL + 1));
    const double u = unitFromHash(h);
    return t + (u - 0.5) * settings_.jitter * spacing;
}

// The pieces of [0, depth] that povray samples as separate intervals: the
// ray is cut where it enters and leaves the volume of a spot or cylinder
// light that scatters in the media (measured: a cylinder light across the
// ray makes three intervals, cut at its falloff radius). Each piece gets
// one interval, the lit ones share what `intervals` leaves beyond that
// (measured with ratio 0.9: intervals 4 and 10 give the lit piece 2 and 8).
// The volumes of several lights that overlap along the ray make one lit
// piece (measured: interior/media/media1.pov's three crossing spotlights).
void Sampler::pieces(double depth, std::vector<Piece>& out) const {
    const int total = constant() ? 1 : std::max(1, settings_.intervals);
    std::vector<double> cuts;
    std::vector<const scene::Light*> volumes;
    if (lights_) {
        for (const scene::Light& light : world_->scene().lights) {
            if (!light.mediaInteraction || light.parallel) continue;
            if (light.kind != scene::LightKind::Spot && light.kind != scene::LightKind::Cylinder)
                continue;
            volumes.push_back(&light);
            lightVolumeCrossings(light, ray_, depth, cuts);
        }
    }
    if (cuts.empty()) {
        out.push_back({0.0, depth, total});
        return;
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.push_back(depth);
    double from = 0.0, litLength = 0.0;
    int unlit = 0, lit = 0;
    for (const double to : cuts) {
        if (!(to > from)) continue;
        bool isLit = false;
        const Vec3 mid = ray_.at(0.5 * (from + to));
        for (const scene::Light* light : volumes) isLit = isLit || insideLightVolume(*light, mid);
        if (isLit && !out.empty() && out.back().intervals < 0) {
            // Lit pieces that touch (overlapping cones) are one piece.
            out.back().to = to;
        } else {
            out.push_back({from, to, isLit ? -1 : 1});
            ++(isLit ? lit : unlit);
        }
        if (isLit) litLength += to - from;
        from = to;
    }
    // One interval per lit piece, and what is left shared by length.
    const int extra = std::max(0, total - unlit - lit);
    for (Piece& p : out) {
        if (p.intervals > 0) continue;
        p.intervals = 1 + static_cast<int>(
                              std::lround(extra * (p.to - p.from) / std::max(litLength, 1e-300)));
    }
}

MediaResult Sampler::run(double depth) const {
    MediaResult result;
    if (!(depth > 0)) return result;
    const int n = std::max(settings_.samplesMin, 3) / 2 + 1;
    // Without spot or cylinder lights the whole stretch is one piece (no
    // allocation on this common path).
    std::vector<Piece> parts;
    const Piece whole{0.0, depth, constant() ? 1 : std::max(1, settings_.intervals)};
    if (hasVolumeLights()) pieces(depth, parts);
    const std::span<const Piece> list =
        parts.empty() ? std::span<const Piece>(&whole, 1) : std::span<const Piece>(parts);
    uint64_t index = 0;
    for (const Piece& piece : list) {
        const double intervalLength = (piece.to - piece.from) / piece.intervals;
        const double spacing = intervalLength / (2.0 * n + 2.0);
        const double weight = intervalLength / n;
        for (int i = 0; i < piece.intervals; ++i) {
            const double start = piece.from + i * intervalLength;
            double a = jittered(start, spacing, index++);
            Sample va = at(a);
            for (int k = 0; k < n; ++k) {
                const double b = jittered(start + (2.0 * k + 2.0) * spacing, spacing, index++);
                const Sample vb = at(b);
                const Sample mean = segment(a, b, va, vb, 1, intervalLength);
                result.light += result.transmittance * mean.light * weight;
                const RGB od = mean.extinction * weight;
                result.transmittance *= RGB(std::exp(-od.r), std::exp(-od.g), std::exp(-od.b));
                a = b;
                va = vb;
            }
        }
    }
    return result;
}

}  // namespace

void MediaSet::add(const scene::MediaList& list) {
    for (const auto& m : list)
        if (m && size_ < kCapacity) items_[size_++] = m.get();
}

MediaResult integrateMedia(const World& world, const LightingQuality& quality,
                           const scene::Ray& ray, double depth, const MediaSet& set, bool lights,
                           uint64_t& samples, uint64_t& shadowRays) {
    if (set.empty()) return {};
    const Sampler sampler(&world, quality, ray, set, lights, samples, shadowRays);
    return sampler.run(depth);
}

RGB mediaTransmittance(const scene::Ray& ray, double depth, const MediaSet& set) {
    if (set.empty()) return RGB(1.0);
    uint64_t samples = 0, shadowRays = 0;
    const LightingQuality quality;
    const Sampler sampler(nullptr, quality, ray, set, false, samples, shadowRays);
    return sampler.run(depth).transmittance;
}

}  // namespace frameray::render
