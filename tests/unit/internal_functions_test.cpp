// functions.inc's internal functions against values povray 3.7 prints for
// the same calls (#debug str(f(...), 0, 9)).
#include "scene/internal_functions.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace frameray::scene {
namespace {

double call(int n, std::vector<double> args) {
    const InternalFunction f = internalFunction(n);
    EXPECT_TRUE(f.function) << f.name;
    EXPECT_EQ(static_cast<int>(args.size()), 3 + f.extraParams) << f.name;
    return f.function ? f.function->eval(args.data()) : 0.0;
}

// The function functions.inc declares under this name.
double callNamed(const std::string& name, std::vector<double> args) {
    for (int n = 0; n < 79; ++n)
        if (internalFunction(n).name == name) return call(n, std::move(args));
    ADD_FAILURE() << "no internal function " << name;
    return 0;
}

constexpr int kEllipsoid = 17, kParaboloid = 45, kPh = 47, kR = 57, kRoundedBox = 60, kSphere = 61,
              kSuperellipsoid = 68, kTh = 69, kTorus = 70, kNoise3d = 76;

TEST(InternalFunctions, NamesAndParameterCountsFollowFunctionsInc) {
    EXPECT_EQ(internalFunction(kSphere).name, "f_sphere");
    EXPECT_EQ(internalFunction(kSphere).extraParams, 1);
    EXPECT_EQ(internalFunction(kRoundedBox).extraParams, 4);
    EXPECT_EQ(internalFunction(24).name, "f_helical_torus");
    EXPECT_EQ(internalFunction(24).extraParams, 10);
    EXPECT_TRUE(internalFunction(77).name.empty());  // no function 77
    EXPECT_TRUE(internalFunction(79).name.empty());
    EXPECT_TRUE(internalFunction(-1).name.empty());
}

TEST(InternalFunctions, DistanceFunctionsMatchPovray) {
    EXPECT_NEAR(call(kSphere, {0.3, 0.2, 0.1, 0.7}), -0.325834, 1e-6);
    EXPECT_NEAR(call(kR, {0.3, 0.2, 0.1}), 0.374166, 1e-6);
    EXPECT_NEAR(call(kTorus, {0.3, 0.2, 0.1, 1, 0.25}), 0.462421552, 1e-9);
    EXPECT_NEAR(call(kTorus, {1.7, -0.4, 2.2, 1, 0.25}), 1.574671064, 1e-9);
    EXPECT_NEAR(call(kRoundedBox, {0.3, 0.2, 0.1, 0.1, 0.5, 0.6, 0.7}), -0.100001, 1e-9);
    EXPECT_NEAR(call(kRoundedBox, {1.7, -0.4, 2.2, 0.1, 0.5, 0.6, 0.7}), 1.961551813, 1e-9);
    EXPECT_NEAR(call(kRoundedBox, {-0.6, 0.9, -1.3, 0.0, 0.5, 0.6, 0.7}), 0.678231998, 1e-9);
    EXPECT_NEAR(call(kEllipsoid, {-0.6, 0.9, -1.3, 1, 2, 3}), 4.337049688, 1e-9);
    EXPECT_NEAR(call(kSuperellipsoid, {0.3, 0.2, 0.1, 0.3, 0.6}), 0.694827624, 1e-9);
    EXPECT_NEAR(call(kSuperellipsoid, {1.7, -0.4, 2.2, 0.3, 0.6}), -1.445807742, 1e-9);
    EXPECT_NEAR(call(kSuperellipsoid, {0.05, 0.5, 0.77, 0.3, 0.6}), 0.179247652, 1e-9);
}

TEST(InternalFunctions, AnglesMatchPovray) {
    EXPECT_NEAR(call(kTh, {0.3, 0.2, 0.1}), 1.249045772, 1e-9);
    EXPECT_NEAR(call(kTh, {-0.6, 0.9, -1.3}), -2.709184878, 1e-9);
    EXPECT_NEAR(call(kPh, {1.7, -0.4, 2.2}), 1.713685841, 1e-9);
    EXPECT_EQ(call(kPh, {0, 0, 0}), 0.0);
    EXPECT_EQ(call(kTh, {0, 0, 0}), 0.0);
}

TEST(InternalFunctions, FieldStrengthSaturatesAtTen) {
    EXPECT_NEAR(call(kParaboloid, {-1.5, -2.5, 0, 1.5}), -7.125, 1e-12);
    EXPECT_NEAR(call(kParaboloid, {-1.5, -2.5, 0, -2}), 9.5, 1e-12);
    EXPECT_EQ(call(kParaboloid, {-1.5, -2.5, 0, -5}), 10.0);
    EXPECT_EQ(call(kParaboloid, {-1.5, -2.5, 0, 3}), -10.0);
}

TEST(InternalFunctions, NoiseIsBozoNoise) {
    EXPECT_NEAR(call(kNoise3d, {0.3, 0.2, 0.1}), 0.373439, 1e-6);
    EXPECT_NEAR(call(78, {0.3, 0.2, 0.1, 1}), 0.209925, 1e-6);
    EXPECT_NEAR(call(78, {0.3, 0.2, 0.1, 2}), 0.373439, 1e-6);
    EXPECT_NEAR(call(78, {0.3, 0.2, 0.1, 3}), 0.578735912427, 1e-12);  // povray 3.7
}

// One or two points per function; values printed by povray 3.7 with
// str(f(...), 0, 9) (tests/language/scenes/internal_functions.pov checks
// many more, line by line).
TEST(InternalFunctions, AllImplementedFunctionsMatchPovray) {
    EXPECT_NEAR(callNamed("f_algbr_cyl1", {-0.437, -0.44, -0.294, 0.7, 3, 1, 0.082, 30}),
                -0.083583839, 1e-09);
    EXPECT_NEAR(callNamed("f_algbr_cyl1", {0.541, -0.217, -0.558, 0.7, 3, 1, 0.082, 30}),
                -0.084448542, 1e-09);
    EXPECT_NEAR(callNamed("f_algbr_cyl2", {0.161, 0.41, 0.282, 0.7, 3, 1, -0.021, 30}),
                -0.033707900, 1e-09);
    EXPECT_NEAR(callNamed("f_algbr_cyl2", {0.75, -0.066, -0.964, 0.7, 3, 1, -0.021, 30}),
                -0.702918186, 1e-09);
    EXPECT_NEAR(callNamed("f_algbr_cyl3", {-0.195, 0.259, -0.21, 0.7, 3, 1, -0.339, 30}),
                -0.045420664, 1e-09);
    EXPECT_NEAR(callNamed("f_algbr_cyl3", {0.0, -0.966, -0.459, 0.7, 3, 1, -0.339, 30}),
                -2.336057256, 2e-09);
    EXPECT_NEAR(callNamed("f_algbr_cyl4", {0.398, -0.014, -0.475, 0.7, 3, 1, 0.009, 30}),
                -0.256652896, 1e-09);
    EXPECT_NEAR(callNamed("f_algbr_cyl4", {-1.489, -0.025, -0.148, 0.7, 3, 1, 0.009, 30}),
                -3.000000000, 3e-09);
    EXPECT_NEAR(callNamed("f_bicorn", {0.101, -0.49, -0.198, 0.234, 0.42}), -0.060744779, 1e-09);
    EXPECT_NEAR(callNamed("f_bicorn", {-0.118, 1.377, 0.434, 0.234, 0.42}), -0.338719673, 1e-09);
    EXPECT_NEAR(callNamed("f_bifolia", {-0.083, 0.12, 0.174, 0.224, 0.464}), -0.000132071, 1e-09);
    EXPECT_NEAR(callNamed("f_bifolia", {0.744, 1.041, 0.493, 0.224, 0.464}), -0.705741245, 1e-09);
    EXPECT_NEAR(callNamed("f_blob", {-0.062, -0.477, 0.119, 0.254, 1.235, 1.366, 0.821, 1.014}),
                -0.781081717, 1e-09);
    EXPECT_NEAR(callNamed("f_blob", {-0.031, -0.794, 0.791, 0.254, 1.235, 1.366, 0.821, 1.014}),
                -0.000000000, 1e-09);
    EXPECT_NEAR(callNamed("f_blob2", {0.212, -0.234, 0.054, 0.167, 0.479, 0.695, 0.366}),
                -0.971072621, 1e-09);
    EXPECT_NEAR(callNamed("f_blob2", {-0.192, 0.865, 0.07, 0.167, 0.479, 0.695, 0.366}),
                -0.565558549, 1e-09);
    EXPECT_NEAR(callNamed("f_boy_surface", {0.344, -0.345, -0.344, 0.133, 1.805}), -4.169056902,
                4e-09);
    EXPECT_NEAR(callNamed("f_boy_surface", {-0.757, -0.52, 0.067, 0.133, 1.805}), -10.000000000,
                1e-08);
    EXPECT_NEAR(
        callNamed("f_cross_ellipsoids", {-0.486, -0.113, 0.092, 0.334, 1.265, 0.367, 0.502}),
        0.175161983, 1e-09);
    EXPECT_NEAR(callNamed("f_cross_ellipsoids", {1.313, 1.442, -0.074, 0.334, 1.265, 0.367, 0.502}),
                0.428924841, 1e-09);
    EXPECT_NEAR(callNamed("f_crossed_trough", {-0.299, -0.319, -0.416, 0.337}), 0.112716855, 1e-09);
    EXPECT_NEAR(callNamed("f_crossed_trough", {-1.347, 0.172, 1.112, 0.337}), 0.698128042, 1e-09);
    EXPECT_NEAR(callNamed("f_cubic_saddle", {0.233, -0.092, 0.222, 0.334}), 0.069663040, 1e-09);
    EXPECT_NEAR(callNamed("f_cubic_saddle", {-1.334, 0.932, -0.494, 0.334}), 0.898288081, 1e-09);
    EXPECT_NEAR(callNamed("f_cushion", {-0.412, 0.046, 0.34, 0.153}), -0.000430625, 1e-09);
    EXPECT_NEAR(callNamed("f_cushion", {0.33, 0.211, 0.451, 0.153}), -0.012480298, 1e-09);
    EXPECT_NEAR(callNamed("f_devils_curve", {0.012, 0.005, -0.312, 0.361}), -0.003414453, 1e-09);
    EXPECT_NEAR(callNamed("f_devils_curve", {-0.953, 0.39, 0.309, 0.361}), -0.251013757, 1e-09);
    EXPECT_NEAR(
        callNamed("f_devils_curve_2d", {0.347, -0.148, 0.129, 0.7, 0.915, 0.544, 1, -0.087, 30}),
        0.093270915, 1e-09);
    EXPECT_NEAR(
        callNamed("f_devils_curve_2d", {-0.955, -1.154, 1.238, 0.7, 0.915, 0.544, 1, -0.087, 30}),
        -8.990689082, 9e-09);
    EXPECT_NEAR(callNamed("f_dupin_cyclid",
                          {-0.131, 0.051, -0.131, 0.164, 1.875, 0.586, 1.634, 1.712, 1.562}),
                -7.261448872, 7e-09);
    EXPECT_NEAR(callNamed("f_dupin_cyclid",
                          {0.994, -0.782, -1.376, 0.164, 1.875, 0.586, 1.634, 1.712, 1.562}),
                -10.000000000, 1e-08);
    EXPECT_NEAR(callNamed("f_flange_cover", {-0.184, 0.379, -0.38, 0.201, 0.364, 1.158, 0.694}),
                -2.595262750, 3e-09);
    EXPECT_NEAR(callNamed("f_flange_cover", {-0.038, -1.093, -0.215, 0.201, 0.364, 1.158, 0.694}),
                -2.153244433, 2e-09);
    EXPECT_NEAR(callNamed("f_folium_surface", {0.311, -0.148, -0.115, 0.299, 1.052, 0.924}),
                0.055417292, 1e-09);
    EXPECT_NEAR(callNamed("f_folium_surface", {0.236, 1.274, -0.925, 0.299, 1.052, 0.924}),
                0.198777395, 1e-09);
    EXPECT_NEAR(
        callNamed("f_folium_surface_2d", {0.345, -0.273, 0.425, 0.7, 0.639, 1.227, 1, -0.412, 30}),
        -1.446984684, 1e-09);
    EXPECT_NEAR(
        callNamed("f_folium_surface_2d", {-1.403, 0.296, 1.402, 0.7, 0.639, 1.227, 1, -0.412, 30}),
        -3.476455018, 3e-09);
    EXPECT_NEAR(callNamed("f_glob", {0.287, -0.248, 0.338, 0.236}), -0.040446170, 1e-09);
    EXPECT_NEAR(callNamed("f_glob", {-0.804, -0.906, -0.126, 0.236}), -0.187799913, 1e-09);
    EXPECT_NEAR(callNamed("f_heart", {-0.329, -0.188, -0.447, 0.231}), 0.037138368, 1e-09);
    EXPECT_NEAR(callNamed("f_heart", {-0.607, -0.351, 1.401, 0.231}), -1.297601874, 1e-09);
    EXPECT_NEAR(callNamed("f_helix1", {0.262, -0.352, 0.106, 1, 0.735, 0.392, 1.35, 1.772, 0, 0}),
                1.240630501, 1e-09);
    EXPECT_NEAR(callNamed("f_helix1", {1.436, 0.806, -1.479, 1, 0.735, 0.392, 1.35, 1.772, 0, 0}),
                1.860617645, 2e-09);
    EXPECT_NEAR(callNamed("f_helix2", {0.023, -0.389, -0.252, 1, 2.908, 0.245, 1.223, 0.708, 0, 0}),
                0.740170027, 1e-09);
    EXPECT_NEAR(callNamed("f_helix2", {0.888, -0.644, -0.358, 1, 2.908, 0.245, 1.223, 0.708, 0, 0}),
                0.900277608, 1e-09);
    EXPECT_NEAR(callNamed("f_hex_x", {-0.396, -0.482, -0.21, 0.38}), 0.615424245, 1e-09);
    EXPECT_NEAR(callNamed("f_hex_x", {-0.633, 1.401, 1.111, 0.38}), 0.233025404, 1e-09);
    EXPECT_NEAR(callNamed("f_hex_y", {-0.406, 0.086, -0.309, 0.301}), 0.086000000, 1e-09);
    EXPECT_NEAR(callNamed("f_hex_y", {0.623, 0.912, 0.874, 0.301}), 0.083533827, 1e-09);
    EXPECT_NEAR(callNamed("f_hetero_mf", {0.363, 0.075, -0.49, 0.457, 1.673, 3, 1.021, 1.012, 0}),
                0.046300985, 1e-09);
    EXPECT_NEAR(callNamed("f_hetero_mf", {0.79, 0.32, 1.198, 0.457, 1.673, 3, 1.021, 1.012, 0}),
                1.666660848, 2e-09);
    EXPECT_NEAR(callNamed("f_hunt_surface", {-0.032, -0.408, -0.494, 0.141}), 10.000000000, 1e-08);
    EXPECT_NEAR(callNamed("f_hunt_surface", {-0.479, 0.651, 0.745, 0.141}), 10.000000000, 1e-08);
    EXPECT_NEAR(callNamed("f_hyperbolic_torus", {-0.114, -0.407, 0.373, 0.202, 0.452, 1.873}),
                -2.173275813, 2e-09);
    EXPECT_NEAR(callNamed("f_hyperbolic_torus", {0.761, 0.291, 1.43, 0.202, 0.452, 1.873}),
                -4.675565037, 5e-09);
    EXPECT_NEAR(callNamed("f_isect_ellipsoids", {0.0, -0.164, -0.336, 0.098, 0.883, 1.886, 0.615}),
                -1.088088892, 1e-09);
    EXPECT_NEAR(callNamed("f_isect_ellipsoids", {1.29, -0.078, 0.858, 0.098, 0.883, 1.886, 0.615}),
                0.208093482, 1e-09);
    EXPECT_NEAR(callNamed("f_kampyle_of_eudoxus", {-0.43, -0.418, -0.168, 0.226, 1.719, 1.069}),
                -0.178145001, 1e-09);
    EXPECT_NEAR(callNamed("f_kampyle_of_eudoxus", {-1.233, 0.446, -0.229, 0.226, 1.719, 1.069}),
                -0.620110410, 1e-09);
    EXPECT_NEAR(callNamed("f_kampyle_of_eudoxus_2d",
                          {0.474, -0.317, -0.342, 0.7, 0.905, 1.231, 1, 0.368, 30}),
                -0.145620899, 1e-09);
    EXPECT_NEAR(callNamed("f_kampyle_of_eudoxus_2d",
                          {-0.657, 1.266, 1.058, 0.7, 0.905, 1.231, 1, 0.368, 30}),
                -1.668283406, 2e-09);
    EXPECT_NEAR(callNamed("f_klein_bottle", {0.01, -0.186, 0.051, 0.276}), 0.122203306, 1e-09);
    EXPECT_NEAR(callNamed("f_klein_bottle", {-1.098, -0.05, 0.35, 0.276}), 0.781337024, 1e-09);
    EXPECT_NEAR(callNamed("f_kummer_surface_v1", {-0.112, -0.351, -0.317, 0.228}), -0.176475093,
                1e-09);
    EXPECT_NEAR(callNamed("f_kummer_surface_v1", {0.232, -0.93, -0.075, 0.228}), -0.176679816,
                1e-09);
    EXPECT_NEAR(
        callNamed("f_kummer_surface_v2", {-0.347, 0.019, -0.075, 0.121, 0.372, 1.063, 1.786}),
        0.113352739, 1e-09);
    EXPECT_NEAR(
        callNamed("f_kummer_surface_v2", {1.315, 1.192, -0.786, 0.121, 0.372, 1.063, 1.786}),
        -1.000969860, 1e-09);
    EXPECT_NEAR(callNamed("f_lemniscate_of_gerono", {0.004, -0.254, -0.213, 0.059}), -0.006482271,
                1e-09);
    EXPECT_NEAR(callNamed("f_lemniscate_of_gerono", {1.41, -0.383, 1.468, 0.059}), -0.251703122,
                1e-09);
    EXPECT_NEAR(callNamed("f_lemniscate_of_gerono_2d",
                          {-0.229, -0.007, 0.436, 0.7, 1.274, 1.079, 1, 0.059, 30}),
                0.142038996, 1e-09);
    EXPECT_NEAR(callNamed("f_lemniscate_of_gerono_2d",
                          {-1.01, 1.022, -0.308, 0.7, 1.274, 1.079, 1, 0.059, 30}),
                -1.188257877, 1e-09);
    EXPECT_NEAR(callNamed("f_mesh1", {-0.125, -0.085, 0.077, 0.306, 1.096, 0.999, 0.634, 1.66}),
                0.446172103, 1e-09);
    EXPECT_NEAR(callNamed("f_mesh1", {1.171, 1.335, 0.4, 0.306, 1.096, 0.999, 0.634, 1.66}),
                1.375002730, 1e-09);
    EXPECT_NEAR(callNamed("f_mitre", {-0.32, -0.25, 0.078, 0.124}), -0.001465872, 1e-09);
    EXPECT_NEAR(callNamed("f_mitre", {-0.161, -0.585, 0.078, 0.124}), 0.022843688, 1e-09);
    EXPECT_NEAR(callNamed("f_nodal_cubic", {0.489, -0.285, -0.483, 0.249}), 0.239477670, 1e-09);
    EXPECT_NEAR(callNamed("f_nodal_cubic", {-0.515, -0.56, -1.128, 0.249}), 1.344835343, 1e-09);
    EXPECT_NEAR(callNamed("f_odd", {0.26, -0.096, -0.025, 0.096}), 0.006644098, 1e-09);
    EXPECT_NEAR(callNamed("f_odd", {-0.311, 0.823, 1.21, 0.096}), -0.054211412, 1e-09);
    EXPECT_NEAR(
        callNamed("f_ovals_of_cassini", {0.381, -0.183, -0.355, 0.085, 0.847, 0.993, 1.215}),
        0.015110713, 1e-09);
    EXPECT_NEAR(callNamed("f_ovals_of_cassini", {0.785, 0.58, -0.385, 0.085, 0.847, 0.993, 1.215}),
                -0.140563010, 1e-09);
    EXPECT_NEAR(callNamed("f_parabolic_torus", {0.131, 0.43, 0.17, 0.073, 0.887, 1.973}),
                -0.714592125, 1e-09);
    EXPECT_NEAR(callNamed("f_parabolic_torus", {-1.495, -1.286, -1.39, 0.073, 0.887, 1.973}),
                -1.125150256, 1e-09);
    EXPECT_NEAR(callNamed("f_pillow", {0.0, 0.03, -0.112, 0.075}), -0.000996438, 1e-09);
    EXPECT_NEAR(callNamed("f_pillow", {-1.099, -1.445, 0.178, 0.075}), 0.186909415, 1e-09);
    EXPECT_NEAR(callNamed("f_piriform", {-0.394, -0.448, -0.237, 0.165}), 0.056452143, 1e-09);
    EXPECT_NEAR(callNamed("f_piriform", {0.41, 1.405, 1.406, 0.165}), 0.645182606, 1e-09);
    EXPECT_NEAR(
        callNamed("f_piriform_2d", {0.162, 0.21, -0.04, 0.7, 1.904, 1.238, 0.622, 1, 0.039, 30}),
        -0.042291542, 1e-09);
    EXPECT_NEAR(
        callNamed("f_piriform_2d", {-0.673, -0.239, 0.644, 0.7, 1.904, 1.238, 0.622, 1, 0.039, 30}),
        0.539054808, 1e-09);
    EXPECT_NEAR(callNamed("f_poly4", {-0.068, -0.441, 0.435, 0.099, 1.927, 0.771, 1.193, 1.114}),
                1.101329330, 1e-09);
    EXPECT_NEAR(callNamed("f_poly4", {-1.087, 1.153, -1.364, 0.099, 1.927, 0.771, 1.193, 1.114}),
                -5.399098029, 5e-09);
    EXPECT_NEAR(callNamed("f_quartic_paraboloid", {-0.184, 0.152, 0.382, 0.141}), 0.018267954,
                1e-09);
    EXPECT_NEAR(callNamed("f_quartic_paraboloid", {0.567, -0.954, 1.471, 0.141}), -0.809278390,
                1e-09);
    EXPECT_NEAR(callNamed("f_quartic_saddle", {0.186, -0.172, -0.476, 0.096}), -0.011698579, 1e-09);
    EXPECT_NEAR(callNamed("f_quartic_saddle", {1.015, 0.762, 1.135, 0.096}), 0.130575370, 1e-09);
    EXPECT_NEAR(callNamed("f_quartic_cylinder", {0.059, 0.453, -0.073, 0.127, 0.655, 0.547}),
                0.015738376, 1e-09);
    EXPECT_NEAR(callNamed("f_quartic_cylinder", {0.473, -1.5, -0.244, 0.127, 0.655, 0.547}),
                -0.075404160, 1e-09);
    EXPECT_NEAR(callNamed("f_ridge", {0.023, -0.272, 0.026, 0.756, 1.897, 3, 1.1, 0.526, 0}),
                -0.646535701, 1e-09);
    EXPECT_NEAR(callNamed("f_ridge", {-1.489, -1.391, 1.387, 0.756, 1.897, 3, 1.1, 0.526, 0}),
                -0.185857484, 1e-09);
    EXPECT_NEAR(callNamed("f_ridged_mf", {0.419, 0.453, 0.032, 0.52, 1.922, 3, 1.062, 1.956, 0}),
                0.213608148, 1e-09);
    EXPECT_NEAR(callNamed("f_ridged_mf", {-0.337, -1.479, 0.081, 0.52, 1.922, 3, 1.062, 1.956, 0}),
                0.702700642, 1e-09);
    EXPECT_NEAR(callNamed("f_spikes", {0.118, -0.256, -0.166, 0.266, 1.394, 0.638, 1.366, 1.234}),
                1.093826193, 1e-09);
    EXPECT_NEAR(callNamed("f_spikes", {1.138, -1.341, -0.066, 0.266, 1.394, 0.638, 1.366, 1.234}),
                0.275842949, 1e-09);
    EXPECT_NEAR(callNamed("f_spikes_2d", {0.14, -0.171, 0.193, 0.7, 1, 0.407, 30}), -0.296548212,
                1e-09);
    EXPECT_NEAR(callNamed("f_spikes_2d", {-0.608, -0.939, -0.693, 0.7, 1, 0.407, 30}), -0.939000000,
                1e-09);
    EXPECT_NEAR(callNamed("f_spiral", {-0.499, 0.396, -0.453, 0.205, 0.175, 1.937, 0, 0, 0}),
                0.221000000, 1e-09);
    EXPECT_NEAR(callNamed("f_spiral", {-0.535, -0.08, 0.22, 0.205, 0.175, 1.937, 0, 0, 0}),
                -0.095000000, 1e-09);
    EXPECT_NEAR(callNamed("f_steiners_roman", {0.378, -0.203, -0.051, 0.13}), -0.001336448, 1e-09);
    EXPECT_NEAR(callNamed("f_steiners_roman", {1.441, -0.58, 0.119, 0.13}), -0.082321096, 1e-09);
    EXPECT_NEAR(callNamed("f_strophoid", {-0.361, 0.196, -0.129, 0.316, 1.619, 0.613, 1.66}),
                0.125811629, 1e-09);
    EXPECT_NEAR(callNamed("f_strophoid", {0.188, -0.396, -0.701, 0.316, 1.619, 0.613, 1.66}),
                -0.031442442, 1e-09);
    EXPECT_NEAR(callNamed("f_strophoid_2d",
                          {-0.131, -0.497, -0.491, 0.7, 1.518, 0.929, 0.661, 1, 0.071, 30}),
                0.248523578, 1e-09);
    EXPECT_NEAR(
        callNamed("f_strophoid_2d", {0.155, -1.411, 0.172, 0.7, 1.518, 0.929, 0.661, 1, 0.071, 30}),
        0.438281016, 1e-09);
    EXPECT_NEAR(callNamed("f_torus2", {-0.398, 0.064, -0.233, 0.193, 1.457, 0.518}), -0.479466271,
                1e-09);
    EXPECT_NEAR(callNamed("f_torus2", {-1.011, 1.358, 0.361, 0.193, 1.457, 0.518}), -2.653292704,
                3e-09);
    EXPECT_NEAR(callNamed("f_torus_gumdrop", {0.233, -0.175, -0.445, 0.218}), -2.566548123, 3e-09);
    EXPECT_NEAR(callNamed("f_torus_gumdrop", {-0.149, 1.243, 0.156, 0.218}), 0.956051812, 1e-09);
    EXPECT_NEAR(callNamed("f_umbrella", {-0.221, 0.299, 0.236, 0.11}), -0.003540669, 1e-09);
    EXPECT_NEAR(callNamed("f_umbrella", {0.431, 0.315, -1.08, 0.11}), 0.019982050, 1e-09);
    EXPECT_NEAR(callNamed("f_witch_of_agnesi", {0.281, 0.497, -0.2, 0.334, 1.215}), 0.184375142,
                1e-09);
    EXPECT_NEAR(callNamed("f_witch_of_agnesi", {-0.049, -0.149, 1.021, 0.334, 1.215}), 0.518273297,
                1e-09);
    EXPECT_NEAR(callNamed("f_witch_of_agnesi_2d",
                          {-0.049, -0.499, -0.363, 0.7, 1.016, 1.711, 1, -0.352, 30}),
                1.289265344, 1e-09);
    EXPECT_NEAR(
        callNamed("f_witch_of_agnesi_2d", {1.205, 0.131, 1.44, 0.7, 1.016, 1.711, 1, -0.352, 30}),
        -2.681830523, 3e-09);
    EXPECT_NEAR(
        callNamed("f_polytubes", {0.45, -0.205, 0.183, 1, -0.85, 0.162, -0.562, 0.403, -0.653}),
        1.183354481, 1e-9);
    EXPECT_NEAR(
        callNamed("f_polytubes", {-0.308, 1.182, 0.976, 1, -0.85, 0.162, -0.562, 0.403, -0.653}),
        3.044432169, 1e-9);
    EXPECT_NEAR(callNamed("f_quantum", {0.268, 0.073, 0.327, 0.127}), 1.174485594, 1e-9);
    EXPECT_NEAR(callNamed("f_quantum", {-1.238, 1.041, 0.023, 0.127}), 1.125555790, 1e-9);
    EXPECT_NEAR(callNamed("f_enneper", {-0.486, 0.425, 0.064, 0.223}), 0.007042415, 1e-9);
    EXPECT_NEAR(callNamed("f_enneper", {1.463, -1.332, 0.342, 0.223}), 0.125310435, 1e-9);
    // Near z = 0 povray divides by 0.2 instead of z; the cut is at |z| = 0.2.
    EXPECT_NEAR(callNamed("f_enneper", {0.3, 0, -0.1, 1}), 0.086993947359, 1e-9);
    EXPECT_NEAR(callNamed("f_enneper", {0.3, 0.5, 0.199999, 0.7}), 0.120146502539, 1e-9);
    EXPECT_NEAR(callNamed("f_enneper", {0.3, 0, -0.2, 1}), 0.063142839335, 1e-9);
}

TEST(InternalFunctions, NoiseGeneratorParameterIsDecodedLikePovray) {
    // povray uses the integer part's two lowest bits: 0, 1, 4, 5 original,
    // 2 range-corrected, 3 and -1 Perlin (measured).
    EXPECT_NEAR(call(78, {0.3, 0.2, 0.1, 0}), 0.209925, 1e-6);
    EXPECT_NEAR(call(78, {0.3, 0.2, 0.1, 4.5}), 0.209925, 1e-6);
    EXPECT_NEAR(call(78, {0.3, 0.2, 0.1, 2.7}), 0.373439, 1e-6);
    EXPECT_NEAR(call(78, {0.3, 0.2, 0.1, -1}), 0.578735912427, 1e-12);
    EXPECT_NEAR(call(78, {0.3, 0.2, 0.1, 3.9}), 0.578735912427, 1e-12);
    EXPECT_NEAR(callNamed("f_ridged_mf", {0.3, 0.2, 0.1, 0.5, 2, 4, 1, 2, 3}), 1.500818443464,
                1e-12);
}

TEST(InternalFunctions, UnmatchedCasesStopInsteadOfGuessing) {
    // f_mesh1 with a thread distance <= 0 behaves oddly in povray; not matched.
    EXPECT_THROW(callNamed("f_mesh1", {0.3, 0.2, 0.1, -1, 1, 1, 1, 1}), std::runtime_error);
    for (int n = 0; n < 79; ++n) {
        const InternalFunction f = internalFunction(n);
        if (!f.name.empty()) {
            EXPECT_TRUE(f.function) << f.name << " is not implemented";
        }
    }
}

TEST(InternalFunctions, CommaIsAHeadSphereWithACurledTail) {
    // Head, tail above z = 0, the z = 0 cut below, the y axis (x moved to
    // 0.0001 there), other scales including negative and zero (povray 3.7).
    EXPECT_NEAR(callNamed("f_comma", {0.3, -0.2, 0.4, 1}), -0.235341672, 1e-9);
    EXPECT_NEAR(callNamed("f_comma", {-0.7, 0.35, 0.6, 1}), 0.176526876, 1e-9);
    EXPECT_NEAR(callNamed("f_comma", {0.9, 0.1, -0.5, 1}), 0.148074070, 1e-9);
    EXPECT_NEAR(callNamed("f_comma", {-0.4, 0, -0.2, 1}), 0.385123540, 1e-9);
    EXPECT_NEAR(callNamed("f_comma", {0, 0.7, 0, 1}), 0.360174407, 1e-9);
    EXPECT_NEAR(callNamed("f_comma", {0, 0, 0, 2}), -0.000100000, 1e-9);
    EXPECT_NEAR(callNamed("f_comma", {0.6, -1.1, 0.8, 2.5}), 0.056560374, 1e-9);
    EXPECT_NEAR(callNamed("f_comma", {0.3, 0.2, 0.1, -1}), 1.330662386, 1e-9);
    EXPECT_NEAR(callNamed("f_comma", {-0.3, 0.2, 0.1, 0}), 0.374165739, 1e-9);
}

TEST(InternalFunctions, HelicalTorusMatchesPovray) {
    struct Case {
        std::vector<double> params;
        double values[5];  // at the five points below
    };
    const double points[5][3] = {
        {0.8, 0.2, 0.5}, {-0.3, -0.25, -1.1}, {0.9, -0.3, -0.2}, {-0.5, 0.1, 0.8}, {0, 0, 0}};
    const Case cases[] = {
        {{1, 3, 1, 0.1, 0.05, 0.35, 0.8, 4, 0.1, 0.6},
         {0.327410168, 0.672274751, 0.497071442, 0.444609788, 0.541221475}},
        {{1.2, 2.5, 0.7, 0.15, 0, 0.3, 1.3, 3, 0.2, 0.3},
         {0.710941286, 0.084000042, 0.345810738, 0.540122522, 0.823785680}},
        // No windings: the groove alone, phase 1.
        {{1, 0, 0, 0.2, 0, 0, 0, 5, 0.1, 1},
         {0.350364315, 0.140035217, 0.422941110, -0.071108900, 0.800238266}},
        // Negative windings and second fatness (a NaN radicand).
        {{0.75, -1, 0, 0.1, 0.13, 0.23, -0.95, 0, 0.04, -0.88},
         {1.333398113, 1.530175425, 1.311954446, 1.333398113, 0.390000000}},
    };
    for (const Case& c : cases) {
        for (int i = 0; i < 5; ++i) {
            std::vector<double> args = {points[i][0], points[i][1], points[i][2]};
            args.insert(args.end(), c.params.begin(), c.params.end());
            EXPECT_NEAR(callNamed("f_helical_torus", args), c.values[i], 1e-9)
                << "point " << i << " parameters " << c.params[0] << ", " << c.params[1];
        }
    }
}

}  // namespace
}  // namespace frameray::scene
