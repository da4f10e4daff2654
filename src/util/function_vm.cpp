#include "util/function_vm.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace frameray {

namespace {
// Steps one sum() or prod() loop may take (see LoopInit).
constexpr double kMaxLoopSteps = 1e7;
// Unlike parse-time expressions, function comparisons are exact (povray 3.7).
bool truth(double v) {
    return v != 0.0;
}
// The loop counts up by 1 until it passes the end: bounds that are not
// finite, or so large that adding 1 changes nothing, would never end it;
// nor is a loop of billions of steps meant.
void checkLoopBounds(double start, double end) {
    if (!(end < start) &&
        !(std::isfinite(start) && std::fabs(start) < 4.5e15 && end - start <= kMaxLoopSteps))
        throw std::runtime_error("sum/prod loop from " + std::to_string(start) + " to " +
                                 std::to_string(end) + ": more than " +
                                 std::to_string(static_cast<long>(kMaxLoopSteps)) + " steps");
}
}  // namespace

double CompiledFunction::eval(const double* args) const {
    std::array<double, kMaxStack> stack;
    std::array<double, kMaxSlots> slots;
    int sp = 0;
    const size_t n = code.size();
    for (size_t pc = 0; pc < n; ++pc) {
        const FnInstr& in = code[pc];
        switch (in.op) {
            case FnOp::Const:
                stack[sp++] = in.value;
                break;
            case FnOp::Param:
                stack[sp++] = args[in.a];
                break;
            case FnOp::Slot:
                stack[sp++] = slots[in.a];
                break;
            case FnOp::Add:
                --sp;
                stack[sp - 1] += stack[sp];
                break;
            case FnOp::Sub:
                --sp;
                stack[sp - 1] -= stack[sp];
                break;
            case FnOp::Mul:
                --sp;
                stack[sp - 1] *= stack[sp];
                break;
            case FnOp::Div:
                --sp;
                stack[sp - 1] /= stack[sp];
                break;
            case FnOp::Neg:
                stack[sp - 1] = -stack[sp - 1];
                break;
            case FnOp::Not:
                stack[sp - 1] = truth(stack[sp - 1]) ? 0.0 : 1.0;
                break;
            case FnOp::Lt:
                --sp;
                stack[sp - 1] = stack[sp - 1] < stack[sp];
                break;
            case FnOp::Le:
                --sp;
                stack[sp - 1] = stack[sp - 1] <= stack[sp];
                break;
            case FnOp::Eq:
                --sp;
                stack[sp - 1] = stack[sp - 1] == stack[sp];
                break;
            case FnOp::Ne:
                --sp;
                stack[sp - 1] = stack[sp - 1] != stack[sp];
                break;
            case FnOp::Ge:
                --sp;
                stack[sp - 1] = stack[sp - 1] >= stack[sp];
                break;
            case FnOp::Gt:
                --sp;
                stack[sp - 1] = stack[sp - 1] > stack[sp];
                break;
            case FnOp::And:
                --sp;
                stack[sp - 1] = truth(stack[sp - 1]) && truth(stack[sp]);
                break;
            case FnOp::Or:
                --sp;
                stack[sp - 1] = truth(stack[sp - 1]) || truth(stack[sp]);
                break;
            case FnOp::Unary:
                stack[sp - 1] = in.unary(stack[sp - 1]);
                break;
            case FnOp::Binary:
                --sp;
                stack[sp - 1] = in.binary(stack[sp - 1], stack[sp]);
                break;
            case FnOp::Call: {
                sp -= in.b;
                stack[sp] = callees[static_cast<size_t>(in.a)]->eval(&stack[sp]);
                ++sp;
                break;
            }
            case FnOp::Select3: {
                sp -= 2;
                stack[sp - 1] = stack[sp - 1] < 0 ? stack[sp] : stack[sp + 1];
                break;
            }
            case FnOp::Select4: {
                sp -= 3;
                const double c = stack[sp - 1];
                stack[sp - 1] = c < 0 ? stack[sp] : (c == 0 ? stack[sp + 1] : stack[sp + 2]);
                break;
            }
            case FnOp::MinN:
            case FnOp::MaxN: {
                sp -= in.a;
                double r = stack[sp];
                for (int i = 1; i < in.a; ++i)
                    r = in.op == FnOp::MinN ? std::min(r, stack[sp + i])
                                            : std::max(r, stack[sp + i]);
                stack[sp++] = r;
                break;
            }
            case FnOp::JumpIfFalse:
                if (!truth(stack[--sp])) pc = static_cast<size_t>(in.a) - 1;
                break;
            case FnOp::Jump:
                pc = static_cast<size_t>(in.a) - 1;
                break;
            case FnOp::LoopInit:
                slots[in.a + 1] = stack[--sp];
                slots[in.a] = stack[--sp];
                checkLoopBounds(slots[in.a], slots[in.a + 1]);
                stack[sp++] = in.b;
                break;
            case FnOp::LoopTest:
                if (slots[in.a] > slots[in.a + 1]) pc = static_cast<size_t>(in.b) - 1;
                break;
            case FnOp::LoopSum:
                --sp;
                stack[sp - 1] += stack[sp];
                break;
            case FnOp::LoopProd:
                --sp;
                stack[sp - 1] *= stack[sp];
                break;
            case FnOp::LoopNext:
                slots[in.a] += 1;
                pc = static_cast<size_t>(in.b) - 1;
                break;
            case FnOp::Native:
                stack[sp++] = natives[static_cast<size_t>(in.a)]->eval(args);
                break;
            case FnOp::Internal:
                throw std::runtime_error("not supported yet: " + unavailable);
        }
    }
    return sp > 0 ? stack[sp - 1] : 0.0;
}

void CompiledFunction::countOperations() {
    operations = static_cast<double>(code.size());
    for (const FnInstr& in : code)
        if (in.op == FnOp::Call) operations += callees[static_cast<size_t>(in.a)]->operations;
}

}  // namespace frameray
