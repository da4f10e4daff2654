#include "scene/internal_functions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include "scene/noise.h"

namespace frameray::scene {

namespace {

using Formula = double (*)(const double* a);

// A native function given by a plain formula over its arguments
// (a[0..2] = x, y, z, then the extra parameters).
class FormulaFunction final : public NativeFunction {
  public:
    explicit FormulaFunction(Formula f) : f_(f) {}
    double eval(const double* args) const override { return f_(args); }

  private:
    Formula f_;
};

double radius(const double* a) {
    return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

// "Field strength" functions saturate at ±10 in povray (measured with
// f_paraboloid: -1.5 · 8.13 gives -10, -5 · -4.75 gives 10).
double field(double v) {
    return std::clamp(v, -10.0, 10.0);
}

double ellipsoid(const double* a) {
    // Extra parameters are inverse scales; povray returns the scaled
    // radius itself (no "- 1": measured).
    const double x = a[0] * a[3], y = a[1] * a[4], z = a[2] * a[5];
    return std::sqrt(x * x + y * y + z * z);
}

double paraboloid(const double* a) {
    return field(-a[3] * (a[0] * a[0] + a[2] * a[2] - a[1]));
}

double phi(const double* a) {
    const double r = radius(a);
    return r == 0 ? 0.0 : std::acos(a[1] / r);
}

double theta(const double* a) {
    return std::atan2(a[0], a[2]);
}

double roundedBox(const double* a) {
    // The distance to a box of half sizes a[4..6] with edges rounded by
    // a[3]; povray's values sit 1e-6 below the exact distance (measured).
    const double r = a[3];
    const double dx = std::max(std::abs(a[0]) - a[4] + r, 0.0);
    const double dy = std::max(std::abs(a[1]) - a[5] + r, 0.0);
    const double dz = std::max(std::abs(a[2]) - a[6] + r, 0.0);
    return std::sqrt(dx * dx + dy * dy + dz * dz) - r - 1e-6;
}

double sphere(const double* a) {
    return radius(a) - a[3];
}

double superellipsoid(const double* a) {
    // 1 - ((|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n))^(n/2) with e = a[3]
    // and n = a[4] (fitted to povray's values).
    const double e = a[3], n = a[4];
    const double xy = std::pow(std::abs(a[0]), 2 / e) + std::pow(std::abs(a[1]), 2 / e);
    const double s = std::pow(xy, e / n) + std::pow(std::abs(a[2]), 2 / n);
    return 1.0 - std::pow(s, n / 2);
}

double torus(const double* a) {
    const double ring = std::hypot(a[0], a[2]) - a[3];
    return std::sqrt(ring * ring + a[1] * a[1]) - a[4];
}

double noise3d(const double* a) {
    return solidNoise({a[0], a[1], a[2]}, NoiseGenerator::RangeCorrected);
}

double noiseGenerator(const double* a) {
    const int g = static_cast<int>(a[3]);
    if (g == 3)
        throw std::runtime_error("not supported yet: noise_generator 3 in f_noise_generator");
    return solidNoise({a[0], a[1], a[2]},
                      g == 1 ? NoiseGenerator::Original : NoiseGenerator::RangeCorrected);
}

struct Entry {
    std::string_view name;
    int extraParams;
    Formula formula;  // null: not implemented yet
};

// functions.inc's internal functions by number (77 is unused).
constexpr std::array<Entry, 79> kInternals = {{
    {"f_algbr_cyl1", 5, nullptr},
    {"f_algbr_cyl2", 5, nullptr},
    {"f_algbr_cyl3", 5, nullptr},
    {"f_algbr_cyl4", 5, nullptr},
    {"f_bicorn", 2, nullptr},
    {"f_bifolia", 2, nullptr},
    {"f_blob", 5, nullptr},
    {"f_blob2", 4, nullptr},
    {"f_boy_surface", 2, nullptr},
    {"f_comma", 1, nullptr},
    {"f_cross_ellipsoids", 4, nullptr},
    {"f_crossed_trough", 1, nullptr},
    {"f_cubic_saddle", 1, nullptr},
    {"f_cushion", 1, nullptr},
    {"f_devils_curve", 1, nullptr},
    {"f_devils_curve_2d", 6, nullptr},
    {"f_dupin_cyclid", 6, nullptr},
    {"f_ellipsoid", 3, ellipsoid},
    {"f_enneper", 1, nullptr},
    {"f_flange_cover", 4, nullptr},
    {"f_folium_surface", 3, nullptr},
    {"f_folium_surface_2d", 6, nullptr},
    {"f_glob", 1, nullptr},
    {"f_heart", 1, nullptr},
    {"f_helical_torus", 10, nullptr},
    {"f_helix1", 7, nullptr},
    {"f_helix2", 7, nullptr},
    {"f_hex_x", 1, nullptr},
    {"f_hex_y", 1, nullptr},
    {"f_hetero_mf", 6, nullptr},
    {"f_hunt_surface", 1, nullptr},
    {"f_hyperbolic_torus", 3, nullptr},
    {"f_isect_ellipsoids", 4, nullptr},
    {"f_kampyle_of_eudoxus", 3, nullptr},
    {"f_kampyle_of_eudoxus_2d", 6, nullptr},
    {"f_klein_bottle", 1, nullptr},
    {"f_kummer_surface_v1", 1, nullptr},
    {"f_kummer_surface_v2", 4, nullptr},
    {"f_lemniscate_of_gerono", 1, nullptr},
    {"f_lemniscate_of_gerono_2d", 6, nullptr},
    {"f_mesh1", 5, nullptr},
    {"f_mitre", 1, nullptr},
    {"f_nodal_cubic", 1, nullptr},
    {"f_odd", 1, nullptr},
    {"f_ovals_of_cassini", 4, nullptr},
    {"f_paraboloid", 1, paraboloid},
    {"f_parabolic_torus", 3, nullptr},
    {"f_ph", 0, phi},
    {"f_pillow", 1, nullptr},
    {"f_piriform", 1, nullptr},
    {"f_piriform_2d", 7, nullptr},
    {"f_poly4", 5, nullptr},
    {"f_polytubes", 6, nullptr},
    {"f_quantum", 1, nullptr},
    {"f_quartic_paraboloid", 1, nullptr},
    {"f_quartic_saddle", 1, nullptr},
    {"f_quartic_cylinder", 3, nullptr},
    {"f_r", 0, radius},
    {"f_ridge", 6, nullptr},
    {"f_ridged_mf", 6, nullptr},
    {"f_rounded_box", 4, roundedBox},
    {"f_sphere", 1, sphere},
    {"f_spikes", 5, nullptr},
    {"f_spikes_2d", 4, nullptr},
    {"f_spiral", 6, nullptr},
    {"f_steiners_roman", 1, nullptr},
    {"f_strophoid", 4, nullptr},
    {"f_strophoid_2d", 7, nullptr},
    {"f_superellipsoid", 2, superellipsoid},
    {"f_th", 0, theta},
    {"f_torus", 2, torus},
    {"f_torus2", 3, nullptr},
    {"f_torus_gumdrop", 1, nullptr},
    {"f_umbrella", 1, nullptr},
    {"f_witch_of_agnesi", 2, nullptr},
    {"f_witch_of_agnesi_2d", 6, nullptr},
    {"f_noise3d", 0, noise3d},
    {"", 0, nullptr},
    {"f_noise_generator", 1, noiseGenerator},
}};

}  // namespace

InternalFunction internalFunction(int n) {
    if (n < 0 || n >= static_cast<int>(kInternals.size())) return {};
    const Entry& e = kInternals[static_cast<size_t>(n)];
    InternalFunction result{std::string(e.name), e.extraParams, nullptr};
    if (e.formula) result.function = std::make_shared<FormulaFunction>(e.formula);
    return result;
}

}  // namespace frameray::scene
