// Expressions of the scene language: floats, vectors (2-5 components),
// colours and strings, with the seed's precedence and promotion rules.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>
#include <numbers>

#include "scene/noise.h"
#include "sdl/float_functions.h"
#include "sdl/function_value.h"
#include "sdl/reader.h"

namespace frameray::sdl {

namespace {

constexpr double kEpsilon = 1e-10;

bool isTrue(double v) {
    return std::fabs(v) > kEpsilon;
}

// trace() ignores surfaces nearer than this to the start (povray 3.7's
// minimum intersection depth, backend/configbackend.h).
constexpr double kTraceMinDepth = 1e-4;

// Whether `primitive` lies inverted inside `node`: an odd number of
// `inverse` flags and subtracted difference operands on the way down. povray
// flips trace()'s normal there (its primitives carry that flag; fact from
// povray's parser/express.cpp).
bool invertedWithin(const scene::Object& node, const scene::Object* primitive, bool inverted,
                    bool& result) {
    inverted = inverted != node.inverse;
    if (&node == primitive) {
        result = inverted;
        return true;
    }
    for (size_t i = 0; i < node.children.size(); ++i) {
        const bool subtracted = node.op == scene::CsgOp::Difference && i > 0;
        if (node.children[i] &&
            invertedWithin(*node.children[i], primitive, inverted != subtracted, result))
            return true;
    }
    return false;
}

// Brings two operands to a common shape: floats promote to every
// component, shorter vectors to longer ones with zeros (seed 004).
VectorValue promote(const Value& v, int size) {
    if (const double* f = std::get_if<double>(&v)) {
        VectorValue out;
        out.size = static_cast<uint8_t>(size);
        for (int i = 0; i < size; ++i) out.v[i] = *f;
        return out;
    }
    VectorValue out = std::get<VectorValue>(v);
    for (int i = out.size; i < size; ++i) out.v[i] = 0;
    out.size = static_cast<uint8_t>(std::max<int>(out.size, size));
    return out;
}

template <typename Op>
Value combine(const Value& a, const Value& b, Op op) {
    if (std::holds_alternative<double>(a) && std::holds_alternative<double>(b))
        return op(std::get<double>(a), std::get<double>(b));
    int size = 0;
    bool color = false;
    for (const Value* v : {&a, &b})
        if (const auto* vec = std::get_if<VectorValue>(v)) {
            size = std::max<int>(size, vec->size);
            color = color || vec->isColor;
        }
    VectorValue va = promote(a, size), vb = promote(b, size), out;
    out.size = static_cast<uint8_t>(size);
    out.isColor = color;
    for (int i = 0; i < size; ++i) out.v[i] = op(va.v[i], vb.v[i]);
    return out;
}

bool isNumeric(const Value& v) {
    return std::holds_alternative<double>(v) || std::holds_alternative<VectorValue>(v);
}

// The component keywords of a colour and their slot.
int colorComponent(Keyword k) {
    switch (k) {
        case Keyword::kw_red:
            return 0;
        case Keyword::kw_green:
            return 1;
        case Keyword::kw_blue:
            return 2;
        case Keyword::kw_filter:
            return 3;
        case Keyword::kw_transmit:
            return 4;
        default:
            return -1;
    }
}

// A float as a whole number for counts, widths and indexes: truncated,
// NaN as 0, and clamped to +-2^62 so the conversion is always defined
// (callers then check their own range).
int64_t wholeNumber(double v) {
    if (std::isnan(v)) return 0;
    constexpr double kBound = 4611686018427387904.0;  // 2^62
    return static_cast<int64_t>(std::clamp(std::trunc(v), -kBound, kBound));
}

// The same, clamped to int's range.
int intNumber(double v) {
    return static_cast<int>(std::clamp<int64_t>(wholeNumber(v), -2147483647, 2147483647));
}

// The value of a built-in constant keyword (pi, true, x, clock, version...),
// or nullopt when `kw` is none.
std::optional<Value> builtinConstant(Keyword kw, const FrameContext& frame, double version,
                                     const std::string& inputFileName) {
    auto vec = [](double a, double b, double c, double t, uint8_t size) {
        return VectorValue{{a, b, c, t, 0}, size, false};
    };
    switch (kw) {
        case Keyword::kw_pi:
            return std::numbers::pi;
        case Keyword::kw_true:
        case Keyword::kw_yes:
        case Keyword::kw_on:
            return 1.0;
        case Keyword::kw_false:
        case Keyword::kw_no:
        case Keyword::kw_off:
            return 0.0;
        case Keyword::kw_x:
            return vec(1, 0, 0, 0, 3);
        case Keyword::kw_y:
            return vec(0, 1, 0, 0, 3);
        case Keyword::kw_z:
            return vec(0, 0, 1, 0, 3);
        case Keyword::kw_t:
            return vec(0, 0, 0, 1, 4);
        case Keyword::kw_u:
            return vec(1, 0, 0, 0, 2);
        case Keyword::kw_v:
            return vec(0, 1, 0, 0, 2);
        case Keyword::kw_clock:
            return frame.clock;
        case Keyword::kw_clock_delta:
            return frame.clockDelta;
        case Keyword::kw_clock_on:
            return double(frame.clockOn);
        case Keyword::kw_frame_number:
            return double(frame.frameNumber);
        case Keyword::kw_initial_clock:
            return frame.initialClock;
        case Keyword::kw_final_clock:
            return frame.finalClock;
        case Keyword::kw_initial_frame:
            return double(frame.initialFrame);
        case Keyword::kw_final_frame:
            return double(frame.finalFrame);
        case Keyword::kw_image_width:
            return double(frame.imageWidth);
        case Keyword::kw_image_height:
            return double(frame.imageHeight);
        case Keyword::kw_version:
            return version;
        case Keyword::kw_input_file_name:
            return inputFileName;
        case Keyword::kw_now: {
            // Days since 2000-01-01 00:00 UTC, as povray's `now`.
            const auto since = std::chrono::system_clock::now().time_since_epoch();
            return std::chrono::duration<double>(since).count() / 86400.0 - 10957.0;
        }
        default:
            return std::nullopt;
    }
}

// Keywords other than the colour keywords that start a float or vector
// expression: the built-in constants and the functions giving a number.
constexpr Keyword kNumericStarts[] = {Keyword::kw_pi,
                                      Keyword::kw_true,
                                      Keyword::kw_yes,
                                      Keyword::kw_on,
                                      Keyword::kw_false,
                                      Keyword::kw_no,
                                      Keyword::kw_off,
                                      Keyword::kw_x,
                                      Keyword::kw_y,
                                      Keyword::kw_z,
                                      Keyword::kw_t,
                                      Keyword::kw_u,
                                      Keyword::kw_v,
                                      Keyword::kw_clock,
                                      Keyword::kw_clock_delta,
                                      Keyword::kw_clock_on,
                                      Keyword::kw_frame_number,
                                      Keyword::kw_initial_clock,
                                      Keyword::kw_final_clock,
                                      Keyword::kw_initial_frame,
                                      Keyword::kw_final_frame,
                                      Keyword::kw_image_width,
                                      Keyword::kw_image_height,
                                      Keyword::kw_version,
                                      Keyword::kw_now,
                                      Keyword::kw_min,
                                      Keyword::kw_max,
                                      Keyword::kw_select,
                                      Keyword::kw_vlength,
                                      Keyword::kw_vdot,
                                      Keyword::kw_vcross,
                                      Keyword::kw_vturbulence,
                                      Keyword::kw_vnormalize,
                                      Keyword::kw_vrotate,
                                      Keyword::kw_vaxis_rotate,
                                      Keyword::kw_strlen,
                                      Keyword::kw_asc,
                                      Keyword::kw_strcmp,
                                      Keyword::kw_val,
                                      Keyword::kw_seed,
                                      Keyword::kw_rand,
                                      Keyword::kw_bitwise_and,
                                      Keyword::kw_bitwise_or,
                                      Keyword::kw_bitwise_xor,
                                      Keyword::kw_dimensions,
                                      Keyword::kw_dimension_size,
                                      Keyword::kw_file_exists,
                                      Keyword::kw_min_extent,
                                      Keyword::kw_max_extent,
                                      Keyword::kw_trace,
                                      Keyword::kw_inside,
                                      Keyword::kw_defined};

bool startsNumericKeyword(Keyword kw) {
    if (unaryFloatFunction(kw) || binaryFloatFunction(kw)) return true;
    return std::find(std::begin(kNumericStarts), std::end(kNumericStarts), kw) !=
           std::end(kNumericStarts);
}

// In single precision, as povray computes it (its last digit shows).
double srgbToLinear(double v) {
    const float x = static_cast<float>(v);
    return x <= 0.04045f ? x / 12.92f : std::pow((x + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

double Reader::toFloat(const Value& v, const Token& at) {
    if (const double* f = std::get_if<double>(&v)) return *f;
    fail(at, fmt::format("expected a float, found a {}", valueKindName(v)));
}

VectorValue Reader::toVector(const Value& v, const Token& at, int size) {
    if (!isNumeric(v)) fail(at, fmt::format("expected a vector, found a {}", valueKindName(v)));
    return promote(v, size);
}

// povray parses comparisons, '&', '|' and '? :' only inside parentheses
// (measured: `#declare F = 1 < 2;` is an error, `(1 < 2)` is 1). At the top
// of an expression, in vector components and in arguments, '<' therefore
// starts the next vector: `box { <0,0,0> <1,1,1> }` needs no comma.
Value Reader::parseExpression() {
    return parseAdditive();
}

double Reader::parseFloat() {
    const Token at = peek();
    return toFloat(parseExpression(), at);
}

VectorValue Reader::parseVector() {
    const Token at = peek();
    return toVector(parseExpression(), at, 3);
}

Vec3 Reader::parseVec3() {
    return parseVector().xyz();
}

bool Reader::startsStringExpression(const Token& t) {
    static constexpr Keyword kStringFunctions[] = {
        Keyword::kw_concat, Keyword::kw_str,      Keyword::kw_chr,
        Keyword::kw_substr, Keyword::kw_strupr,   Keyword::kw_strlwr,
        Keyword::kw_vstr,   Keyword::kw_datetime, Keyword::kw_input_file_name};
    if (t.kind == TokenKind::String) return true;
    if (t.isIdentifier()) {
        const Value* v = lookup(t);
        return v && std::holds_alternative<std::string>(*v);
    }
    return t.kind == TokenKind::Word &&
           std::find(std::begin(kStringFunctions), std::end(kStringFunctions), t.kw) !=
               std::end(kStringFunctions);
}

std::string Reader::parsePathname() {
    const bool outer = pathnameMode_;
    pathnameMode_ = true;
    try {
        std::string name = parseString();
        pathnameMode_ = outer;
        return name;
    } catch (...) {
        pathnameMode_ = outer;
        throw;
    }
}

std::string Reader::parseString() {
    const Token at = peek();
    // A string expression has no operators, so nothing after it is looked
    // at: `#include "x.inc"` runs before whatever the next line holds.
    if (startsStringExpression(at)) {
        Value v = parsePrimary();
        if (auto* s = std::get_if<std::string>(&v)) return std::move(*s);
        fail(at, fmt::format("expected a string, found a {}", valueKindName(v)));
    }
    Value v = parseExpression();
    if (auto* s = std::get_if<std::string>(&v)) return std::move(*s);
    fail(at, fmt::format("expected a string, found a {}", valueKindName(v)));
}

bool Reader::colorFollows() {
    return isColorKeyword(peek().kw) || floatFollows();
}

bool Reader::floatFollows() {
    const Token& t = peek();
    switch (t.kind) {
        case TokenKind::Number:
            return true;
        case TokenKind::Symbol:
            return t.is(Sym::LParen) || t.is(Sym::Plus) || t.is(Sym::Minus) || t.is(Sym::Bang) ||
                   t.is(Sym::Less);
        case TokenKind::Word:
            break;
        default:
            return false;
    }
    if (t.kw != Keyword::None) return startsNumericKeyword(t.kw);
    // povray commits to an expression at any numeric identifier (`bumps
    // V.x`); a vector there without a component is then an error.
    const Value* v = lookup(t);
    return v && (std::holds_alternative<double>(*v) || std::holds_alternative<VectorValue>(*v) ||
                 std::holds_alternative<FunctionPtr>(*v) || std::holds_alternative<SplinePtr>(*v) ||
                 std::holds_alternative<ArrayPtr>(*v));
}

double Reader::parseOptionalFloat(double absent) {
    return floatFollows() ? parseFloat() : absent;
}

bool Reader::parseOptionalBool() {
    return parseOptionalFloat(1.0) != 0;
}

Color Reader::parseColor() {
    const Token at = peek();
    accept(Keyword::kw_color) || accept(Keyword::kw_colour);
    VectorValue c;
    c.size = 5;
    c.isColor = true;
    // Either component keywords alone, or an expression optionally followed
    // by component keywords ("Red filter 0.5").
    if (colorComponent(peek().kw) < 0 || peek().kind != TokenKind::Word) {
        const Value v = parseExpression();
        if (!isNumeric(v)) fail(at, fmt::format("expected a color, found a {}", valueKindName(v)));
        c = promote(v, 5);
        // A float or plain vector given as a colour sets rgb only.
        if (!std::get_if<VectorValue>(&v) || !std::get<VectorValue>(v).isColor) {
            if (std::holds_alternative<double>(v)) c.v[3] = c.v[4] = 0;
        }
    }
    for (int slot; peek().kind == TokenKind::Word && (slot = colorComponent(peek().kw)) >= 0;) {
        next();
        c.v[slot] = parseFloat();
    }
    return c.color();
}

Value Reader::parseTernary() {
    const Token at = peek();
    Value cond = parseLogical();
    if (!peek().is(Sym::Question)) return cond;
    next();
    const bool truth = isTrue(toFloat(cond, at));
    Value a = parseTernary();
    expect(Sym::Colon, "':' of the conditional expression");
    Value b = parseTernary();
    return truth ? a : b;
}

// The token after a complete operand, to see whether an operator follows.
// At the top level of a #declare's value (no parentheses, brackets or
// argument list open, in the declaration's own file or macro), a directive
// ends the value without running here: the statement loop runs it after
// the identifier is bound. Pre-3.5 scenes write `#declare I = I + 1`
// without ';' before a loop's #end; running the #end here would start the
// next iteration inside this expression, one nesting level per iteration,
// and a `#declare J = I` on the next line would not see I yet.
// An operand that came out of a macro (`#declare A = MakeArray()`) ends
// where the macro's #end returns to the declaration: that #end runs, the
// directive after it does not (povray binds A first).
const Token& Reader::peekAfterOperand() {
    for (;;) {
        const Token& t = rawPeek();
        if (!t.is(Sym::Hash) || declareValue_.grouping != 0 || cursors_.back().inDirective)
            return peek();
        const int depth = static_cast<int>(cursors_.size());
        if (declareValue_.cursorDepth == depth) return t;
        if (declareValue_.cursorDepth > depth || declareValue_.cursorDepth <= 0) return peek();
        runDirective();
    }
}

Value Reader::parseLogical() {
    Value left = parseRelational();
    for (;;) {
        const Token op = peekAfterOperand();
        if (!op.is(Sym::Amp) && !op.is(Sym::Bar)) return left;
        next();
        const Value right = parseRelational();
        const bool a = isTrue(toFloat(left, op)), b = isTrue(toFloat(right, op));
        left = op.is(Sym::Amp) ? double(a && b) : double(a || b);
    }
}

Value Reader::parseRelational() {
    Value left = parseAdditive();
    for (;;) {
        const Token op = peekAfterOperand();
        const bool relational = op.is(Sym::Less) || op.is(Sym::LessEq) || op.is(Sym::Equal) ||
                                op.is(Sym::NotEq) || op.is(Sym::GreaterEq) || op.is(Sym::Greater);
        if (!relational) return left;
        next();
        const Value right = parseAdditive();
        if (std::holds_alternative<std::string>(left) &&
            std::holds_alternative<std::string>(right)) {
            const int c = std::get<std::string>(left).compare(std::get<std::string>(right));
            bool r = false;
            switch (op.sym) {
                case Sym::Less:
                    r = c < 0;
                    break;
                case Sym::LessEq:
                    r = c <= 0;
                    break;
                case Sym::Equal:
                    r = c == 0;
                    break;
                case Sym::NotEq:
                    r = c != 0;
                    break;
                case Sym::GreaterEq:
                    r = c >= 0;
                    break;
                default:
                    r = c > 0;
                    break;
            }
            left = double(r);
            continue;
        }
        if (!isNumeric(left) || !isNumeric(right))
            fail(op, "relational operators need floats, vectors or two strings");
        left = combine(left, right, [&](double a, double b) {
            switch (op.sym) {
                // As povray 3.7: '=' '!=' '<=' '>=' allow 1e-10, '<' '>' are exact.
                case Sym::Less:
                    return double(a < b);
                case Sym::LessEq:
                    return double(a <= b + kEpsilon);
                case Sym::Equal:
                    return double(std::fabs(a - b) <= kEpsilon);
                case Sym::NotEq:
                    return double(std::fabs(a - b) > kEpsilon);
                case Sym::GreaterEq:
                    return double(a >= b - kEpsilon);
                default:
                    return double(a > b);
            }
        });
    }
}

Value Reader::parseAdditive() {
    Value left = parseMultiplicative();
    for (;;) {
        const Token op = peekAfterOperand();
        if (!op.is(Sym::Plus) && !op.is(Sym::Minus)) return left;
        next();
        const Value right = parseMultiplicative();
        if (!isNumeric(left) || !isNumeric(right))
            fail(op, fmt::format("cannot apply '{}' to a {} and a {}", op.text, valueKindName(left),
                                 valueKindName(right)));
        left = op.is(Sym::Plus) ? combine(left, right, std::plus<double>())
                                : combine(left, right, std::minus<double>());
    }
}

Value Reader::parseMultiplicative() {
    Value left = parseUnary();
    for (;;) {
        const Token op = peekAfterOperand();
        if (!op.is(Sym::Star) && !op.is(Sym::Slash)) return left;
        next();
        const Value right = parseUnary();
        if (!isNumeric(left) || !isNumeric(right))
            fail(op, fmt::format("cannot apply '{}' to a {} and a {}", op.text, valueKindName(left),
                                 valueKindName(right)));
        // povray warns once per component divided by zero, and the result
        // is +inf whatever the sign of the dividend (measured: -1/0 and
        // 0/0 are inf too).
        left = op.is(Sym::Star) ? combine(left, right, std::multiplies<double>())
                                : combine(left, right, [&](double a, double b) {
                                      if (b != 0) return a / b;
                                      warn(op, "divide by zero; the result is inf");
                                      return std::numeric_limits<double>::infinity();
                                  });
    }
}

Value Reader::parseUnary() {
    const Token op = peek();
    const NestingGuard nesting(*this, op);
    if (op.is(Sym::Minus) || op.is(Sym::Plus) || op.is(Sym::Bang)) {
        next();
        Value v = parseUnary();
        if (!isNumeric(v))
            fail(op, fmt::format("cannot apply '{}' to a {}", op.text, valueKindName(v)));
        if (op.is(Sym::Plus)) return v;
        if (op.is(Sym::Minus)) return combine(v, 0.0, [](double a, double) { return -a; });
        return combine(v, 0.0, [](double a, double) { return double(!isTrue(a)); });
    }
    return parsePostfix();
}

int dotItemSlot(Keyword kw) {
    switch (kw) {
        case Keyword::kw_x:
        case Keyword::kw_u:
        case Keyword::kw_red:
            return 0;
        case Keyword::kw_y:
        case Keyword::kw_v:
        case Keyword::kw_green:
            return 1;
        case Keyword::kw_z:
        case Keyword::kw_blue:
            return 2;
        case Keyword::kw_t:
        case Keyword::kw_filter:
            return 3;
        case Keyword::kw_transmit:
            return 4;
        case Keyword::kw_gray:
            return kGrayItem;
        default:
            return -1;
    }
}

Value Reader::parsePostfix() {
    Value v = parsePrimary();
    while (peekAfterOperand().is(Sym::Dot)) {
        const Token dot = next();
        const Token item = next();
        if (!std::holds_alternative<VectorValue>(v))
            fail(dot, fmt::format("'.{}' needs a vector or color, not a {}", item.text,
                                  valueKindName(v)));
        const VectorValue& vec = std::get<VectorValue>(v);
        const int slot = dotItemSlot(item.kw);
        if (slot < 0) fail(item, fmt::format("'{}' is not a vector component", item.text));
        if (slot == kGrayItem) {
            const VectorValue c = promote(v, 5);
            v = grey(c.v[0], c.v[1], c.v[2]);
            continue;
        }
        // Colours always carry all five components.
        const int size = vec.isColor ? 5 : vec.size;
        if (slot >= size)
            fail(item, fmt::format("'.{}' is beyond this {}-component vector", item.text, size));
        v = vec.v[slot];
    }
    return v;
}

Value Reader::parseVectorLiteral() {
    const GroupingGuard grouping(declareValue_);
    const Token open = next();  // '<'
    VectorValue out;
    int n = 0;
    do {
        const Token at = peek();
        const double c = toFloat(parseAdditive(), at);
        if (n >= 5) fail(at, "a vector has at most 5 components");
        out.v[n++] = c;
        // povray accepts a comma before the closing '>' (<0.2,0.1,0.5,> in
        // its example float4.pov), and no comma at all between components
        // (woods.inc: < -1 0 0 >; < 1 -2 > is one component, 1 - 2).
        if (accept(Sym::Comma)) {
            if (peek().is(Sym::Greater)) break;
            continue;
        }
        const Token after = peek();
        if (after.kind != TokenKind::Number && !after.is(Sym::LParen) && !after.isIdentifier())
            break;
    } while (true);
    expect(Sym::Greater, "'>' closing the vector");
    if (n < 2) fail(open, "a vector needs at least 2 components");
    out.size = static_cast<uint8_t>(n);
    return out;
}

Value Reader::parseColorKeywords(const Token& first) {
    VectorValue c;
    c.size = 5;
    c.isColor = true;
    switch (first.kw) {
        case Keyword::kw_rgb:
        case Keyword::kw_rgbf:
        case Keyword::kw_rgbt:
        case Keyword::kw_rgbft:
        case Keyword::kw_srgb:
        case Keyword::kw_srgbf:
        case Keyword::kw_srgbt:
        case Keyword::kw_srgbft: {
            const std::string_view name = first.text;
            const bool srgb = name.starts_with("srgb");
            const std::string_view suffix = name.substr(srgb ? 4 : 3);
            const int size = 3 + static_cast<int>(suffix.size());
            const Token at = peek();
            const Value v = parseAdditive();
            const VectorValue vec = toVector(v, at, size);
            // sRGB values convert to the working gamma, which must be known
            // by then (povray 3.7 stops the parse otherwise).
            if (srgb && !assumedGamma_)
                fail(first,
                     "cannot use sRGB colors before assumed_gamma has been set in global_settings");
            const double gamma = assumedGamma_.value_or(1.0);
            for (int i = 0; i < 3; ++i) {
                c.v[i] = vec.v[i];
                if (srgb) {
                    c.v[i] = srgbToLinear(vec.v[i]);
                    if (gamma != 1.0) c.v[i] = std::pow(c.v[i], 1.0 / gamma);
                }
            }
            if (suffix == "f") c.v[3] = vec.v[3];
            if (suffix == "t") c.v[4] = vec.v[3];
            if (suffix == "ft") {
                c.v[3] = vec.v[3];
                c.v[4] = vec.v[4];
            }
            break;
        }
        default: {
            // red/green/blue/filter/transmit groups starting from black.
            const int slot = colorComponent(first.kw);
            c.v[slot] = parseFloat();
            break;
        }
    }
    for (int slot; peek().kind == TokenKind::Word && (slot = colorComponent(peek().kw)) >= 0;) {
        next();
        c.v[slot] = parseFloat();
    }
    // povray keeps colours in single precision.
    for (double& component : c.v) component = static_cast<float>(component);
    return c;
}

Value Reader::identifierValue(const Token& name, const Value* known) {
    const std::string_view id(name.text);
    const Value* v = known ? known : lookup(name);
    if (!v) fail(name, fmt::format("undeclared identifier '{}'", name.text));
    if (const std::string* deprecation = symbols_.deprecationWarning(id)) warn(name, *deprecation);
    Value out = *v;
    // Arrays of arrays index on: Nested[0][1].
    while (std::holds_alternative<ArrayPtr>(out) && peekAfterOperand().is(Sym::LBracket)) {
        const ArrayPtr array = std::get<ArrayPtr>(out);  // keep alive while indexing
        const size_t index = parseArrayIndex(*array, name);
        out = array->get(index);
        if (std::holds_alternative<std::monostate>(out))
            fail(name,
                 fmt::format("element {} of array '{}' used before it was set", index, name.text));
    }
    if (const auto* spline = std::get_if<SplinePtr>(&out);
        spline && peekAfterOperand().is(Sym::LParen)) {
        const SplinePtr keep = *spline;
        return callSpline(*keep, name);
    }
    if (const auto* function = std::get_if<FunctionPtr>(&out);
        function && peekAfterOperand().is(Sym::LParen)) {
        const FunctionPtr keep = *function;
        return callFunction(*keep, name);
    }
    // "Cyan red 0.6": component keywords after a colour identifier.
    if (auto* vec = std::get_if<VectorValue>(&out); vec && vec->isColor) {
        for (int slot; peek().kind == TokenKind::Word && (slot = colorComponent(peek().kw)) >= 0;) {
            next();
            vec->v[slot] = parseFloat();
        }
    }
    return out;
}

std::vector<Value> Reader::parseArguments(size_t min, size_t max, const Token& fn) {
    const GroupingGuard grouping(declareValue_);
    expectAfter(Sym::LParen, "'('", fn.text);
    std::vector<Value> args;
    // A function of exactly one argument reads its parentheses as the
    // argument's own, so comparisons and '? :' work there as in any
    // parenthesised expression (povray: abs(1 < 2) is 1, pow(1 < 2, 2) an
    // error).
    const bool single = min == 1 && max == 1;
    if (!peek().is(Sym::RParen)) {
        do {
            args.push_back(single ? parseTernary() : parseExpression());
        } while (accept(Sym::Comma));
    }
    expect(Sym::RParen, "')'");
    if (args.size() < min || args.size() > max)
        fail(fn, min == max ? fmt::format("'{}' takes {} argument{}, {} given", fn.text, min,
                                          min == 1 ? "" : "s", args.size())
                            : fmt::format("'{}' takes {} to {} arguments, {} given", fn.text, min,
                                          max, args.size()));
    return args;
}

Value Reader::parsePrimary() {
    const Token t = peek();
    switch (t.kind) {
        case TokenKind::Number:
            next();
            return t.number;
        case TokenKind::String: {
            const TokenizedFile& file = *cursors_.back().file;
            if (pathnameMode_) {
                next();
                return file.rawString(t);
            }
            if (t.unknownEscape) {
                const SourceLoc at{file.source.get(), t.line, file.unknownEscapeColumn(t)};
                throw SdlError(at,
                               "illegal escape sequence in string (a '\\' must be written '\\\\')",
                               includeChain(at));
            }
            next();
            return std::string(t.text);
        }
        case TokenKind::End:
            fail(t, "unexpected end of file in an expression");
        case TokenKind::Symbol:
            if (t.is(Sym::LParen)) {
                next();
                const GroupingGuard grouping(declareValue_);
                Value v = parseTernary();
                expect(Sym::RParen, "')'");
                return v;
            }
            if (t.is(Sym::Less)) return parseVectorLiteral();
            fail(t, fmt::format("expected an expression, found {}", describeToken(t)));
        case TokenKind::Word:
            break;
    }
    if (t.kw == Keyword::None) {
        // peek() just looked this identifier up; nothing ran since.
        const Value* known = peekCache_.identifier;
        next();
        return identifierValue(t, known);
    }
    if (std::optional<Value> constant = builtinConstant(t.kw, frame_, version_, inputFileName_)) {
        next();
        return std::move(*constant);
    }
    switch (t.kw) {
        case Keyword::kw_color:
        case Keyword::kw_colour: {
            next();
            if (colorComponent(peek().kw) >= 0 && peek().kind == TokenKind::Word) {
                const Token first = next();
                return parseColorKeywords(first);
            }
            const Token at = peek();
            Value v = parseAdditive();
            VectorValue c = toVector(v, at, 5);
            c.isColor = true;
            return c;
        }
        case Keyword::kw_rgb:
        case Keyword::kw_rgbf:
        case Keyword::kw_rgbt:
        case Keyword::kw_rgbft:
        case Keyword::kw_srgb:
        case Keyword::kw_srgbf:
        case Keyword::kw_srgbt:
        case Keyword::kw_srgbft:
        case Keyword::kw_red:
        case Keyword::kw_green:
        case Keyword::kw_blue:
        case Keyword::kw_filter:
        case Keyword::kw_transmit: {
            next();
            return parseColorKeywords(t);
        }
        default:
            break;
    }
    next();
    return parseBuiltinFunction(t);
}

// povray's domain checks of the float functions at parse time (compiled
// user functions have none): sqrt, log and ln of a number out of their
// domain stop the parse; acos and asin warn and take the nearest end of
// theirs.
double Reader::checkedArgument(const Token& fn, double a) {
    switch (fn.kw) {
        case Keyword::kw_sqrt:
            if (a < 0) fail(fn, fmt::format("sqrt of a negative number ({})", a));
            return a;
        case Keyword::kw_ln:
        case Keyword::kw_log:
            if (a <= 0) fail(fn, fmt::format("{} of a number not above zero ({})", fn.text, a));
            return a;
        case Keyword::kw_acos:
        case Keyword::kw_asin:
            if (a > 1 || a < -1) {
                warn(fn, fmt::format("domain error in {}: {} is outside -1 to 1; using {}", fn.text,
                                     a, a > 1 ? 1 : -1));
                return a > 1 ? 1.0 : -1.0;
            }
            return a;
        default:
            return a;
    }
}

Value Reader::parseBuiltinFunction(const Token& fn) {
    auto f = [&](const Value& v) { return toFloat(v, fn); };
    if (const UnaryFloatFunction op = unaryFloatFunction(fn.kw))
        return op(checkedArgument(fn, f(parseArguments(1, 1, fn)[0])));
    if (const BinaryFloatFunction op = binaryFloatFunction(fn.kw)) {
        auto a = parseArguments(2, 2, fn);
        const double x = f(a[0]), y = f(a[1]);
        if (fn.kw == Keyword::kw_atan2 && x == 0 && y == 0)
            fail(fn, "domain error in atan2: atan2(0, 0) has no angle");
        return op(x, y);
    }
    if (std::optional<Value> v = parseNumericBuiltin(fn)) return std::move(*v);
    if (std::optional<Value> v = parseStringBuiltin(fn)) return std::move(*v);
    if (std::optional<Value> v = parseQueryBuiltin(fn)) return std::move(*v);
    unsupported(fn, fmt::format("'{}' in an expression", fn.text));
}

// The float and vector functions of more than two arguments, and rand.
std::optional<Value> Reader::parseNumericBuiltin(const Token& fn) {
    auto f = [&](const Value& v) { return toFloat(v, fn); };
    auto vec = [&](const Value& v) { return toVector(v, fn, 3).xyz(); };
    switch (fn.kw) {
        case Keyword::kw_min:
        case Keyword::kw_max: {
            auto a = parseArguments(1, 256, fn);
            double r = f(a[0]);
            for (size_t i = 1; i < a.size(); ++i)
                r = fn.kw == Keyword::kw_min ? std::min(r, f(a[i])) : std::max(r, f(a[i]));
            return r;
        }
        case Keyword::kw_select: {
            auto a = parseArguments(3, 4, fn);
            const double s = f(a[0]);
            if (a.size() == 3) return s < 0 ? a[1] : a[2];
            return s < 0 ? a[1] : (s == 0 ? a[2] : a[3]);
        }
        case Keyword::kw_vlength:
            return length(vec(parseArguments(1, 1, fn)[0]));
        case Keyword::kw_vdot: {
            auto a = parseArguments(2, 2, fn);
            return dot(vec(a[0]), vec(a[1]));
        }
        case Keyword::kw_vcross: {
            auto a = parseArguments(2, 2, fn);
            return VectorValue::fromVec3(cross(vec(a[0]), vec(a[1])));
        }
        case Keyword::kw_vturbulence: {
            // vturbulence(Lambda, Omega, Octaves, P): the displacement a
            // turbulence warp with these parameters gives at P.
            auto a = parseArguments(4, 4, fn);
            scene::Turbulence turb;
            turb.lambda = static_cast<float>(f(a[0]));
            turb.omega = static_cast<float>(f(a[1]));
            turb.octaves = static_cast<int>(f(a[2]));
            return VectorValue::fromVec3(scene::vectorTurbulence(vec(a[3]), turb));
        }
        case Keyword::kw_vnormalize:
            return VectorValue::fromVec3(normalize(vec(parseArguments(1, 1, fn)[0])));
        case Keyword::kw_vrotate: {
            auto a = parseArguments(2, 2, fn);
            return VectorValue::fromVec3(Transform::rotate(vec(a[1])).point(vec(a[0])));
        }
        case Keyword::kw_vaxis_rotate: {
            auto a = parseArguments(3, 3, fn);
            // The axis-angle rotation matrix in the row-vector convention,
            // evaluated in this order so results match povray's to the bit.
            const Vec3 p = vec(a[0]), k = normalize(vec(a[1]));
            const double ang = f(a[2]) * std::numbers::pi / 180.0;
            const double c = std::cos(ang), sn = std::sin(ang), t = 1 - c;
            const double m00 = k.x * k.x + c * (1 - k.x * k.x), m01 = k.x * k.y * t + k.z * sn,
                         m02 = k.x * k.z * t - k.y * sn;
            const double m10 = k.x * k.y * t - k.z * sn, m11 = k.y * k.y + c * (1 - k.y * k.y),
                         m12 = k.y * k.z * t + k.x * sn;
            const double m20 = k.x * k.z * t + k.y * sn, m21 = k.y * k.z * t - k.x * sn,
                         m22 = k.z * k.z + c * (1 - k.z * k.z);
            return VectorValue::fromVec3({p.x * m00 + p.y * m10 + p.z * m20,
                                          p.x * m01 + p.y * m11 + p.z * m21,
                                          p.x * m02 + p.y * m12 + p.z * m22});
        }
        case Keyword::kw_seed: {
            // The stream's state starts at the seed truncated to a 32-bit
            // integer; seed() returns the stream's number.
            const double v = f(parseArguments(1, 1, fn)[0]);
            randomStreams_.push_back(static_cast<uint32_t>(wholeNumber(v)));
            return double(randomStreams_.size() - 1);
        }
        case Keyword::kw_rand: {
            // povray 3.7's generator, read off its output: a 32-bit LCG
            // (multiplier 1812433253, increment 12345) scaled by 2^32-1.
            const double v = f(parseArguments(1, 1, fn)[0]);
            const int64_t stream = wholeNumber(std::round(v));
            if (stream < 0 || static_cast<size_t>(stream) >= randomStreams_.size())
                fail(fn, fmt::format("rand: {} is not a random stream made by seed()", v));
            uint32_t& state = randomStreams_[static_cast<size_t>(stream)];
            state = state * 1812433253u + 12345u;
            return state / 4294967295.0;
        }
        case Keyword::kw_bitwise_and:
        case Keyword::kw_bitwise_or:
        case Keyword::kw_bitwise_xor: {
            auto a = parseArguments(2, 256, fn);
            auto r = wholeNumber(f(a[0]));
            for (size_t i = 1; i < a.size(); ++i) {
                const auto b = wholeNumber(f(a[i]));
                r = fn.kw == Keyword::kw_bitwise_and  ? (r & b)
                    : fn.kw == Keyword::kw_bitwise_or ? (r | b)
                                                      : (r ^ b);
            }
            return double(r);
        }
        case Keyword::kw_dimensions:
        case Keyword::kw_dimension_size: {
            auto a = parseArguments(fn.kw == Keyword::kw_dimensions ? 1 : 2,
                                    fn.kw == Keyword::kw_dimensions ? 1 : 2, fn);
            const auto* arr = std::get_if<ArrayPtr>(&a[0]);
            if (!arr)
                fail(fn,
                     fmt::format("'{}' needs an array, found a {}", fn.text, valueKindName(a[0])));
            if (fn.kw == Keyword::kw_dimensions) return double((*arr)->dims.size());
            const int64_t d = wholeNumber(std::round(f(a[1])));
            if (d < 1 || static_cast<size_t>(d) > (*arr)->dims.size()) return 0.0;
            return double((*arr)->dims[static_cast<size_t>(d - 1)]);
        }
        default:
            return std::nullopt;
    }
}

// The string functions.
std::optional<Value> Reader::parseStringBuiltin(const Token& fn) {
    auto f = [&](const Value& v) { return toFloat(v, fn); };
    auto str = [&](const Value& v) -> std::string {
        if (const auto* s = std::get_if<std::string>(&v)) return *s;
        fail(fn, fmt::format("'{}' expects a string, found a {}", fn.text, valueKindName(v)));
    };
    switch (fn.kw) {
        case Keyword::kw_strlen:
            return double(str(parseArguments(1, 1, fn)[0]).size());
        case Keyword::kw_strupr:
        case Keyword::kw_strlwr: {
            std::string s = str(parseArguments(1, 1, fn)[0]);
            for (char& c : s) {
                const auto byte = static_cast<unsigned char>(c);
                c = static_cast<char>(fn.kw == Keyword::kw_strupr ? std::toupper(byte)
                                                                  : std::tolower(byte));
            }
            return s;
        }
        case Keyword::kw_concat: {
            std::string out;
            for (const Value& v : parseArguments(1, 1024, fn)) {
                const std::string part = str(v);
                checkStringLength(out.size() + part.size(), fn);
                out += part;
            }
            return out;
        }
        case Keyword::kw_chr:
            return std::string(1, static_cast<char>(wholeNumber(f(parseArguments(1, 1, fn)[0]))));
        case Keyword::kw_asc: {
            const std::string s = str(parseArguments(1, 1, fn)[0]);
            return s.empty() ? 0.0 : double(static_cast<unsigned char>(s[0]));
        }
        case Keyword::kw_strcmp: {
            auto a = parseArguments(2, 2, fn);
            const int c = str(a[0]).compare(str(a[1]));
            return double((c > 0) - (c < 0));
        }
        case Keyword::kw_substr: {
            auto a = parseArguments(3, 3, fn);
            const std::string s = str(a[0]);
            const int64_t start = wholeNumber(f(a[1])), len = wholeNumber(f(a[2]));
            if (start < 1 || len < 0 || static_cast<size_t>(start - 1 + len) > s.size())
                fail(fn,
                     fmt::format("substr: characters {} to {} are outside the {}-character string",
                                 start, start + len - 1, s.size()));
            return s.substr(static_cast<size_t>(start - 1), static_cast<size_t>(len));
        }
        case Keyword::kw_val:
            return std::strtod(str(parseArguments(1, 1, fn)[0]).c_str(), nullptr);
        case Keyword::kw_str: {
            // str(value, width, precision) as printf's "%W.Pf"; width 0
            // means none, precision -1 means 6.
            auto a = parseArguments(3, 3, fn);
            const double v = f(a[0]);
            const int width = intNumber(f(a[1])), precision = intNumber(f(a[2]));
            const int p = precision < 0 ? 6 : precision;
            checkStringLength(static_cast<size_t>(std::abs(width)) + static_cast<size_t>(p), fn);
            if (width < 0) return fmt::format("{:0{}.{}f}", v, -width, p);
            return fmt::format("{:{}.{}f}", v, width, p);
        }
        case Keyword::kw_vstr: {
            auto a = parseArguments(5, 5, fn);
            // vstr(N, V, separator, width, precision); povray prints at
            // least 2 components, and a float V fills only the first.
            const int dims = std::clamp(intNumber(f(a[0])), 2, 5);
            VectorValue v;
            if (const double* single = std::get_if<double>(&a[1]))
                v.v[0] = *single;
            else
                v = toVector(a[1], fn, dims);
            const std::string sep = str(a[2]);
            const int width = intNumber(f(a[3])), precision = intNumber(f(a[4]));
            const int p = precision < 0 ? 6 : precision;
            checkStringLength((static_cast<size_t>(std::abs(width)) + static_cast<size_t>(p)) * 5 +
                                  str(a[2]).size() * 4,
                              fn);
            std::string out;
            for (int i = 0; i < dims; ++i) {
                if (i) out += sep;
                out += width < 0 ? fmt::format("{:0{}.{}f}", v.v[i], -width, p)
                                 : fmt::format("{:{}.{}f}", v.v[i], width, p);
            }
            return out;
        }
        case Keyword::kw_datetime: {
            // Days since 2000-01-01 00:00 UTC, formatted by strftime (default
            // format as povray's).
            auto a = parseArguments(1, 2, fn);
            const double days = f(a[0]);
            const std::string format = a.size() > 1 ? str(a[1]) : "%Y-%m-%d %H:%M:%SZ";
            const auto seconds =
                static_cast<std::time_t>(std::floor((days + 10957.0) * 86400.0 + 0.5));
            std::tm utc{};
            gmtime_r(&seconds, &utc);
            char buffer[512];
            const size_t n = std::strftime(buffer, sizeof buffer, format.c_str(), &utc);
            return std::string(buffer, n);
        }
        default:
            return std::nullopt;
    }
}

// What the scene and its files hold: file_exists, extents, trace, inside, defined.
std::optional<Value> Reader::parseQueryBuiltin(const Token& fn) {
    auto vec = [&](const Value& v) { return toVector(v, fn, 3).xyz(); };
    auto str = [&](const Value& v) -> std::string {
        if (const auto* s = std::get_if<std::string>(&v)) return *s;
        fail(fn, fmt::format("'{}' expects a string, found a {}", fn.text, valueKindName(v)));
    };
    switch (fn.kw) {
        case Keyword::kw_file_exists: {
            const std::string name = str(parseArguments(1, 1, fn)[0]);
            // A file the scene may not read is reported missing: its
            // existence is what the restrictions keep from the scene.
            const std::filesystem::path path = findIncludeFile(name);
            return double(!path.empty() && frame_.fileAccess.checkRead(path, name).empty());
        }
        case Keyword::kw_min_extent:
        case Keyword::kw_max_extent: {
            auto a = parseArguments(1, 1, fn);
            // povray 3.7: max_extent of an image_map pigment is the image's
            // resolution <width, height, 0>.
            if (const auto* pig = std::get_if<PigmentPtr>(&a[0]);
                pig && fn.kw == Keyword::kw_max_extent) {
                if (!(*pig)->imageMap())
                    fail(fn, "The parameter to max_extent must be an image map pigment");
                const scene::ImageTexels& t = (*pig)->imageMap()->texels();
                return VectorValue::fromVec3(Vec3(t.width(), t.height(), 0));
            }
            const auto* obj = std::get_if<ObjectPtr>(&a[0]);
            if (!obj)
                fail(fn,
                     fmt::format("'{}' needs an object, found a {}", fn.text, valueKindName(a[0])));
            const scene::Bounds b = (*obj)->object->worldBounds();
            return VectorValue::fromVec3(fn.kw == Keyword::kw_min_extent ? b.lo : b.hi);
        }
        case Keyword::kw_trace: {
            // trace(Object, Start, Direction [, NormalIdentifier]): the first
            // surface point along the ray, <0,0,0> (and a zero normal) if none.
            expectAfter(Sym::LParen, "'('", fn.text);
            const Token objToken = peek();
            const Value objValue = parseExpression();
            const auto* obj = std::get_if<ObjectPtr>(&objValue);
            if (!obj)
                fail(objToken,
                     fmt::format("'trace' needs an object, found a {}", valueKindName(objValue)));
            expect(Sym::Comma, "','");
            const Vec3 start = parseVec3();
            expect(Sym::Comma, "','");
            const Vec3 direction = parseVec3();
            std::string normalName;
            if (accept(Sym::Comma)) normalName = expectIdentifier();
            expect(Sym::RParen, "')'");
            scene::SurfaceHit hit;
            Vec3 point, normal;
            // povray traces along the unit direction (made unit by its
            // reciprocal length): a search in steps of the ray's parameter
            // (an isosurface's accuracy) then works in scene units.
            const double dirLength = length(direction);
            const scene::Ray ray{start, direction * (1.0 / dirLength)};
            // The nearest crossing at least kTraceMinDepth away. Shapes
            // found by marching (julia_fractal, isosurface) march from the
            // start as povray's do; nearer crossings are stepped over.
            bool found = false;
            if (dirLength > 0) {
                double from = 0.0;
                for (int tries = 0; tries < 64; ++tries) {
                    if (!(*obj)->object->firstHit(ray, from, scene::kInfinity, scene::RayKind::Any,
                                                  hit) ||
                        hit.t <= from)
                        break;
                    if (hit.t >= kTraceMinDepth) {
                        found = true;
                        break;
                    }
                    from = hit.t;
                }
            }
            if (found) {
                point = ray.at(hit.t);
                normal = hit.primitive->normalAt(point);
                bool inverted = false;
                if (invertedWithin(*(*obj)->object, hit.primitive, false, inverted) && inverted)
                    normal = -normal;
            }
            if (!normalName.empty())
                symbols_.declare(normalName, VectorValue::fromVec3(normal), false);
            return VectorValue::fromVec3(point);
        }
        case Keyword::kw_inside: {
            auto a = parseArguments(2, 2, fn);
            const auto* obj = std::get_if<ObjectPtr>(&a[0]);
            if (!obj)
                fail(fn, fmt::format("'inside' needs an object, found a {}", valueKindName(a[0])));
            return double((*obj)->object->inside(vec(a[1])));
        }
        case Keyword::kw_defined: {
            expect(Sym::LParen, "'('");
            const Token id = rawPeek();
            ++cursors_.back().pos;
            expect(Sym::RParen, "')'");
            return double(id.isIdentifier() && lookup(id.text) != nullptr);
        }

        default:
            return std::nullopt;
    }
}

}  // namespace frameray::sdl
