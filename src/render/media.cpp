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

// Whether a light's light scatters in media: it interacts with media and
// is not shadowless (measured with povray 3.7: a shadowless light adds
// nothing to scattering media, thin or dense, camera inside or outside).
bool scattersInMedia(const scene::Light& light) {
    return light.mediaInteraction && !light.shadowless;
}

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

RGB expNegative(const RGB& od) {
    return RGB(std::exp(-od.r), std::exp(-od.g), std::exp(-od.b));
}

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
            const MediaSet& set, bool lights, uint64_t& samples, uint64_t& shadowRays,
            std::span<const scene::Interior* const> inside = {})
        : world_(world),
          quality_(quality),
          ray_(ray),
          media_(set.media()),
          settings_(sampling(media_)),
          aaThreshold_(smallestAaThreshold(media_)),
          primary_(lights && world),
          lights_(primary_ && anyScatters()),
          samples_(samples),
          shadowRays_(shadowRays),
          inside_(inside) {
        seed_ = fmix64(std::bit_cast<uint64_t>(ray.origin.x) ^
                       fmix64(std::bit_cast<uint64_t>(ray.origin.y + 3.0 * ray.direction.x) ^
                              fmix64(std::bit_cast<uint64_t>(ray.origin.z + 5.0 * ray.direction.y) ^
                                     std::bit_cast<uint64_t>(ray.direction.z))));
    }

    MediaResult run(double depth);

  private:
    // povray 3.7 samples several media together with the settings of the
    // first one with the most intervals, and the smallest aa_threshold.
    static const scene::Media& sampling(std::span<const scene::Media* const> media) {
        const scene::Media* best = media.front();
        for (const scene::Media* m : media)
            if (m->intervals > best->intervals) best = m;
        return *best;
    }
    static double smallestAaThreshold(std::span<const scene::Media* const> media) {
        double t = media.front()->aaThreshold;
        for (const scene::Media* m : media) t = std::min(t, m->aaThreshold);
        return t;
    }
    bool anyScatters() const {
        for (const scene::Media* m : media_)
            if (m->scatters()) return true;
        return false;
    }
    // Whether every media along the stretch is constant (no density).
    bool constant() const {
        for (const scene::Media* m : media_)
            if (!m->constant()) return false;
        return true;
    }
    // Whether a light that interacts with media other than a spot or
    // cylinder light's volume lights the whole stretch (camera and
    // secondary rays only: shadow rays see no light).
    bool wholeLit() const {
        if (!primary_) return false;
        for (const scene::Light& light : world_->scene().lights)
            if (scattersInMedia(light) &&
                (light.parallel || (light.kind != scene::LightKind::Spot &&
                                    light.kind != scene::LightKind::Cylinder)))
                return true;
        return false;
    }
    // The intervals of a stretch that no light volume cuts: measured with
    // povray 3.7, constant media are sampled over one interval whatever
    // `intervals` says unless a light interacting with media lights the
    // stretch (even media that only emit and absorb: a point light in the
    // scene makes `intervals 4` sample four).
    int wholeIntervals(bool lit) const {
        return constant() && !lit ? 1 : std::max(1, settings_.intervals);
    }
    struct Piece {
        double from, to;
        int intervals;  // -1 while a lit piece waits for its share
    };
    MediaResult runAdaptive(std::span<const Piece> list) const;
    MediaResult runRegular(std::span<const Piece> list) const;
    Sample at(double t) const;
    RGB inScattered(const Vec3& p, double t, const RGB* scattering) const;
    RGB photonScattered(const Vec3& p, const RGB* scattering) const;
    // The stretch of the ray each scene light can light (indexed like the
    // scene's lights): everywhere for point lights, the crossing of a spot
    // or cylinder light's volume (a little wider) otherwise, as povray 3.7
    // only scatters a light at the points of its lit interval. Only for
    // rays that scatter light; empty otherwise.
    void litRanges(double depth);
    struct Range {
        double from, to;
    };
    std::vector<Range> ranges_;
    double margin_ = 0.0;
    bool convexVolumes_ = true;  // every volume light's range is exact
    // `scale`: the interval's length, which the light differences are
    // multiplied by before they are compared with aa_threshold.
    Sample segment(double a, double b, const Sample& va, const Sample& vb, int level,
                   double scale) const;
    double jittered(double t, double spacing, uint64_t index) const;
    // A number in [0, 1) for the index-th draw along this ray (povray's
    // are random).
    double draw(uint64_t index) const {
        return unitFromHash(fmix64(seed_ ^ fmix64(index * 0x9E3779B97F4A7C15ULL + 1)));
    }
    void pieces(double depth, std::vector<Piece>& out) const;
    bool hasVolumeLights() const {
        if (!primary_) return false;
        for (const scene::Light& light : world_->scene().lights)
            if (scattersInMedia(light) && !light.parallel &&
                (light.kind == scene::LightKind::Spot || light.kind == scene::LightKind::Cylinder))
                return true;
        return false;
    }

    const World* world_;
    const LightingQuality& quality_;
    const scene::Ray& ray_;
    std::span<const scene::Media* const> media_;
    const scene::Media& settings_;
    double aaThreshold_;
    bool primary_;  // a camera or secondary ray, not a shadow ray
    bool lights_;   // primary_ and some media scatters light
    uint64_t seed_ = 0;
    uint64_t& samples_;
    uint64_t& shadowRays_;
    std::span<const scene::Interior* const> inside_;  // the ray's containers
    mutable std::vector<PhotonNeighbour> photonScratch_;
};

