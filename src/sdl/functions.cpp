// User-defined functions: `function [(params)] { float expression }`
// compiled into util/function_vm's stack machine, and calls to them.
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "scene/internal_functions.h"
#include "scene/patterns.h"
#include "scene/texture.h"
#include "sdl/float_functions.h"
#include "sdl/function_value.h"
#include "sdl/reader.h"
#include "sdl/value_builders.h"

namespace frameray::sdl {

std::shared_ptr<CompiledFunction> nativeBody(std::string name, int paramCount,
                                             std::shared_ptr<const NativeFunction> native) {
    auto fn = std::make_shared<CompiledFunction>();
    fn->name = std::move(name);
    fn->paramCount = paramCount;
    fn->natives.push_back(std::move(native));
    fn->code.push_back({FnOp::Native, 0});
    fn->countOperations();
    return fn;
}

namespace {

// One component (or .gray) of a vector-valued function.
class VectorComponent final : public NativeFunction {
  public:
    VectorComponent(std::shared_ptr<const VectorFunction> vector, int slot)
        : vector_(std::move(vector)), slot_(slot) {}
    int paramCount() const { return vector_->paramCount; }
    double eval(const double* args) const override {
        const std::array<double, 5> v = vector_->eval(args);
        return slot_ == kGrayItem ? grey(v[0], v[1], v[2]) : v[static_cast<size_t>(slot_)];
    }

  private:
    std::shared_ptr<const VectorFunction> vector_;
    int slot_;
};

}  // namespace

// Recursive-descent compiler over the reader's token stream, with the
// same precedence as parse-time expressions.
class FunctionCompiler {
  public:
    FunctionCompiler(Reader& in, std::vector<std::string> params)
        : in_(in), params_(std::move(params)) {
        fn_->paramCount = static_cast<int>(params_.size());
    }

    std::shared_ptr<CompiledFunction> compileBody() {
        ternary();
        fn_->slotCount = maxSlots_;
        fn_->countOperations();
        return fn_;
    }

  private:
    size_t emit(FnInstr i, int stackEffect) {
        depth_ += stackEffect;
        maxDepth_ = std::max(maxDepth_, depth_);
        if (maxDepth_ > CompiledFunction::kMaxStack)
            in_.failHere("function expression is too deeply nested");
        fn_->code.push_back(i);
        return fn_->code.size() - 1;
    }
    size_t here() const { return fn_->code.size(); }

    void ternary() {
        logical();
        if (!in_.peek().is(Sym::Question)) return;
        in_.next();
        const size_t jumpFalse = emit({FnOp::JumpIfFalse}, -1);
        ternary();
        const size_t jumpEnd = emit({FnOp::Jump}, 0);
        in_.expect(Sym::Colon, "':' of the conditional expression");
        fn_->code[jumpFalse].a = static_cast<int32_t>(here());
        depth_ -= 1;  // only one branch's value is on the stack at run time
        ternary();
        fn_->code[jumpEnd].a = static_cast<int32_t>(here());
    }

    // In function bodies '&' binds tighter than '|' (povray 3.7).
    void logical() {
        logicalAnd();
        while (in_.peek().is(Sym::Bar)) {
            in_.next();
            logicalAnd();
            emit({FnOp::Or}, -1);
        }
    }

    void logicalAnd() {
        relational();
        while (in_.peek().is(Sym::Amp)) {
            in_.next();
            relational();
            emit({FnOp::And}, -1);
        }
    }

    void relational() {
        additive();
        for (;;) {
            const Token op = in_.peek();
            FnOp code;
            switch (op.sym) {
                case Sym::Less:
                    code = FnOp::Lt;
                    break;
                case Sym::LessEq:
                    code = FnOp::Le;
                    break;
                case Sym::Equal:
                    code = FnOp::Eq;
                    break;
                case Sym::NotEq:
                    code = FnOp::Ne;
                    break;
                case Sym::GreaterEq:
                    code = FnOp::Ge;
                    break;
                case Sym::Greater:
                    code = FnOp::Gt;
                    break;
                default:
                    return;
            }
            if (op.kind != TokenKind::Symbol) return;
            in_.next();
            additive();
            emit({code}, -1);
        }
    }

