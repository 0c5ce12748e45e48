// SPDX-License-Identifier: MIT
//
// One evaluation of a sky function, the function-language work done for every
// ray that escapes to a gensky/gendaylit sky (ns per call): NextEvaluation()
// plus Evaluate() of the modifier's expression with gensky-like real
// arguments, cycling over 256 fixed upward directions.
//
// The *Equivalent cases use the sky formulas of radiance-functions.md §12.5
// (skybright.cal's skybr) and §12.8 (perezlum.cal's skybright), written here so
// the benchmark needs nothing outside the tree. The *Radiance cases load
// Radiance's own files from ../shared/reference/radiance-5.4a/lib when that
// folder exists, and are skipped otherwise.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "cal/program.h"
#include "cal/ray_variables.h"

#ifndef RT_SOURCE_DIR
#define RT_SOURCE_DIR "."
#endif

namespace {

constexpr const char* kCieSky = R"(
{ CIE skies: A1 type (1 clear, 2 overcast, 3 uniform, 4 intermediate),
  A2 zenith radiance, A3 ground radiance, A4 normalisation, A5 A6 A7 sun }
sun_cos = Dx*A5 + Dy*A6 + Dz*A7;
sun_angle = Acos(sun_cos);
sun_zenith = Acos(A7);
view_zenith = Acos(Dz);
blend(wa, va, wb, vb) : (wa*va + wb*vb)/(wa + wb);
skybr = blend((Dz + 1.01)^10, select(A1, clear, overcast, uniform, intermediate),
              (Dz + 1.01)^-10, A3);
clear = A2*(.91 + 10*exp(-3*sun_angle) + .45*sun_cos*sun_cos)
        *if(Dz - .01, 1 - exp(-.32/Dz), 1)/A4;
overcast = A2*(1 + 2*Dz)/3;
uniform = A2;
intermediate = A2*((1.35*sin(5.631 - 3.59*view_zenith) + 3.12)*sin(4.396 - 2.6*sun_zenith)
               + 6.37 - view_zenith)/2.326
               *exp(-.563*sun_angle*((2.629 - view_zenith)*(1.562 - sun_zenith) + .812))/A4;
)";

constexpr const char* kPerezSky = R"(
{ Perez all-weather sky: A1 normalisation, A2 ground radiance, A3..A7 the
  coefficients a..e, A8 A9 A10 sun }
sun_cos = Dx*A8 + Dy*A9 + Dz*A10;
sun_angle = Acos(sun_cos);
dz = if(Dz - .01, Dz, .01);
perez = A1*(1 + A3*Exp(A4/dz))*(1 + A5*Exp(A6*sun_angle) + A7*sun_cos*sun_cos);
blend(wa, va, wb, vb) = (wa*va + wb*vb)/(wa + wb);
skybright = blend((Dz + 1.01)^10, perez, (Dz + 1.01)^-10, A2);
)";

// gensky 3 21 12 +s (type 1) and -c (type 2) style arguments.
const std::vector<double> kClearArgs = {1, 35.1, 6.2, 1.21, 0.0, -0.556, 0.831};
const std::vector<double> kOvercastArgs = {2, 12.4, 2.5, 1.0, 0.0, -0.556, 0.831};
// gendaylit-style Perez coefficients.
const std::vector<double> kPerezArgs = {20.8,  3.82, -1.0, -0.55,  6.55,
                                        -2.68, 0.35, 0.0,  -0.636, 0.772};

struct Ray : rt::cal::ChannelSource {
    double d[3] = {0, 0, 1};
    double Channel(int n) const override {
        switch (n) {
            case rt::cal::kDx:
                return d[0];
            case rt::cal::kDy:
                return d[1];
            case rt::cal::kDz:
                return d[2];
            case rt::cal::kNx:
                return -d[0];
            case rt::cal::kNy:
                return -d[1];
            case rt::cal::kNz:
                return -d[2];
            case rt::cal::kT:
                return 1e10;
            case rt::cal::kTs:
                return 1e10;
            case rt::cal::kRdot:
                return 1.0;
            case rt::cal::kS:
                return 1.0;
            default:
                return 0.0;
        }
    }
};