RGB Sampler::inScattered(const Vec3& p, double t, const RGB* scattering) const {
    RGB sum(0.0);
    const scene::Scene& scene = world_->scene();
    size_t index = 0;
    // A point in open space: shadow rays start right at it.
    const double selfHit =
        std::max(1e-9 * std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}), 1e-300);
    for (const scene::Light& light : scene.lights) {
        const size_t i = index++;
        if (!scattersInMedia(light)) continue;
        if (i < ranges_.size() && !(t >= ranges_[i].from - margin_ && t <= ranges_[i].to + margin_))
            continue;
        LightPath path;
        if (!pathToLight(light, p, path)) continue;
        const RGB arriving =
            lightArriving(*world_, light, p, path, selfHit, quality_, shadowRays_, inside_);
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
        s.light += inScattered(p, t, scattering.data());
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
    const bool left =
        level < settings_.aaLevel && summedDifference(va.light, vm.light) * scale >= aaThreshold_;
    const bool right =
        level < settings_.aaLevel && summedDifference(vm.light, vb.light) * scale >= aaThreshold_;
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
    return t + (draw(index) - 0.5) * settings_.jitter * spacing;
}

// The pieces of [0, depth] that povray samples as separate intervals: the
// ray is cut where it enters and leaves the volume of a spot or cylinder
// light that interacts with media (measured: a cylinder light across the
// ray makes three intervals, cut at its falloff radius). The volumes of
// several lights that overlap along the ray make one lit piece (measured:
// interior/media/media1.pov's three crossing spotlights).
//
// The intervals are shared as povray 3.7 shares them: with `ratio` the
// weight of a lit piece and 1 - ratio that of an unlit one, piece i gets
// floor(weight / (sum of weights) * intervals) + 1, but no more than
// leaves one for each piece after it (measured with ratio 0.9: intervals 4
// and 10 give the lit middle of three pieces 2 and 8; `intervals` below
// the number of pieces counts as that number).
void Sampler::pieces(double depth, std::vector<Piece>& out) const {
    std::vector<double> cuts;
    std::vector<const scene::Light*> volumes;
    std::vector<Range> volumeRanges;
    // With every volume's crossing known (litRanges), the pieces come from
    // the crossings' ends; otherwise from each volume's surface crossings.
    const bool fromRanges = convexVolumes_ && !ranges_.empty();
    const std::vector<scene::Light>& lights = world_->scene().lights;
    for (size_t i = 0; i < lights.size(); ++i) {
        const scene::Light& light = lights[i];
        if (!scattersInMedia(light) || light.parallel) continue;
        if (light.kind != scene::LightKind::Spot && light.kind != scene::LightKind::Cylinder)
            continue;
        if (!fromRanges) {
            volumes.push_back(&light);
            lightVolumeCrossings(light, ray_, depth, cuts);
            continue;
        }
        const Range& r = ranges_[i];
        volumeRanges.push_back(r);
        if (r.from > 0 && r.from < depth) cuts.push_back(r.from);
        if (r.to > 0 && r.to < depth) cuts.push_back(r.to);
    }
    auto litAt = [&](double t) {
        if (!fromRanges) {
            const Vec3 mid = ray_.at(t);
            for (const scene::Light* light : volumes)
                if (insideLightVolume(*light, mid)) return true;
            return false;
        }
        for (const Range& r : volumeRanges)
            if (t >= r.from && t <= r.to) return true;
        return false;
    };
    std::sort(cuts.begin(), cuts.end());
    cuts.push_back(depth);
    std::vector<bool> lit;
    double from = 0.0;
    for (const double to : cuts) {
        if (!(to > from)) continue;
        const bool isLit = litAt(0.5 * (from + to));
        if (isLit && !lit.empty() && lit.back()) {
            // Lit pieces that touch (overlapping cones) are one piece.
            out.back().to = to;
        } else {
            out.push_back({from, to, 0});
            lit.push_back(isLit);
        }
        from = to;
    }
    if (out.size() == 1) {
        out.front().intervals = wholeIntervals(lit.front());
        return;
    }
    const int count = static_cast<int>(out.size());
    const int total = std::max(settings_.intervals, count);
    const double ratio = settings_.ratio;
    double sum = 0.0;
    for (const bool l : lit) sum += l ? ratio : 1.0 - ratio;
    int remaining = total;
    for (int i = 0; i < count; ++i) {
        const double weight = lit[size_t(i)] ? ratio : 1.0 - ratio;
        int n = static_cast<int>(weight / sum * total) + 1;
        n = std::min(n, remaining - count + i + 1);
        out[size_t(i)].intervals = std::max(n, 1);
        remaining -= n;
    }
}