    void additive() {
        multiplicative();
        for (;;) {
            const Token op = in_.peek();
            if (!op.is(Sym::Plus) && !op.is(Sym::Minus)) return;
            in_.next();
            multiplicative();
            emit({op.is(Sym::Plus) ? FnOp::Add : FnOp::Sub}, -1);
        }
    }

    void multiplicative() {
        unary();
        for (;;) {
            const Token op = in_.peek();
            if (!op.is(Sym::Star) && !op.is(Sym::Slash)) return;
            in_.next();
            unary();
            emit({op.is(Sym::Star) ? FnOp::Mul : FnOp::Div}, -1);
        }
    }

    void unary() {
        const Token op = in_.peek();
        const Reader::NestingGuard nesting(in_, op);
        if (op.is(Sym::Minus) || op.is(Sym::Plus) || op.is(Sym::Bang)) {
            in_.next();
            unary();
            if (op.is(Sym::Minus)) emit({FnOp::Neg}, 0);
            if (op.is(Sym::Bang)) emit({FnOp::Not}, 0);
            return;
        }
        primary();
    }

    void constant(double v) { emit({FnOp::Const, 0, 0, v}, +1); }

    // Arguments in parentheses, each compiled onto the stack.
    // With `starts`, also the first instruction of each argument.
    int arguments(const Token& fn, std::vector<size_t>* starts = nullptr) {
        in_.expectAfter(Sym::LParen, "'('", fn.text);
        int n = 0;
        if (!in_.peek().is(Sym::RParen)) {
            do {
                if (starts) starts->push_back(here());
                ternary();
                ++n;
            } while (in_.accept(Sym::Comma));
        }
        in_.expect(Sym::RParen, "')'");
        return n;
    }

    // A native body's reason to refuse these arguments, from the ones that
    // compiled to a constant (`c` or `-c`); empty for other callees.
    std::string nativeRefusal(const CompiledFunction& callee, const std::vector<size_t>& starts) {
        if (callee.code.size() != 1 || callee.code[0].op != FnOp::Native) return {};
        std::vector<double> args(starts.size(), 0.0);
        std::unique_ptr<bool[]> known(new bool[starts.size()]());
        for (size_t i = 0; i < starts.size(); ++i) {
            const size_t end = i + 1 < starts.size() ? starts[i + 1] : here();
            const std::vector<FnInstr>& code = fn_->code;
            if (end == starts[i] + 1 && code[starts[i]].op == FnOp::Const) {
                args[i] = code[starts[i]].value;
                known[i] = true;
            } else if (end == starts[i] + 2 && code[starts[i]].op == FnOp::Const &&
                       code[starts[i] + 1].op == FnOp::Neg) {
                args[i] = -code[starts[i]].value;
                known[i] = true;
            }
        }
        if (static_cast<int>(args.size()) < callee.paramCount) return {};
        return callee.natives[0]->unsupportedWith(args.data(), known.get());
    }

    void requireArgs(const Token& fn, int n, int min, int max) {
        if (n < min || n > max)
            in_.fail(fn, min == max ? fmt::format("'{}' takes {} argument{}, {} given", fn.text,
                                                  min, min == 1 ? "" : "s", n)
                                    : fmt::format("'{}' takes {} to {} arguments, {} given",
                                                  fn.text, min, max, n));
    }

    // x and u name the same parameter, as do y and v (povray 3.7).
    int paramIndex(std::string_view name) const {
        auto alias = [](std::string_view n) -> std::string_view {
            if (n == "u") return "x";
            if (n == "v") return "y";
            return n;
        };
        for (size_t i = 0; i < params_.size(); ++i)
            if (alias(params_[i]) == alias(name)) return static_cast<int>(i);
        return -1;
    }

