// What the reader (reader.h) asks of the statement builders: the values
// scene items make where the language core meets them (#declare, macro
// arguments, #default, pattern functions). builders.cpp implements it
// over the builder table.
#pragma once

#include <optional>

#include "sdl/token.h"
#include "sdl/value.h"

namespace frameray::sdl {

class ValueBuilders {
  public:
    virtual ~ValueBuilders() = default;
    // The value the item starting at `keyword` (peek()) makes: an object,
    // a pigment, a camera...; nullopt when no builder makes a value of it.
    virtual std::optional<Value> buildValue(const Token& keyword) = 0;
    // #default { ... }, after `#default`.
    virtual void defaultDirective() = 0;
    // function { pattern { ... } }, at `pattern`; the function body's '}'
    // is left to the caller.
    virtual Value patternFunction() = 0;
    // Whether the scene holds an object yet (#version warns after one).
    virtual bool sceneHasObjects() const = 0;
};

}  // namespace frameray::sdl