std::vector<std::array<double, 3>> Directions() {
    std::vector<std::array<double, 3>> dirs;
    for (int i = 0; i < 256; ++i) {
        const double z = (i + 0.5) / 256.0, phi = 2.399963 * i;  // golden-angle spiral
        const double r = std::sqrt(1 - z * z);
        dirs.push_back({r * std::cos(phi), r * std::sin(phi), z});
    }
    return dirs;
}

void RunSky(benchmark::State& state, rt::cal::Program& program, const std::string& context,
            const char* expression, const std::vector<double>& args) {
    const rt::cal::Expression sky =
        program.CompileExpression(expression, "brightfunc \"skyfunc\"", context);
    rt::cal::Context ctx(program);
    Ray ray;
    ctx.SetChannels(&ray);
    ctx.SetArguments(args, "brightfunc \"skyfunc\"");
    const std::vector<std::array<double, 3>> dirs = Directions();
    std::size_t i = 0;
    double sum = 0.0;
    for (auto _ : state) {
        const std::array<double, 3>& d = dirs[i++ & 255];
        ray.d[0] = d[0];
        ray.d[1] = d[1];
        ray.d[2] = d[2];
        ctx.NextEvaluation();
        sum += program.Evaluate(sky, ctx);
    }
    benchmark::DoNotOptimize(sum);
    if (ctx.mathError() != rt::cal::MathError::None) state.SkipWithError("math error");
}

rt::cal::Program RtraceProgram() {
    rt::cal::Program program;
    program.DefineRayVariables();
    rt::cal::SearchPath builtins;  // lazyrad's own rayinit.cal, whatever RAYPATH says
    program.LoadRayinit(builtins);
    return program;
}

void BM_CalSkybrEquivalent(benchmark::State& state) {
    rt::cal::Program program = RtraceProgram();
    program.LoadText(kCieSky, "cie_sky.cal", "cie_sky");
    RunSky(state, program, "cie_sky", "skybr", state.range(0) == 1 ? kClearArgs : kOvercastArgs);
}
BENCHMARK(BM_CalSkybrEquivalent)->Arg(1)->Arg(2);

void BM_CalPerezEquivalent(benchmark::State& state) {
    rt::cal::Program program = RtraceProgram();
    program.LoadText(kPerezSky, "perez_sky.cal", "perez_sky");
    RunSky(state, program, "perez_sky", "skybright", kPerezArgs);
}
BENCHMARK(BM_CalPerezEquivalent);

const std::string kRadianceLib =
    std::string(RT_SOURCE_DIR) + "/../shared/reference/radiance-5.4a/lib";

void RunRadiance(benchmark::State& state, const char* file, const char* expression,
                 const std::vector<double>& args) {
    rt::cal::SearchPath radiance;
    radiance.entries = {kRadianceLib};
    radiance.builtins = false;
    if (!rt::cal::FindFunctionFile(file, radiance)) {
        state.SkipWithError("Radiance's lib/ not found (../shared absent)");
        return;
    }
    rt::cal::Program program = RtraceProgram();
    const std::string context = program.LoadFile(file, radiance);
    RunSky(state, program, context, expression, args);
}

void BM_CalSkybrRadiance(benchmark::State& state) {
    RunRadiance(state, "skybright.cal", "skybr", state.range(0) == 1 ? kClearArgs : kOvercastArgs);
}
BENCHMARK(BM_CalSkybrRadiance)->Arg(1)->Arg(2);

void BM_CalPerezRadiance(benchmark::State& state) {
    RunRadiance(state, "perezlum.cal", "skybright", kPerezArgs);
}
BENCHMARK(BM_CalPerezRadiance);

}  // namespace