    void primary() {
        const Token t = in_.peek();
        if (t.kind == TokenKind::Number) {
            in_.next();
            constant(t.number);
            return;
        }
        if (t.is(Sym::LParen)) {
            in_.next();
            ternary();
            in_.expect(Sym::RParen, "')'");
            return;
        }
        if (t.kind != TokenKind::Word)
            in_.fail(t, fmt::format("expected a function expression, found {}", describeToken(t)));
        if (const int p = paramIndex(t.text); p >= 0) {
            in_.next();
            emit({FnOp::Param, p}, +1);
            return;
        }
        if (t.kw == Keyword::None) {
            identifier(t);
            return;
        }
        keyword(t);
    }

    void identifier(const Token& t) {
        for (auto it = loopVars_.rbegin(); it != loopVars_.rend(); ++it)
            if (it->first == t.text) {
                in_.next();
                emit({FnOp::Slot, it->second}, +1);
                return;
            }
        const Value* v = in_.lookup(t);
        if (v && std::holds_alternative<FunctionPtr>(*v)) {
            const FunctionPtr callee = std::get<FunctionPtr>(*v);
            in_.next();
            std::vector<size_t> starts;
            const int n = arguments(t, &starts);
            if (!callee->unsupported.empty()) {
                // Calling it compiles an instruction that fails when run.
                if (fn_->unavailable.empty()) fn_->unavailable = callee->unsupported;
                emit({FnOp::Internal, -1, n}, 1 - n);
                return;
            }
            if (callee->vector) return vectorComponentCall(t, callee->vector, n);
            if (!callee->variadic)
                requireArgs(t, n, callee->compiled->paramCount, callee->compiled->paramCount);
            if (fn_->unavailable.empty()) fn_->unavailable = callee->compiled->unavailable;
            if (fn_->unavailable.empty())
                fn_->unavailable = nativeRefusal(*callee->compiled, starts);
            fn_->callees.push_back(callee->compiled);
            if (callee->compiled->followsNoiseGenerator) fn_->followsNoiseGenerator = true;
            emit({FnOp::Call, static_cast<int32_t>(fn_->callees.size() - 1), n}, 1 - n);
            return;
        }
        // Any other identifier is a constant taken at declaration time.
        const Token at = in_.peek();
        const Value value = in_.parsePostfix();
        const double* f = std::get_if<double>(&value);
        if (!f)
            in_.fail(at, fmt::format("'{}' is a {}; a function body needs floats", at.text,
                                     valueKindName(value)));
        constant(*f);
    }

    void keyword(const Token& t) {
        if (const UnaryFloatFunction op = unaryFloatFunction(t.kw)) {
            in_.next();
            requireArgs(t, arguments(t), 1, 1);
            emit({FnOp::Unary, 0, 0, 0, op}, 0);
            return;
        }
        if (const BinaryFloatFunction op = binaryFloatFunction(t.kw)) {
            in_.next();
            requireArgs(t, arguments(t), 2, 2);
            FnInstr i{FnOp::Binary};
            i.binary = op;
            emit(i, -1);
            return;
        }
        switch (t.kw) {
            case Keyword::kw_x:
            case Keyword::kw_u:
            case Keyword::kw_y:
            case Keyword::kw_v:
            case Keyword::kw_z:
                in_.fail(t, fmt::format("'{}' is not a parameter of this function", t.text));
            case Keyword::kw_min:
            case Keyword::kw_max: {
                in_.next();
                const int n = arguments(t);
                requireArgs(t, n, 1, 64);
                emit({t.kw == Keyword::kw_min ? FnOp::MinN : FnOp::MaxN, n}, 1 - n);
                return;
            }
            case Keyword::kw_select: {
                in_.next();
                const int n = arguments(t);
                requireArgs(t, n, 3, 4);
                emit({n == 3 ? FnOp::Select3 : FnOp::Select4}, 1 - n);
                return;
            }
            case Keyword::kw_sum:
            case Keyword::kw_prod:
                loop(t);
                return;
            case Keyword::kw_internal:
                in_.fail(t, "'internal' must be a function's whole body");
            default:
                break;
        }
        // Constant keywords (pi, clock, image_width, true...) evaluate now.
        const Value value = in_.parsePostfix();
        const double* f = std::get_if<double>(&value);
        if (!f) in_.unsupported(t, fmt::format("'{}' in a function", t.text));
        constant(*f);
    }

