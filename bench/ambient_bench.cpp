// SPDX-License-Identifier: MIT
//
// Google Benchmark microbenchmarks of the irradiance cache's parts, apart from
// ray tracing: record index lookup (SphereGrid::ForEachContaining), cache
// interpolation (AmbientCache::Interpolate), hemisphere sampling
// (SampleHemisphere with an analytic trace function, so only the sampler and
// gradient code is timed) and record creation (MakeClassicRecord).
//   build/bin/lazyrad_bench --benchmark_filter=RecordIndex
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "ambient/cache.h"
#include "ambient/hemisphere.h"
#include "ambient/hessian.h"
#include "ambient/limits.h"
#include "core/random.h"
#include "octree/sphere_grid.h"

namespace {

// n spheres in the unit cube with radii log-uniform in [0.005, 0.05] (a
// record population of roughly the shape the cornell floor run builds).
rt::SphereGrid MakeTree(int n, rt::Rng& rng) {
    rt::SphereGrid tree({0, 0, 0}, 1.0);
    for (int i = 0; i < n; ++i) {
        const rt::Vec3 c(rng.Uniform(), rng.Uniform(), rng.Uniform());
        const double r = 0.005 * std::pow(10.0, rng.Uniform());
        tree.Insert(c, r, static_cast<std::uint32_t>(i));
    }
    return tree;
}

void BM_RecordIndexLookup(benchmark::State& state) {
    rt::Rng rng(1);
    const rt::SphereGrid tree = MakeTree(static_cast<int>(state.range(0)), rng);
    std::vector<rt::Vec3> queries(4096);
    for (auto& q : queries) q = {rng.Uniform(), rng.Uniform(), rng.Uniform()};
    std::size_t i = 0;
    std::uint64_t found = 0;
    for (auto _ : state) {
        tree.ForEachContaining(queries[i++ & 4095], [&](std::uint32_t) { ++found; });
    }
    benchmark::DoNotOptimize(found);
    state.SetItemsProcessed(state.iterations());
    state.counters["found/query"] =
        static_cast<double>(found) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_RecordIndexLookup)->Arg(1000)->Arg(10000)->Arg(100000);

// Records on the floor z = 0 of a unit cube, normals up, radius 0.02..0.06,
// as a cache of `n` first-bounce records; queries are floor points.
void BM_CacheInterpolate(benchmark::State& state) {
    rt::Rng rng(2);
    const rt::AmbientLimits limits = rt::AmbientLimits::FromResolution(256, 1.0);
    rt::AmbientCache cache({0, 0, -0.5}, 1.0, 0.1, limits);
    for (int i = 0; i < state.range(0); ++i) {
        rt::AmbientRecord r;
        r.position = {rng.Uniform(), rng.Uniform(), 0};
        r.normal = {0, 0, 1};
        r.uAxis = {1, 0, 0};
        r.value = {0.5, 0.4, 0.3};
        r.radius[0] = r.radius[1] = 0.02 + 0.04 * rng.Uniform();
        r.posGradient[0] = 0.5 * (rng.Uniform() - 0.5);
        cache.Add(r);
    }
    std::vector<rt::AmbientQuery> queries(4096);
    for (auto& q : queries) {
        q.point = {rng.Uniform(), rng.Uniform(), 0};
        q.normal = q.shadingNormal = {0, 0, 1};
    }
    std::size_t i = 0, hits = 0;
    for (auto _ : state) {
        if (cache.Interpolate(queries[i++ & 4095])) ++hits;
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["hit rate"] = static_cast<double>(hits) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_CacheInterpolate)->Arg(1000)->Arg(10000);

// A smooth analytic environment: sky-like radiance rising towards the
// normal, hit distance varying with direction (so gradients are non-zero).
std::optional<rt::AmbientSample> Analytic(const rt::Vec3& d) {
    return rt::AmbientSample{rt::Rgb(1 + d.z, 1 + 0.5 * d.x, 1 + 0.25 * d.y), 1.0 + 0.5 * d.x * d.x};
}

void BM_HemisphereSampling(benchmark::State& state) {
    rt::HemisphereOptions options;
    options.divisions = static_cast<int>(state.range(0));
    options.superSamples = static_cast<int>(state.range(0) / 2);
    rt::Rng rng(3);
    const rt::AmbientTraceFn trace = Analytic;
    std::uint64_t rays = 0;
    for (auto _ : state) {
        rt::Hemisphere h = rt::SampleHemisphere({0, 0, 1}, options, rng, trace);
        rays += static_cast<std::uint64_t>(h.raysTraced);
        benchmark::DoNotOptimize(h);
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["samples/s"] = benchmark::Counter(static_cast<double>(rays),
                                                     benchmark::Counter::kIsRate);
}
BENCHMARK(BM_HemisphereSampling)->Arg(128)->Arg(512)->Arg(1024);

// Radiance 5's square-grid hemisphere and its record (Hessian, ellipse,
// gradients, corral) at -ad N -as N/2, less the tracing: the per-ray
// overhead that the -ah+ method adds to the cost of its rays.
void BM_HessianRecord(benchmark::State& state) {
    rt::HemisphereOptions options;
    options.divisions = static_cast<int>(state.range(0));
    options.superSamples = static_cast<int>(state.range(0) / 2);
    rt::Rng rng(6);
    const rt::AmbientTraceFn trace = Analytic;
    const rt::AmbientLimits limits = rt::AmbientLimits::FromResolution(256, 5.56);
    std::uint64_t rays = 0;
    for (auto _ : state) {
        const rt::HessianHemisphere h = rt::SampleHessianHemisphere(
            {1, 2, 0}, {0, 0, 1}, options, rt::HessianFarDistance(5.56), rng, trace);
        auto record = rt::MakeHessianRecord(h, 0, 1.0, 0.1, limits);
        rays += static_cast<std::uint64_t>(h.raysTraced);
        benchmark::DoNotOptimize(record);
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["samples/s"] = benchmark::Counter(static_cast<double>(rays),
                                                     benchmark::Counter::kIsRate);
}
BENCHMARK(BM_HessianRecord)->Arg(128)->Arg(512)->Arg(1024);

void BM_RecordCreation(benchmark::State& state) {
    rt::HemisphereOptions options;  // -ad 1024 -as 512
    rt::Rng rng(4);
    const rt::Hemisphere h = rt::SampleHemisphere({0, 0, 1}, options, rng, rt::AmbientTraceFn(Analytic));
    const rt::AmbientLimits limits = rt::AmbientLimits::FromResolution(256, 5.56);
    for (auto _ : state) {
        auto record = rt::MakeClassicRecord({1, 2, 0}, {0, 0, 1}, h, 0, 1.0, limits);
        benchmark::DoNotOptimize(record);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_RecordCreation);

// Record creation as the renderer does it, less the tracing: sample a
// hemisphere, make the record and insert it into a growing cache.
void BM_RecordCreationAndInsert(benchmark::State& state) {
    rt::HemisphereOptions options;
    options.divisions = static_cast<int>(state.range(0));
    options.superSamples = static_cast<int>(state.range(0) / 2);
    rt::Rng rng(5);
    const rt::AmbientTraceFn trace = Analytic;
    const rt::AmbientLimits limits = rt::AmbientLimits::FromResolution(256, 1.0);
    rt::AmbientCache cache({0, 0, -0.5}, 1.0, 0.1, limits);
    for (auto _ : state) {
        const rt::Vec3 p(rng.Uniform(), rng.Uniform(), 0);
        rt::Hemisphere h = rt::SampleHemisphere({0, 0, 1}, options, rng, trace);
        if (auto record = rt::MakeClassicRecord(p, {0, 0, 1}, h, 0, 1.0, limits)) {
            cache.Add(*record);
        }
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_RecordCreationAndInsert)->Arg(1024);

}  // namespace
