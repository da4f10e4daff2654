// Values of the scene language: their names in messages.
#include "sdl/value.h"

#include "sdl/blend_map_value.h"

namespace frameray::sdl {

const char* valueKindName(const Value& v) {
    struct Namer {
        const char* operator()(std::monostate) const { return "nothing"; }
        const char* operator()(double) const { return "float"; }
        const char* operator()(const VectorValue& vec) const {
            return vec.isColor ? "color" : "vector";
        }
        const char* operator()(const std::string&) const { return "string"; }
        const char* operator()(const ObjectPtr&) const { return "object"; }
        const char* operator()(const PigmentPtr&) const { return "pigment"; }
        const char* operator()(const FinishPtr&) const { return "finish"; }
        const char* operator()(const TexturePtr&) const { return "texture"; }
        const char* operator()(const CameraPtr&) const { return "camera"; }
        const char* operator()(const LightPtr&) const { return "light_source"; }
        const char* operator()(const MacroPtr&) const { return "macro"; }
        const char* operator()(const TransformPtr&) const { return "transform"; }
        const char* operator()(const ArrayPtr&) const { return "array"; }
        const char* operator()(const FilePtr&) const { return "file identifier"; }
        const char* operator()(const SplinePtr&) const { return "spline"; }
        const char* operator()(const FunctionPtr&) const { return "function"; }
        const char* operator()(const IdentifierAlias&) const { return "identifier"; }
        const char* operator()(const FogPtr&) const { return "fog"; }
        const char* operator()(const SkySpherePtr&) const { return "sky_sphere"; }
        const char* operator()(const InteriorPtr&) const { return "interior"; }
        const char* operator()(const BlendMapPtr& m) const { return m->kindName(); }
        const char* operator()(const NormalPtr&) const { return "normal"; }
        const char* operator()(const MaterialPtr&) const { return "material"; }
        const char* operator()(const MediaPtr&) const { return "media"; }
        const char* operator()(const DensityPtr&) const { return "density"; }
    };
    return std::visit(Namer{}, v);
}

void ArrayValue::set(size_t i, Value value) {
    if (std::holds_alternative<std::monostate>(value)) {  // unset it again
        if (!values_.empty())
            values_[i] = std::move(value);
        else if (!floatSet_.empty())
            floatSet_[i] = false;
        return;
    }
    if (!kind_) kind_ = valueKindName(value);
    if (const double* f = std::get_if<double>(&value); f && values_.empty()) {
        if (floats_.empty()) {
            floats_.assign(size_, 0.0);
            floatSet_.assign(size_, false);
        }
        floats_[i] = *f;
        floatSet_[i] = true;
        return;
    }
    if (values_.empty()) {
        // The first element not a float (the kind check lets that happen
        // only while no float is set): every element becomes a Value.
        values_.resize(size_);
        for (size_t k = 0; k < floatSet_.size(); ++k)
            if (floatSet_[k]) values_[k] = floats_[k];
        std::vector<double>().swap(floats_);  // freed, not only emptied
        std::vector<bool>().swap(floatSet_);
    }
    values_[i] = std::move(value);
}

}  // namespace frameray::sdl
