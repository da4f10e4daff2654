// Compiled user functions: a small stack machine. The scene language's
// `function { ... }` bodies are compiled once (sdl/functions.cpp) into this
// form, which is cheap to evaluate millions of times (isosurfaces, function
// patterns) and has no knowledge of the language.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace frameray {

enum class FnOp : uint8_t {
    Const,  // push value
    Param,  // push parameter a
    Slot,   // push loop variable in slot a
    Add,
    Sub,
    Mul,
    Div,
    Neg,
    Not,
    Lt,
    Le,
    Eq,
    Ne,
    Ge,
    Gt,
    And,
    Or,
    Unary,    // replace top by unary(top)
    Binary,   // pop b, a; push binary(a, b)
    Call,     // pop b arguments; push callees[a](args)
    Select3,  // pop c, b, a: a < 0 ? b : c
    Select4,  // pop d, c, b, a: a < 0 ? b : (a == 0 ? c : d)
    MinN,
    MaxN,         // pop a values, push their min/max
    JumpIfFalse,  // pop; jump to a when zero
    Jump,         // jump to a
    LoopInit,  // pop end, start into slots a (variable) and a+1 (end); push b (0 sum / 1 product)
    LoopTest,  // jump to b when slot a > slot a+1
    LoopSum,   // pop v; top += v
    LoopProd,  // pop v; top *= v
    LoopNext,  // slot a += 1; jump to b
    Native,    // push natives[a](the running function's own arguments)
    Internal,  // a function that cannot run yet (throws); b arguments were pushed
};

struct FnInstr {
    FnOp op;
    int32_t a = 0;
    int32_t b = 0;
    double value = 0;
    double (*unary)(double) = nullptr;
    double (*binary)(double, double) = nullptr;
};

// A function written in C++ rather than compiled from the language: the
// functions.inc internals and `function { pattern { ... } }`. It reads the
// arguments of the compiled function whose body it is.
class NativeFunction {
  public:
    virtual ~NativeFunction() = default;
    virtual double eval(const double* args) const = 0;
    // Why a call with these arguments cannot run yet (empty: it can),
    // judged from the arguments known when the call is compiled (known[i]
    // false: args[i] is not a constant). Lets a function body that could
    // only fail mid-render stop at parse time instead.
    virtual std::string unsupportedWith(const double* /*args*/, const bool* /*known*/) const {
        return {};
    }
};

class CompiledFunction {
  public:
    static constexpr int kMaxStack = 256;
    static constexpr int kMaxSlots = 64;

    std::string name;
    int paramCount = 0;
    int slotCount = 0;
    std::vector<FnInstr> code;
    std::vector<std::shared_ptr<const CompiledFunction>> callees;
    std::vector<std::shared_ptr<const NativeFunction>> natives;
    // Instructions one evaluation runs, counting each call as the callee's
    // own count (each sum/prod loop body once): calls of calls multiply, so
    // a chain of functions each calling the previous one twice reaches
    // 2^40 in 40 lines. Set by the compiler (countOperations).
    double operations = 0;
    // Why this function (or one it calls) cannot run yet: empty when it
    // can. Shapes check it before rendering so no frame stops midway.
    std::string unavailable;
    // functions.inc's f_noise3d follows global_settings' noise_generator,
    // which povray applies whatever the order: this function is f_noise3d
    // (noiseInternal, its internal number, >= 0) or calls it, so the parser
    // binds the generator when the function is used (sdl/functions.cpp).
    bool followsNoiseGenerator = false;
    int noiseInternal = -1;

    // Evaluates with `paramCount` arguments. Throws std::runtime_error for
    // a call of a function that cannot run yet.
    double eval(const double* args) const;
    // Sets `operations` from the code and the callees' counts.
    void countOperations();
};

}  // namespace frameray
