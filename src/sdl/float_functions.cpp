#include "sdl/float_functions.h"

#include <cmath>
#include <numbers>
#include <utility>

namespace frameray::sdl {

namespace {

constexpr std::pair<Keyword, UnaryFloatFunction> kUnary[] = {
    {Keyword::kw_abs, [](double a) { return std::fabs(a); }},
    {Keyword::kw_acos, [](double a) { return std::acos(a); }},
    {Keyword::kw_acosh, [](double a) { return std::acosh(a); }},
    {Keyword::kw_asin, [](double a) { return std::asin(a); }},
    {Keyword::kw_asinh, [](double a) { return std::asinh(a); }},
    {Keyword::kw_atan, [](double a) { return std::atan(a); }},
    {Keyword::kw_atanh, [](double a) { return std::atanh(a); }},
    {Keyword::kw_ceil, [](double a) { return std::ceil(a); }},
    {Keyword::kw_cos, [](double a) { return std::cos(a); }},
    {Keyword::kw_cosh, [](double a) { return std::cosh(a); }},
    {Keyword::kw_degrees, [](double a) { return a * 180.0 / std::numbers::pi; }},
    {Keyword::kw_exp, [](double a) { return std::exp(a); }},
    {Keyword::kw_floor, [](double a) { return std::floor(a); }},
    // int() and div() convert through an integer in povray, so they never
    // give -0 (str(int(-0.5),0,2) is "0.00"); adding +0 turns -0 into +0.
    {Keyword::kw_int, [](double a) { return std::trunc(a) + 0.0; }},
    {Keyword::kw_ln, [](double a) { return std::log(a); }},
    {Keyword::kw_log, [](double a) { return std::log10(a); }},
    {Keyword::kw_radians, [](double a) { return a * std::numbers::pi / 180.0; }},
    {Keyword::kw_sin, [](double a) { return std::sin(a); }},
    {Keyword::kw_sinh, [](double a) { return std::sinh(a); }},
    {Keyword::kw_sqr, [](double a) { return a * a; }},
    {Keyword::kw_sqrt, [](double a) { return std::sqrt(a); }},
    {Keyword::kw_tan, [](double a) { return std::tan(a); }},
    {Keyword::kw_tanh, [](double a) { return std::tanh(a); }},
};

constexpr std::pair<Keyword, BinaryFloatFunction> kBinary[] = {
    {Keyword::kw_atan2, [](double a, double b) { return std::atan2(a, b); }},
    {Keyword::kw_pow, [](double a, double b) { return std::pow(a, b); }},
    {Keyword::kw_mod, [](double a, double b) { return std::fmod(a, b); }},
    {Keyword::kw_div, [](double a, double b) { return std::trunc(a / b) + 0.0; }},
};

}  // namespace

UnaryFloatFunction unaryFloatFunction(Keyword kw) {
    for (const auto& [k, f] : kUnary)
        if (k == kw) return f;
    return nullptr;
}

BinaryFloatFunction binaryFloatFunction(Keyword kw) {
    for (const auto& [k, f] : kBinary)
        if (k == kw) return f;
    return nullptr;
}

}  // namespace frameray::sdl