// Method 3 (see render/media.h).
MediaResult Sampler::runAdaptive(std::span<const Piece> list) const {
    MediaResult result;
    const int n = std::max(settings_.samplesMin, 3) / 2 + 1;
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
                result.transmittance *= expNegative(od);
                a = b;
                va = vb;
            }
        }
    }
    return result;
}

// Methods 1 and 2 (see render/media.h).
MediaResult Sampler::runRegular(std::span<const Piece> list) const {
    const int minSamples = std::max(1, settings_.samplesMin);
    const int maxSamples = std::max(minSamples, settings_.samplesMax);
    // A shadow ray through constant media needs one sample per interval.
    const int first = !primary_ && constant() ? 1 : minSamples;
    const bool more = primary_ && maxSamples > minSamples &&
                      settings_.sampleThreshold.size() >= size_t(maxSamples);
    RGB depthSoFar(0.0);  // optical depth of the intervals before
    MediaResult result;
    uint64_t index = 0;
    for (const Piece& piece : list) {
        const double length = (piece.to - piece.from) / piece.intervals;
        for (int i = 0; i < piece.intervals; ++i) {
            const double start = piece.from + i * length;
            RGB light(0.0), light2(0.0), od(0.0);
            int count = 0;
            // A sample at `u` (0 at the interval's start, 1 at its end)
            // stands for the whole interval, its light dimmed by its own
            // extinction over the distance from the interval's start.
            auto take = [&](double u) {
                const double d = u * length;
                const Sample s = at(start + d);
                od += s.extinction * length;
                const RGB e = s.light * length * expNegative(s.extinction * d);
                light += e;
                light2 += e * e;
                ++count;
            };
            for (int j = 0; j < first; ++j) {
                const double u = settings_.method == 2
                                     ? (j + 0.5 + draw(index++) * settings_.jitter) / minSamples
                                     : draw(index++);
                take(u);
            }
            // The confidence test: more random samples while the variance
            // of the mean light exceeds the threshold for the count so far.
            if (more && count < maxSamples) {
                for (;;) {
                    const RGB mean = light * (1.0 / count);
                    const RGB variance = (light2 * (1.0 / count) - mean * mean) * (1.0 / count);
                    const double limit = settings_.sampleThreshold[size_t(count - 1)];
                    if (std::fabs(variance.r) < limit && std::fabs(variance.g) < limit &&
                        std::fabs(variance.b) < limit)
                        break;
                    take(draw(index++));
                    if (count > maxSamples) break;
                }
            }
            const double share = 1.0 / count;
            result.light += light * share * expNegative(depthSoFar);
            depthSoFar += od * share;
        }
    }
    result.transmittance = expNegative(depthSoFar);
    return result;
}

