// SPDX-License-Identifier: MIT
#include "cal/eval.h"

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <string>

#include "cal/library.h"
#include "cal/program.h"

namespace rt::cal {
namespace {

// Deep recursion must end in an error, not a stack overflow: nested calls are
// limited both in number and in C stack used. The budget leaves room below it
// for one function body's own expression depth (bounded by the parser) on the
// 8 MiB main stack and std::thread's default stack.
constexpr int kMaxDepth = 4000;
constexpr std::uintptr_t kStackBudget = std::uintptr_t{1} << 20;  // bytes

std::uintptr_t StackPosition() {
    return reinterpret_cast<std::uintptr_t>(__builtin_frame_address(0));
}

MathError ErrnoKind(int e) {
    if (e == EDOM) return MathError::Domain;
    if (e == ERANGE) return MathError::Range;
    return MathError::None;
}

// Leaves the call depth as it was, also when an EvalError unwinds.
struct DepthScope {
    explicit DepthScope(int& depth) : depth_(depth) {}
    ~DepthScope() { --depth_; }
    DepthScope(const DepthScope&) = delete;
    DepthScope& operator=(const DepthScope&) = delete;
    int& depth_;
};

}  // namespace

Evaluator::Evaluator(const Program& program, Context& context, Program* foldInto)
    : program_(program),
      code_(program.code()),
      nodes_(program.code().nodes.data()),
      args_(program.code().args.data()),
      ctx_(context),
      foldInto_(foldInto) {}

void Evaluator::BeginTop() {
    if (ctx_.depth_ == 0) {
        const std::uintptr_t here = StackPosition();
        ctx_.stackLimit_ =
            reinterpret_cast<const char*>(here > kStackBudget ? here - kStackBudget : 0);
    }
}

double Evaluator::TopExpression(std::int32_t node) {
    BeginTop();
    return Eval(node, nullptr);
}

double Evaluator::TopVariable(std::int32_t slot) {
    BeginTop();
    return Variable(slot, 0);
}

double Evaluator::TopCall(std::int32_t slot, const double* args, int nargs) {
    BeginTop();
    return CallSlot(slot, Args{nullptr, nullptr, args, nargs, slot, 0});
}

void Evaluator::Fail(std::string message, std::uint32_t loc) const {
    throw EvalError{std::move(message), loc};
}

void Evaluator::FailNamed(const char* before, std::int32_t slot, std::uint32_t loc,
                          const char* after, std::uint32_t at) const {
    Fail(before + NameAt(loc, slot) + after, at);
}

std::string Evaluator::NameAt(std::uint32_t loc, std::int32_t slot) const {
    const SourceLoc& where = code_.locs[loc];
    if (where.name >= 0) return code_.names[static_cast<std::size_t>(where.name)];
    return code_.slots[static_cast<std::size_t>(slot)].name;
}

void Evaluator::Enter(std::int32_t slot, std::uint32_t loc) {
    if (++ctx_.depth_ > kMaxDepth ||
        StackPosition() < reinterpret_cast<std::uintptr_t>(ctx_.stackLimit_)) {
        --ctx_.depth_;
        FailNamed("recursion too deep in '", slot, loc, "'", loc);
    }
    if (++ctx_.calls_ > ctx_.callLimit_) {
        --ctx_.depth_;
        Fail("evaluation too long (more than " + std::to_string(ctx_.callLimit_) + " calls) in '" +
                 NameAt(loc, slot) + "'",
             loc);
    }
}

double Evaluator::MathFailure(MathError kind, std::string_view what, std::uint32_t loc) {
    ctx_.mathError_ = kind;
    if (ctx_.folding_) {
        // Parse time: the parser reports it as part of "bad constant expression".
        if (ctx_.errorWhat_.empty()) ctx_.errorWhat_ = what;
        return 0.0;
    }
    if (ctx_.errorText_.empty() || ctx_.warnings_) {
        std::string text = program_.Where(loc);
        text += text.empty() ? "" : ": ";
        text += what;
        if (ctx_.warnings_) ctx_.warnings_(text);
        if (ctx_.errorText_.empty()) ctx_.errorText_ = std::move(text);
    }
    return 0.0;
}

double Evaluator::Eval(std::int32_t index, Frame* frame) {
    const Node& node = nodes_[index];
    switch (node.op) {
        case Op::Num:
            return node.num;
        case Op::Var:
            return Variable(node.a, node.loc);
        case Op::Param:
            return Parameter(frame, node.a, node.loc);
        case Op::Chan: {
            if (ctx_.folding_) {
                if (program_.options().foldedChannelsAreZero) return 0.0;
                Fail("ray parameter used in constant expression", node.loc);
            }
            if (node.a < 1 || node.a > program_.options().channelCount) {
                Fail("illegal channel number $" + std::to_string(node.a), node.loc);
            }
            if (ctx_.channels_ == nullptr) {
                Fail("no ray quantities for $" + std::to_string(node.a), node.loc);
            }
            return ctx_.channels_->Channel(node.a);
        }
        case Op::Neg:
            return -Operand(node.a, frame);
        case Op::Add:
            return Operand(node.a, frame) + Operand(node.b, frame);
        case Op::Sub:
            return Operand(node.a, frame) - Operand(node.b, frame);
        case Op::Mul:
            return Operand(node.a, frame) * Operand(node.b, frame);
        case Op::Div: {
            // Radiance evaluates the divisor first and skips the dividend on zero.
            const double d = Operand(node.b, frame);
            if (d == 0.0) return MathFailure(MathError::Range, "Division by zero", node.loc);
            return Operand(node.a, frame) / d;
        }
        case Op::Pow: {
            // As a library call: a math error in either operand, or a NaN or
            // infinite result, makes the power 0 ("Illegal power").
            const MathError saved = ctx_.mathError_;
            ctx_.mathError_ = MathError::None;
            const double x = Operand(node.a, frame);
            const double y = Operand(node.b, frame);
            errno = 0;
            const double r = std::pow(x, y);
            MathError kind = ErrnoKind(errno);
            if (kind == MathError::None) kind = ctx_.mathError_;
            if (kind == MathError::None && !std::isfinite(r)) {
                kind = std::isnan(r) ? MathError::Domain : MathError::Range;
            }
            if (kind != MathError::None) return MathFailure(kind, "Illegal power", node.loc);
            ctx_.mathError_ = saved;
            return r;
        }
        case Op::Call:
            return CallSlot(node.a, Args{frame, args_ + node.b, nullptr, node.n, node.a, node.loc});
        case Op::CallParam:
            return CallParameter(node, frame);
    }
    return 0.0;
}

double Evaluator::Variable(std::int32_t slotIndex, std::uint32_t loc) {
    const Slot& slot = code_.slots[static_cast<std::size_t>(slotIndex)];
    if (slot.def < 0 || code_.defs[static_cast<std::size_t>(slot.def)].params >= 0) {
        FailNamed("undefined variable '", slotIndex, loc, "'", loc);
    }
    const Definition& def = code_.defs[static_cast<std::size_t>(slot.def)];
    const Node& body = code_.nodes[static_cast<std::size_t>(def.body)];
    if (body.op == Op::Num) return body.num;
    if (def.constant) {
        // Radiance warns on every use of a `:` value that folding could not
        // reduce to a number, but keeps the first value.
        if (ctx_.warnings_) ctx_.warnings_(slot.name + ": assigned non-constant value");
        if (def.frozen) return def.frozenValue;
        if (foldInto_ != nullptr) {
            // Parse time: the value freezes in the Program, for every Context.
            Definition& frozen = foldInto_->code_.defs[static_cast<std::size_t>(slot.def)];
            frozen.frozen = true;  // a reference to itself reads 0, as in Radiance
            frozen.frozenValue = 0.0;
            Enter(slotIndex, loc);
            DepthScope scope(ctx_.depth_);
            const double value = Eval(def.body, nullptr);
            foldInto_->code_.defs[static_cast<std::size_t>(slot.def)].frozenValue = value;
            return value;
        }
    }
    Context::CacheEntry& entry = ctx_.cache_[static_cast<std::size_t>(slotIndex)];
    const std::uint64_t tick = def.constant ? Context::kFrozen : ctx_.clock_;
    if (entry.tick == tick) return entry.value;
    // The tick is set before computing, so a variable that refers to itself
    // reads its previous value (0 at first) instead of recursing: `x = x + 1`
    // gives 1, as in Radiance.
    entry.tick = tick;
    Enter(slotIndex, loc);
    DepthScope scope(ctx_.depth_);
    const double value = Eval(def.body, nullptr);
    ctx_.cache_[static_cast<std::size_t>(slotIndex)].value = value;
    return value;
}

double Evaluator::Parameter(Frame* frame, int index, std::uint32_t loc) {
    if (index < Frame::kCached && ((frame->done >> index) & 1u)) return frame->values[index];
    if (index >= frame->nargs) {
        FailNamed("too few arguments to '", frame->slot, frame->loc, "'",
                  frame->loc != 0 ? frame->loc : loc);
    }
    const double value = frame->argValues != nullptr
                             ? frame->argValues[index]
                             : Operand(frame->argNodes[index], frame->caller);
    if (index < Frame::kCached) {
        frame->values[index] = value;
        frame->done |= 1u << index;
    }
    return value;
}

double Evaluator::Arg(const Args& args, int i) {
    if (i >= args.n) FailNamed("too few arguments to '", args.slot, args.loc, "'", args.loc);
    if (args.values != nullptr) return args.values[i];
    return Operand(args.nodes[i], args.env);
}

double Evaluator::CallSlot(std::int32_t slotIndex, const Args& args) {
    const Slot& slot = code_.slots[static_cast<std::size_t>(slotIndex)];
    if (slot.def >= 0) {
        const Definition& def = code_.defs[static_cast<std::size_t>(slot.def)];
        if (def.params < 0) FailNamed("undefined function '", slotIndex, args.loc, "'", args.loc);
        Enter(slotIndex, args.loc);
        DepthScope scope(ctx_.depth_);
        Frame callee;
        callee.caller = args.env;
        callee.argNodes = args.nodes;
        callee.argValues = args.values;
        callee.nargs = args.n;
        callee.slot = slotIndex;
        callee.loc = args.loc;
        return Eval(def.body, &callee);
    }
    if (slot.library >= 0) {
        return Library(cal::Library()[static_cast<std::size_t>(slot.library)], args);
    }
    FailNamed("undefined function '", slotIndex, args.loc, "'", args.loc);
}

double Evaluator::CallParameter(const Node& node, Frame* frame) {
    // The parameter must have been given a bare name; follow parameters passed
    // on through intermediate calls back to that name.
    Frame* owner = frame;
    int index = node.a;
    for (;;) {
        if (index >= owner->nargs) {
            FailNamed("too few arguments to '", owner->slot, owner->loc, "'",
                      owner->loc != 0 ? owner->loc : node.loc);
        }
        if (owner->argValues == nullptr) {
            const Node& given = nodes_[owner->argNodes[index]];
            if (given.op == Op::Var) {
                return CallSlot(given.a,
                                Args{frame, args_ + node.b, nullptr, node.n, given.a, node.loc});
            }
            if (given.op == Op::Param && owner->caller != nullptr) {
                index = given.a;
                owner = owner->caller;
                continue;
            }
        }
        FailNamed("argument not a function in '", owner->slot, owner->loc, "'", node.loc);
    }
}

double Evaluator::Library(const LibraryFunction& f, const Args& args) {
    using K = LibraryFunction::Kind;
    // calcomp's libfunc(): errors inside the arguments or in the C function make
    // the call's result 0 and leave the flag set; otherwise the flag is restored.
    const MathError saved = ctx_.mathError_;
    ctx_.mathError_ = MathError::None;
    double result = 0.0;
    int cError = 0;
    switch (f.kind) {
        case K::If:
            result = Arg(args, 0) > 0.0 ? Arg(args, 1) : Arg(args, 2);
            break;
        case K::Select: {
            const double a = Arg(args, 0);
            const int count = args.n - 1;
            // k = (int)(a + 0.5); a < -0.5 or k > count is a domain error.
            if (!(a >= -0.5) || !(a + 0.5 < static_cast<double>(count) + 1.0)) {
                cError = EDOM;
                break;
            }
            const int k = static_cast<int>(a + 0.5);
            result = k == 0 ? static_cast<double>(count) : Arg(args, k);
            break;
        }
        case K::Min:
        case K::Max: {
            result = Arg(args, 0);
            for (int i = 1; i < args.n; ++i) {
                const double v = Arg(args, i);
                if (f.kind == K::Min ? v < result : v > result) result = v;
            }
            break;
        }
        case K::Rand:
            result = HashRandom(Arg(args, 0));
            break;
        case K::Arg: {
            if (ctx_.folding_) {
                Fail("bad call to arg(n) - illegal constant in .cal file?", args.loc);
            }
            const double a = Arg(args, 0) + 0.5;
            const std::size_t count = ctx_.args_.size();
            if (!(a >= 1.0)) {  // n = (int)(a + 0.5) < 1, or NaN
                result = static_cast<double>(count);
            } else if (a >= static_cast<double>(count) + 1.0) {
                const long n = a < 1e9 ? static_cast<long>(a) : 1000000000L;
                const std::string owner =
                    ctx_.argsOwner_.empty() ? std::string("the modifier") : ctx_.argsOwner_;
                Fail("missing real argument " + std::to_string(n) + " for " + owner, args.loc);
            } else {
                result = ctx_.args_[static_cast<std::size_t>(a) - 1];
            }
            break;
        }
        case K::Math1: {
            const double x = Arg(args, 0);
            errno = 0;
            result = f.f1(x);
            cError = errno;
            break;
        }
        case K::Math2: {
            const double x = Arg(args, 0);
            const double y = Arg(args, 1);
            errno = 0;
            result = f.f2(x, y);
            cError = errno;
            break;
        }
        case K::Math3: {
            const double x = Arg(args, 0);
            const double y = Arg(args, 1);
            const double z = Arg(args, 2);
            result = f.f3(x, y, z);
            break;
        }
    }
    MathError kind = ErrnoKind(cError);
    if (kind == MathError::None) kind = ctx_.mathError_;
    if (kind == MathError::None && !std::isfinite(result)) {
        kind = std::isnan(result) ? MathError::Domain : MathError::Range;
    }
    if (kind != MathError::None) {
        const std::string what =
            std::string(f.name) + (kind == MathError::Domain ? ": domain error" : ": range error");
        return MathFailure(kind, what, args.loc);
    }
    ctx_.mathError_ = saved;
    return result;
}

}  // namespace rt::cal