    // F(args).item for a vector-valued F: a native callee giving that one
    // component (or .gray of a colour).
    void vectorComponentCall(const Token& t, std::shared_ptr<const VectorFunction> vector, int n) {
        requireArgs(t, n, vector->paramCount, vector->paramCount);
        if (!in_.peek().is(Sym::Dot))
            in_.fail(t, fmt::format(
                            "'{}' is a {} function and gives a {}; inside a function take one "
                            "component ('{}(...).x', '.red', '.gray' ...)",
                            t.text, vector->kind, vector->isColor ? "colour" : "vector", t.text));
        in_.next();
        const Token item = in_.next();
        const int slot = dotItemSlot(item.kw);
        if (slot < 0) in_.fail(item, fmt::format("'{}' is not a vector component", item.text));
        if (slot != kGrayItem && slot >= vector->size)
            in_.fail(item, fmt::format("'.{}' is beyond this {}-component vector", item.text,
                                       vector->size));
        auto native = std::make_shared<VectorComponent>(std::move(vector), slot);
        const int params = native->paramCount();
        fn_->callees.push_back(
            nativeBody(fmt::format("{}.{}", t.text, item.text), params, std::move(native)));
        emit({FnOp::Call, static_cast<int32_t>(fn_->callees.size() - 1), n}, 1 - n);
    }

    // sum(I, Start, End, Expr) and prod(...): I runs from Start to End by 1.
    void loop(const Token& t) {
        in_.next();
        in_.expect(Sym::LParen, "'('");
        const Token var = in_.next();
        if (var.kind != TokenKind::Word) in_.fail(var, "expected the loop variable's name");
        in_.expect(Sym::Comma, "','");
        ternary();
        in_.expect(Sym::Comma, "','");
        ternary();
        in_.expect(Sym::Comma, "','");
        const int slot = slots_;
        slots_ += 2;
        maxSlots_ = std::max(maxSlots_, slots_);
        if (maxSlots_ > CompiledFunction::kMaxSlots) in_.fail(t, "too many nested sum/prod loops");
        emit({FnOp::LoopInit, slot, t.kw == Keyword::kw_sum ? 0 : 1}, -1);
        const size_t test = emit({FnOp::LoopTest, slot}, 0);
        loopVars_.emplace_back(std::string(var.text), slot);
        ternary();
        loopVars_.pop_back();
        emit({t.kw == Keyword::kw_sum ? FnOp::LoopSum : FnOp::LoopProd}, -1);
        emit({FnOp::LoopNext, slot, static_cast<int32_t>(test)}, 0);
        fn_->code[test].b = static_cast<int32_t>(here());
        slots_ -= 2;
        in_.expect(Sym::RParen, "')'");
    }

