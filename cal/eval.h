// SPDX-License-Identifier: MIT
//
// The tree-walking evaluator over cal/code.h (internal to cal/). It follows
// calcomp's semantics exactly: lazily evaluated function arguments remembered
// per call, `=` values cached per clock tick, `:` values frozen, math errors
// giving 0 and a flag (src/common/calexpr.c, caldefn.c, calfunc.c).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "cal/code.h"
#include "cal/context.h"

namespace rt::cal {

class Program;
struct LibraryFunction;

/// A fatal evaluation error (Radiance quits on these). Internal: the API turns
/// it into an rt::Error naming the place of `loc`.
struct EvalError {
    std::string message;
    std::uint32_t loc = 0;
};

/// One user-function call: where its argument expressions are and the values
/// of those already evaluated. Lives on the C stack of the call.
struct Frame {
    static constexpr int kCached = 16;  // parameters remembered; later ones re-evaluate
    Frame* caller = nullptr;            // environment of the argument expressions
    const std::int32_t* argNodes = nullptr;
    const double* argValues = nullptr;  // instead of argNodes, for Program::Call
    int nargs = 0;
    std::int32_t slot = 0;  // the function, for messages
    std::uint32_t loc = 0;  // the call, for messages
    std::uint32_t done = 0;
    double values[kCached];
};

class Evaluator {
  public:
    /// `foldInto`: the Program being parsed when this evaluates for
    /// constant folding (frozen `:` values are stored there); else nullptr.
    Evaluator(const Program& program, Context& context, Program* foldInto = nullptr);

    double TopExpression(std::int32_t node);
    double TopVariable(std::int32_t slot);
    double TopCall(std::int32_t slot, const double* args, int nargs);

  private:
    // The arguments of one library-function call.
    struct Args {
        Frame* env;
        const std::int32_t* nodes;
        const double* values;
        int n;
        std::int32_t slot;
        std::uint32_t loc;
    };

    void BeginTop();
    double Eval(std::int32_t node, Frame* frame);
    // Eval with the common leaves (numbers, variables already computed for
    // this evaluation) handled without a dispatch: most operands are leaves.
    double Operand(std::int32_t node, Frame* frame) {
        const Node& n = nodes_[node];
        if (n.op == Op::Num) return n.num;
        if (n.op == Op::Var) {
            const Context::CacheEntry& entry = ctx_.cache_[static_cast<std::size_t>(n.a)];
            if (entry.tick == ctx_.clock_) return entry.value;
        }
        return Eval(node, frame);
    }
    double Variable(std::int32_t slot, std::uint32_t loc);
    double Parameter(Frame* frame, int index, std::uint32_t loc);
    double CallSlot(std::int32_t slot, const Args& args);
    double CallParameter(const Node& node, Frame* frame);
    double Library(const LibraryFunction& f, const Args& args);
    double Arg(const Args& args, int i);
    double MathFailure(MathError kind, std::string_view what, std::uint32_t loc);
    void Enter(std::int32_t slot, std::uint32_t loc);
    [[noreturn]] void Fail(std::string message, std::uint32_t loc) const;
    // "<before>'<name>'<after>", built only when failing (kept out of the hot code).
    [[noreturn, gnu::cold, gnu::noinline]] void FailNamed(const char* before, std::int32_t slot,
                                                          std::uint32_t loc, const char* after,
                                                          std::uint32_t at) const;
    std::string NameAt(std::uint32_t loc, std::int32_t slot) const;

    const Program& program_;
    const Code& code_;
    const Node* nodes_;
    const std::int32_t* args_;
    Context& ctx_;
    Program* foldInto_;
};

}  // namespace rt::cal
