// SPDX-License-Identifier: MIT
//
// Fuzz target: arbitrary bytes as a function file (statements, in a file
// context, after rtrace's globals and lazyrad's rayinit.cal), then as one
// expression; every variable the text defines is then evaluated with a ray
// and real arguments. rt::Error is the expected way to reject input or stop
// an evaluation; a crash, UB, a hang or another exception type is a finding.
// The call limit turns exponential recursion into an error instead of a hang.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "cal/program.h"
#include "cal/ray_variables.h"
#include "core/error.h"
#include "tests/fuzz/fuzz_entry.h"

namespace {

struct FixedRay : rt::cal::ChannelSource {
    double Channel(int n) const override { return 0.25 * n - 3.0; }
};

void EvaluateAll(const rt::cal::Program& program, std::size_t firstSlot) {
    rt::cal::Context context(program);
    const FixedRay ray;
    const std::vector<double> args = {1.0, -2.0, 0.5};
    context.SetChannels(&ray);
    context.SetArguments(args, "brightfunc \"fuzz\"");
    context.SetCallLimit(20000);
    const std::vector<rt::cal::Slot>& slots = program.code().slots;
    for (std::size_t s = firstSlot; s < slots.size(); ++s) {
        if (slots[s].def < 0) continue;
        context.NextEvaluation();
        try {
            const rt::cal::Variable v{static_cast<std::int32_t>(s)};
            static_cast<void>(program.Evaluate(v, context));
        } catch (const rt::Error& e) {
            rt::fuzz::ExpectRefusal(e);
            // A fatal evaluation error: expected for arbitrary input.
        }
    }
}

}  // namespace

extern "C" int RT_FUZZ_ENTRY(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    rt::cal::Program program(rt::cal::Options{}, [](const std::string&) {});
    program.DefineRayVariables();
    program.LoadRayinit(rt::cal::SearchPath{});
    const std::size_t firstSlot = program.code().slots.size();
    try {
        program.LoadText(text, "fuzz.cal", "fuzz");
    } catch (const rt::Error& e) {
        rt::fuzz::ExpectRefusal(e);
        // Rejected input: expected.
    }
    EvaluateAll(program, firstSlot);
    try {
        const rt::cal::Expression e = program.CompileExpression(text, "brightfunc \"fuzz\"");
        rt::cal::Context context(program);
        const FixedRay ray;
        context.SetChannels(&ray);
        context.SetCallLimit(20000);
        context.NextEvaluation();
        static_cast<void>(program.Evaluate(e, context));
    } catch (const rt::Error& e) {
        rt::fuzz::ExpectRefusal(e);
    }
    return 0;
}
