// Values the interpreter computes and binds to identifiers.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "scene/atmosphere.h"
#include "scene/camera.h"
#include "scene/lights.h"
#include "scene/object.h"
#include "scene/texture.h"
#include "sdl/object_value.h"
#include "sdl/token.h"

namespace frameray::sdl {

// Vectors of 2 to 5 components and colours (5 components: r g b filter
// transmit). Floats are promoted to these where a vector is expected.
struct VectorValue {
    std::array<double, 5> v{};
    uint8_t size = 3;
    bool isColor = false;

    Vec3 xyz() const { return {v[0], v[1], v[2]}; }
    Color color() const { return Color(RGB(v[0], v[1], v[2]), v[3], v[4]); }
    static VectorValue fromVec3(const Vec3& p) { return {{p.x, p.y, p.z, 0, 0}, 3, false}; }
    static VectorValue fromColor(const Color& c) {
        return {{c.rgb.r, c.rgb.g, c.rgb.b, c.filter, c.transmit}, 5, true};
    }
};

// A macro: where its body starts (just after the parameter list) in which
// tokenized file, and its parameter names.
struct Macro {
    std::string name;
    std::shared_ptr<const TokenizedFile> file;
    size_t bodyStart = 0;
    std::vector<std::string> params;
    SourceLoc loc;
};

using ObjectPtr = std::shared_ptr<const ObjectValue>;  // object_value.h
using PigmentPtr = std::shared_ptr<const scene::Pigment>;
using FinishPtr = std::shared_ptr<const scene::Finish>;
using TexturePtr = std::shared_ptr<const scene::Texture>;
using CameraPtr = std::shared_ptr<const scene::Camera>;
using LightPtr = std::shared_ptr<const scene::Light>;
using MacroPtr = std::shared_ptr<const Macro>;
using TransformPtr = std::shared_ptr<const Transform>;
using FogPtr = std::shared_ptr<const scene::Fog>;
using SkySpherePtr = std::shared_ptr<const scene::SkySphere>;
using InteriorPtr = std::shared_ptr<const scene::Interior>;
using NormalPtr = std::shared_ptr<const scene::Normal>;  // null: normal { } without a pattern

// `material { texture { } interior { } }`: what it gives an object. An
// unset part leaves the object's own.
struct MaterialValue {
    TexturePtr texture;
    InteriorPtr interior;
};
using MaterialPtr = std::shared_ptr<const MaterialValue>;
using MediaPtr = std::shared_ptr<const scene::Media>;
// density { }: a pigment-like pattern, kept apart from pigments so that a
// declared density is only accepted where a density is.
struct DensityValue {
    PigmentPtr pigment;
};
using DensityPtr = std::shared_ptr<const DensityValue>;

class ArrayValue;
struct FileHandle;
struct SplineValue;
struct FunctionValue;
struct BlendMapValue;  // blend_map_value.h
using ArrayPtr = std::shared_ptr<ArrayValue>;
using FilePtr = std::shared_ptr<FileHandle>;
using SplinePtr = std::shared_ptr<const SplineValue>;
using FunctionPtr = std::shared_ptr<const FunctionValue>;
using BlendMapPtr = std::shared_ptr<const BlendMapValue>;

// The value of spline `s` at `x`, with the spline's own type (splines.cpp).
VectorValue splineAt(const SplineValue& s, double x);

// A macro parameter passed as a bare identifier: the parameter names the
// caller's identifier `name` in symbol table `scope` (by reference), so
// the macro can read it and assign it, even create it.
struct IdentifierAlias {
    size_t scope = 0;
    std::string name;
};

using Value =
    std::variant<std::monostate, double, VectorValue, std::string, ObjectPtr, PigmentPtr, FinishPtr,
                 TexturePtr, CameraPtr, LightPtr, MacroPtr, TransformPtr, ArrayPtr, FilePtr,
                 SplinePtr, FunctionPtr, IdentifierAlias, FogPtr, SkySpherePtr, InteriorPtr,
                 BlendMapPtr, NormalPtr, MaterialPtr, MediaPtr, DensityPtr>;

// Arrays of up to five dimensions. Elements start unset; once one is set,
// every other must have the same kind (seed: "all other elements can only
// be defined as that type"). Float elements, the kind of the largest
// arrays scenes make, are kept unboxed (8 bytes and a bit each, as povray
// keeps them) instead of as 56-byte Values; the storage for a kind is
// made when the first element of it is set.
class ArrayValue {
  public:
    std::vector<int> dims;

    // Sets the element count; every element unset.
    void reset(size_t count) {
        size_ = count;
        kind_ = nullptr;
        std::vector<double>().swap(floats_);
        std::vector<bool>().swap(floatSet_);
        std::vector<Value>().swap(values_);
    }
    size_t size() const { return size_; }
    // valueKindName of the elements set so far; null while none is set.
    const char* kind() const { return kind_; }
    bool isSet(size_t i) const {
        return values_.empty() ? !floatSet_.empty() && floatSet_[i]
                               : !std::holds_alternative<std::monostate>(values_[i]);
    }
    // Element i (monostate while unset).
    Value get(size_t i) const {
        if (!values_.empty()) return values_[i];
        if (!floatSet_.empty() && floatSet_[i]) return floats_[i];
        return {};
    }
    // The first element set, in row-major order (none: monostate).
    Value firstSet() const {
        for (size_t i = 0; i < size_; ++i)
            if (isSet(i)) return get(i);
        return {};
    }
    // Stores element i; the caller has checked `value`'s kind against kind().
    void set(size_t i, Value value);

  private:
    size_t size_ = 0;
    const char* kind_ = nullptr;
    std::vector<double> floats_;  // float elements, while values_ is empty
    std::vector<bool> floatSet_;
    std::vector<Value> values_;  // elements of any other kind
};

// Whether `v` is an array whose elements hold a T. Elements are all of one
// kind, so the first one set tells (an array of arrays: its innermost).
template <typename T>
bool arrayHolds(const Value& v) {
    const auto* array = std::get_if<ArrayPtr>(&v);
    if (!array || !*array || !(*array)->kind()) return false;
    const Value first = (*array)->firstSet();
    return std::holds_alternative<T>(first) || arrayHolds<T>(first);
}

// "float", "vector", "object"... for messages.
const char* valueKindName(const Value& v);

}  // namespace frameray::sdl