void Sampler::litRanges(double depth) {
    const std::vector<scene::Light>& lights = world_->scene().lights;
    ranges_.assign(lights.size(), Range{-scene::kInfinity, scene::kInfinity});
    // Points within this of an end of the crossing are still lit (light's
    // own attenuation decides there): the skipped ones are surely dark.
    margin_ = 1e-6 * std::max(depth, 1.0);
    std::vector<double> cuts;
    for (size_t i = 0; i < lights.size(); ++i) {
        const scene::Light& light = lights[i];
        if (!scattersInMedia(light) || light.parallel) continue;
        if (light.kind != scene::LightKind::Spot && light.kind != scene::LightKind::Cylinder)
            continue;
        // A cone wider than a half-space is not convex: no range.
        if (light.kind == scene::LightKind::Spot && std::max(light.falloff, light.radius) >= 90.0) {
            convexVolumes_ = false;
            continue;
        }
        cuts.clear();
        cuts.push_back(0.0);
        lightVolumeCrossings(light, ray_, depth, cuts);
        std::sort(cuts.begin(), cuts.end());
        cuts.push_back(depth);
        // The volume is convex: the lit pieces between the cuts make one
        // stretch.
        double from = scene::kInfinity, to = -scene::kInfinity;
        for (size_t k = 0; k + 1 < cuts.size(); ++k) {
            if (!(cuts[k + 1] > cuts[k])) continue;
            if (!insideLightVolume(light, ray_.at(0.5 * (cuts[k] + cuts[k + 1])))) continue;
            from = std::min(from, cuts[k]);
            to = std::max(to, cuts[k + 1]);
        }
        ranges_[i] = from <= to ? Range{from, to} : Range{scene::kInfinity, -scene::kInfinity};
    }
}

MediaResult Sampler::run(double depth) {
    if (!(depth > 0)) return {};
    // A light that interacts with media everywhere (a point light) makes
    // the whole stretch one lit piece, spot and cylinder volumes included;
    // otherwise spot and cylinder volumes cut it. Without either the
    // stretch is one piece (no allocation on this common path).
    const bool lit = wholeLit();
    if ((lights_ || !lit) && hasVolumeLights()) litRanges(depth);
    std::vector<Piece> parts;
    if (!lit && hasVolumeLights()) pieces(depth, parts);
    const Piece whole{0.0, depth, wholeIntervals(lit)};
    const std::span<const Piece> list =
        parts.empty() ? std::span<const Piece>(&whole, 1) : std::span<const Piece>(parts);
    return settings_.method == 3 ? runAdaptive(list) : runRegular(list);
}

}  // namespace

void MediaSet::add(const scene::MediaList& list) {
    for (const auto& m : list)
        if (m && size_ < kCapacity) items_[size_++] = m.get();
}

MediaResult integrateMedia(const World& world, const LightingQuality& quality,
                           const scene::Ray& ray, double depth, const MediaSet& set, bool lights,
                           uint64_t& samples, uint64_t& shadowRays,
                           std::span<const scene::Interior* const> inside) {
    if (set.empty()) return {};
    Sampler sampler(&world, quality, ray, set, lights, samples, shadowRays, inside);
    return sampler.run(depth);
}

RGB mediaTransmittance(const scene::Ray& ray, double depth, const MediaSet& set) {
    if (set.empty()) return RGB(1.0);
    uint64_t samples = 0, shadowRays = 0;
    const LightingQuality quality;
    Sampler sampler(nullptr, quality, ray, set, false, samples, shadowRays);
    return sampler.run(depth).transmittance;
}

}  // namespace frameray::render