    Reader& in_;
    std::vector<std::string> params_;
    std::shared_ptr<CompiledFunction> fn_ = std::make_shared<CompiledFunction>();
    int depth_ = 0, maxDepth_ = 0;
    int slots_ = 0, maxSlots_ = 0;
    std::vector<std::pair<std::string, int>> loopVars_;
};

Value Reader::parseFunctionDeclaration() {
    next();  // function
    std::vector<std::string> params;
    if (accept(Sym::LParen)) {
        do {
            const Token p = next();
            if (p.kind != TokenKind::Word)
                fail(p, fmt::format("expected a parameter name, found {}", describeToken(p)));
            params.emplace_back(p.text);
        } while (accept(Sym::Comma));
        expect(Sym::RParen, "')'");
    } else {
        params = {"x", "y", "z"};
    }
    return parseFunctionBody(std::move(params));
}

Value Reader::parseFunctionBody(std::vector<std::string> params) {
    expect(Sym::LBrace, "'{' starting the function body");
    auto value = std::make_shared<FunctionValue>();
    const Token first = peek();
    if (first.is(Keyword::kw_internal)) return parseInternalFunctionBody();
    if (first.is(Keyword::kw_pattern)) return builders_->patternFunction();
    if (first.is(Keyword::kw_pigment) || first.is(Keyword::kw_transform) ||
        first.is(Keyword::kw_spline)) {
        value->vector = parseVectorFunctionBody();
        expect(Sym::RBrace, "'}' closing the function body");
        return FunctionPtr(value);
    }
    FunctionCompiler compiler(*this, std::move(params));
    auto compiled = compiler.compileBody();
    compiled->name = "function";
    value->compiled = std::move(compiled);
    expect(Sym::RBrace, "'}' closing the function body");
    return FunctionPtr(value);
}

std::shared_ptr<const VectorFunction> Reader::parseVectorFunctionBody() {
    auto fn = std::make_shared<VectorFunction>();
    const Token first = peek();
    fn->kind = std::string(first.text);
    if (first.is(Keyword::kw_pigment)) {
        const std::optional<Value> built = builders_->buildValue(first);
        const PigmentPtr pigment = std::get<PigmentPtr>(*built);
        if (pigment->uvMapping()) unsupported(first, "a uv_mapping pigment in a function");
        fn->size = 5;
        fn->isColor = true;
        fn->eval = [pigment](const double* a) {
            const Color c = pigment->at({a[0], a[1], a[2]});
            return std::array<double, 5>{c.rgb.r, c.rgb.g, c.rgb.b, c.filter, c.transmit};
        };
    } else if (first.is(Keyword::kw_transform)) {
        const Transform transform = parseTransformBlock();
        fn->eval = [transform](const double* a) {
            const Vec3 p = transform.point({a[0], a[1], a[2]});
            return std::array<double, 5>{p.x, p.y, p.z, 0, 0};
        };
    } else {
        const Value spline = parseSpline();
        const SplinePtr s = std::get<SplinePtr>(spline);
        fn->paramCount = 1;
        fn->size = splineAt(*s, 0).size;
        fn->eval = [s](const double* a) { return splineAt(*s, a[0]).v; };
    }
    return fn;
}

Value Reader::callVectorFunction(const VectorFunction& function, const Token& at) {
    const std::vector<Value> args = parseArguments(0, 64, at);
    if (static_cast<int>(args.size()) != function.paramCount)
        fail(at, fmt::format("'{}' takes {} argument{}, {} given", at.text, function.paramCount,
                             function.paramCount == 1 ? "" : "s", args.size()));
    std::vector<double> values;
    values.reserve(args.size());
    for (const Value& v : args) values.push_back(toFloat(v, at));
    VectorValue out;
    out.v = function.eval(values.data());
    out.size = static_cast<uint8_t>(function.size);
    out.isColor = function.isColor;
    return out;
}

// Skips tokens until `depth` open braces have closed.
void Reader::skipToClosingBrace(const Token& from, int depth) {
    while (depth > 0) {
        const Token t = next();
        if (t.kind == TokenKind::End) fail(from, "function body is never closed");
        if (t.is(Sym::LBrace)) ++depth;
        if (t.is(Sym::RBrace)) --depth;
    }
}

// function { internal(N) }: functions.inc's built-ins, taking x, y, z and
// their own extra parameters.
Value Reader::parseInternalFunctionBody() {
    FunctionValue value;
    const Token at = next();  // internal
    expect(Sym::LParen, "'(' after 'internal'");
    const double n = parseFloat();
    expect(Sym::RParen, "')'");
    expect(Sym::RBrace, "'}' closing the function body");
    const scene::InternalFunction internal = scene::internalFunction(static_cast<int>(n));
    if (internal.name.empty()) fail(at, fmt::format("there is no internal function {}", n));
    if (!internal.function) {
        // Declaring it is fine (functions.inc declares them all); using it
        // stops with `not supported yet`.
        value.unsupported = fmt::format("functions.inc function {}", internal.name);
        value.variadic = true;
        return FunctionPtr(std::make_shared<FunctionValue>(value));
    }
    auto compiled = nativeBody(internal.name, 3 + internal.extraParams, internal.function);
    if (internal.name == "f_noise3d") {
        compiled->followsNoiseGenerator = true;
        compiled->noiseInternal = static_cast<int>(n);
    }
    value.compiled = std::move(compiled);
    return FunctionPtr(std::make_shared<FunctionValue>(value));
}

namespace {

// `function` with every f_noise3d it calls bound to generator g (a copy
// where anything changes).
std::shared_ptr<const CompiledFunction> withNoiseGenerator(
    const std::shared_ptr<const CompiledFunction>& function, scene::NoiseGenerator g) {
    if (!function->followsNoiseGenerator) return function;
    auto bound = std::make_shared<CompiledFunction>(*function);
    if (function->noiseInternal >= 0) {
        bound->natives = {scene::internalFunction(function->noiseInternal, g).function};
        return bound;
    }
    for (auto& callee : bound->callees) callee = withNoiseGenerator(callee, g);
    return bound;
}

}  // namespace

std::shared_ptr<const CompiledFunction> Reader::boundToNoise(
    const std::shared_ptr<const CompiledFunction>& function) {
    if (!function->followsNoiseGenerator) return function;
    noiseGeneratorUsed_ = true;
    return withNoiseGenerator(function, noiseGenerator_);
}

void Reader::setNumberOfWaves(int count) {
    *waveSources_ = *scene::makeWaveSources(count);
}

void Reader::setNoiseGenerator(scene::NoiseGenerator g, const Token& at) {
    if (g != noiseGenerator_ && noiseGeneratorUsed_)
        unsupported(at, "global noise_generator after a pattern or f_noise3d");
    noiseGenerator_ = g;
}

// A `function { ... }` of x, y, z that the renderer will evaluate (patterns,
// isosurfaces, height fields): a body frameray cannot run yet stops here
// rather than mid-render.
std::shared_ptr<const CompiledFunction> Reader::parseXyzFunction(const Token& at,
                                                                 bool colourAsGray) {
    const Value body = parseFunctionBody({"x", "y", "z"});
    const FunctionValue& fn = *std::get<FunctionPtr>(body);
    if (!fn.unsupported.empty()) unsupported(at, fn.unsupported);
    if (fn.vector && fn.vector->isColor && colourAsGray && fn.vector->paramCount == 3)
        return nativeBody("pigment function", 3,
                          std::make_shared<VectorComponent>(fn.vector, kGrayItem));
    if (fn.vector)
        fail(at,
             fmt::format(
                 "a {} function gives a {}; here a float function is needed (take one component: "
                 "F(x, y, z).gray)",
                 fn.vector->kind, fn.vector->isColor ? "colour" : "vector"));
    if (!fn.compiled->unavailable.empty()) unsupported(at, fn.compiled->unavailable);
    if (fn.compiled->paramCount > 3)
        fail(at, fmt::format("{} takes {} parameters; here it is given only x, y, z",
                             fn.compiled->name, fn.compiled->paramCount));
    checkFunctionCost(*fn.compiled, at);
    return boundToNoise(fn.compiled);
}

void Reader::checkFunctionCost(const CompiledFunction& function, const Token& at) {
    const double limit = frame_.limits.functionOperations;
    if (limit > 0 && function.operations > limit)
        fail(at,
             fmt::format(
                 "this function runs about {:.3g} operations per evaluation (its calls of other "
                 "functions multiply); more than {:.3g} would not finish",
                 function.operations, limit));
}

Value Reader::callFunction(const FunctionValue& function, const Token& at) {
    if (!function.unsupported.empty()) unsupported(at, function.unsupported);
    if (function.vector) return callVectorFunction(*function.vector, at);
    const std::vector<Value> args = parseArguments(0, 64, at);
    const int expected = function.compiled->paramCount;
    if (!function.variadic && static_cast<int>(args.size()) != expected)
        fail(at, fmt::format("'{}' takes {} argument{}, {} given", at.text, expected,
                             expected == 1 ? "" : "s", args.size()));
    std::vector<double> values;
    values.reserve(std::max(args.size(), static_cast<size_t>(expected)));
    for (const Value& v : args) values.push_back(toFloat(v, at));
    values.resize(std::max<size_t>(values.size(), static_cast<size_t>(expected)), 0.0);
    checkFunctionCost(*function.compiled, at);
    try {
        return boundToNoise(function.compiled)->eval(values.data());
    } catch (const std::runtime_error& e) {
        fail(at, e.what());
    }
}

}  // namespace frameray::sdl
