// Pigment patterns (seed 003 §5.4.1): colour-list patterns pick an index,
// colour-mapped patterns give a value in [0, 1] after the wave type,
// frequency and phase. Noise-based patterns follow povray 3.7 exactly
// (noise.h). Each pattern carries its chain of transformations and warps
// (warps.h). Evaluation is const, thread-safe and allocation-free.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "scene/crackle.h"
#include "scene/density_file.h"
#include "scene/facets.h"
#include "scene/fractals.h"
#include "scene/image_map.h"
#include "scene/noise.h"
#include "scene/tiling.h"
#include "scene/warps.h"
#include "util/function_vm.h"
#include "util/vec3.h"

namespace frameray::scene {

struct Object;
class Pigment;

// What a pattern may know of the surface besides the point (slope and aoi):
// the unit (perturbed) surface normal facing the viewer and the unit ray
// direction, both in world space whatever the pattern's space.
struct SurfaceInfo {
    Vec3 normal;
    Vec3 direction;
    // The surface's (u, v, 0) for uv_mapping (Object::surfaceUv).
    Vec3 uv;
};

enum class PatternKind {
    // colour-list patterns
    Checker,
    Hexagon,
    Brick,
    Square,      // 4 colours
    Triangular,  // 6 colours
    Cubic,       // 6 colours
    // colour-mapped patterns
    Gradient,
    Onion,
    Radial,
    Spherical,
    Cylindrical,
    Planar,
    Boxed,
    Leopard,
    Quilted,
    Spiral1,
    Spiral2,
    Cells,
    // pigment_pattern { }: the grey value of a pigment
    PigmentPattern,
    // object { }: a list pattern, index 1 inside the object, 0 outside
    Object,
    // facets (normals only, facets.h)
    Facets,
    // density_file df3 (density_file.h)
    DensityFile,
    // slope { } and aoi: values from the surface normal and the ray
    Slope,
    Aoi,
    // noise-based colour-mapped patterns (spotted is bozo with another
    // default colour map)
    Bozo,
    Spotted,
    Bumps,
    Dents,
    Granite,
    Marble,
    Wood,
    Agate,
    Wrinkles,
    Ripples,
    Waves,
    // image_pattern: the image's grey value or alpha (image_map.h)
    Image,
    // function { ... }: a user function of x, y, z
    Function,
    // crackle (crackle.h)
    Crackle,
    // mandel and julia (fractals.h)
    Fractal,
    // tiling N and pavement (tiling.h)
    Tiling,
    Pavement,
};

// The sources of ripples and waves (shared with their normals):
// global_settings' number_of_waves of them, povray's default 10.
struct WaveSources {
    std::vector<Vec3> center;
    std::vector<double> frequency;
};
inline constexpr int kDefaultWaveCount = 10;
std::shared_ptr<const WaveSources> makeWaveSources(int count);

// quilted's offset from the unit cube's centre, scaled by the quilt curve
// of its length (the pattern averages its coordinates; the normal adds it).
Vec3 quiltOffset(const Vec3& p, double control0, double control1);

enum class WaveType { Ramp, Triangle, Sine, Scallop, Cubic, Poly };

struct Pattern {
    PatternKind kind = PatternKind::Gradient;
    Vec3 gradient{1, 0, 0};  // gradient direction, normalised
    Vec3 brickSize{8, 3, 4.5};
    double mortar = 0.5;
    double control0 = 1, control1 = 1;  // quilted
    int arms = 0;                       // spiral1 / spiral2
    int tiling = 1;                     // tiling N
    PavementSettings pavement;          // pavement
    WaveType waveType = WaveType::Ramp;
    double exponent = 1;  // poly_wave
    // povray keeps frequency and phase in single precision (visible in its
    // pattern values), so the parser rounds them to float.
    double frequency = 1, phase = 0;
    NoiseGenerator noiseGenerator = NoiseGenerator::RangeCorrected;
    // noise_generator written in the pattern; otherwise the parser gives it
    // global_settings' noise_generator.
    bool noiseGeneratorGiven = false;
    // ripples and waves: the sources for the number_of_waves in force
    // (null: the default 10).
    std::shared_ptr<const WaveSources> waves;
    const WaveSources& waveSources() const;
    double agateTurb = 1.0;
    std::shared_ptr<const ImageMap> image;             // image_pattern
    std::shared_ptr<const CompiledFunction> function;  // function { ... }
    CrackleSettings crackle;                           // crackle's form, metric, offset, solid
    FractalSettings fractal;                           // mandel, julia and magnet
    FacetsSettings facets;                             // facets (normals only)
    std::shared_ptr<const Pigment> pigment;            // pigment_pattern
    std::shared_ptr<const Object> object;              // object
    std::shared_ptr<const DensityFile> density;        // density_file
    int densityInterpolation = 0;                      // density_file's interpolate
    // slope { S [, lo, hi] [altitude A [, lo, hi]] }: 0.5 + asin(n·Ŝ)/π and
    // the point's height p·Â, each mapped by (v - lo) / (hi - lo) when a
    // range is given, averaged with the weights |S| and |A| (measured).
    Vec3 slopeDirection{0, 1, 0};
    double slopeLow = 0, slopeHigh = 1;
    Vec3 altitudeDirection{0, 0, 0};  // zero: no altitude
    double altitudeLow = 0, altitudeHigh = 1;
    // The pattern's own `turbulence`: applied after every warp and
    // transformation, or used inside marble, wood and agate.
    std::optional<Turbulence> turbulence;
    // Transformations and warps in the order written.
    std::vector<Warp> chain;

    // Appends a transformation, merged with a directly preceding one.
    void addTransform(const Transform& t);
    void addWarp(const Warp& w) { chain.push_back(w); }
    // Texture-space point to pattern space: the chain backwards, then the
    // pattern's turbulence unless the pattern uses it itself.
    Vec3 patternPoint(const Vec3& p) const;

    // Number of colours a colour-list pattern takes (0 for mapped patterns).
    static int listSize(PatternKind kind);
    bool isList() const { return listSize(kind) > 0; }

    // Colour-list patterns: the index of the colour at texture point p.
    int index(const Vec3& p) const;
    // The same at pattern-space point q (after patternPoint).
    int indexAt(const Vec3& q) const;
    // Colour-mapped patterns: the pattern function at pattern-space point q
    // (after patternPoint), before the wave.
    double raw(const Vec3& q, const SurfaceInfo* surface = nullptr) const;
    // The colour map index at texture point p: raw() after frequency, phase
    // and the wave type.
    double value(const Vec3& p, const SurfaceInfo* surface = nullptr) const;
    // Applies frequency, phase and the wave type to a raw value.
    double wave(double raw) const;
};

// `function { pattern { ... } }`: a pattern's value as a function of x, y,
// z — the colour-list index for list patterns (through frequency, phase
// and the wave when any of them is not the default), otherwise the value
// after frequency, phase and the wave (measured against povray).
class PatternFunction final : public NativeFunction {
  public:
    explicit PatternFunction(Pattern pattern) : pattern_(std::move(pattern)) {}
    double eval(const double* args) const override;

  private:
    Pattern pattern_;
};

// The hexagon lattice of the hexagon pattern (unit sides, a centre at the
// origin, corners along x) in the x-z plane: the axial coordinates (q, r)
// of the centre nearest to (x, z). Shared with the tiling patterns.
void nearestHexagon(double x, double z, double& rq, double& rr);

}  // namespace frameray::scene
