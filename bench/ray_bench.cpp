// SPDX-License-Identifier: MIT
//
// Ray throughput: raw Embree (rtcIntersect1 on the scene's triangles, nothing
// else) against lazyrad's RayCore (Embree plus the double-precision hit
// recomputation and Radiance's coincidence rules) and against the full shading
// path (Renderer::TraceInput: materials, direct light with shadow rays, the
// indirect calculation), all on the cornell box. Raw Embree is the limit; the
// rays/s ratios are our efficiency against it (docs/benchmarks.md).
//
// This file includes <embree3/rtcore.h> outside raycore/ on purpose: the raw
// baseline must not go through our wrapper. Nothing else here may use Embree.
// (The RayCore part was tests/raycore/raycore_bench.cpp.)
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include "raycore/raycore.h"
#include "scene/loader.h"
#include "shading/renderer.h"
#include "tests/raycore/test_scenes.h"

#ifndef RT_SOURCE_DIR
#define RT_SOURCE_DIR "."
#endif

namespace {

const std::string kCornell = std::string(RT_SOURCE_DIR) + "/scenes/cornell/cornell.rad";

const rt::Scene& Cornell() {
    static const rt::Scene scene = rt::LoadScene({kCornell}, {}, [](const std::string&) {});
    return scene;
}

// The simple room raycore_bench used: six walls, two blocks, a light panel, a sphere.
rt::Scene Room() {
    rt::testing::SceneBuilder b;
    const int white = b.AddMaterial(rt::MaterialType::Plastic);
    const int light = b.AddMaterial(rt::MaterialType::Light);
    b.AddBox({0, 0, 0}, {5.5, 5.5, 5.5}, white);
    b.AddBox({1.3, 0.65, 0}, {2.9, 2.25, 1.65}, white);
    b.AddBox({2.65, 2.95, 0}, {4.3, 4.6, 3.3}, white);
    b.AddPolygon({{2.1, 2.1, 5.49}, {3.4, 2.1, 5.49}, {3.4, 3.4, 5.49}, {2.1, 3.4, 5.49}}, light);
    b.AddSphere({4.2, 1.2, 0.8}, 0.8, false, white);
    b.scene().cubeOrigin = {-1e-5, -1e-5, -1e-5};
    b.scene().cubeSize = 5.5 + 2e-5;
    return b.scene();
}

struct Ray {
    rt::Vec3 org, dir;
};

// Origins uniform in the middle 90 % of the scene cube, directions uniform on
// the sphere; generated before timing so only the queries are measured.
std::vector<Ray> RandomRays(const rt::Scene& scene, std::size_t count) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> pos(0, 0.9 * scene.cubeSize);
    std::normal_distribution<double> g;
    const rt::Vec3 lo = scene.cubeOrigin + rt::Vec3{1, 1, 1} * (0.05 * scene.cubeSize);
    std::vector<Ray> rays(count);
    for (Ray& r : rays) {
        r.org = lo + rt::Vec3{pos(rng), pos(rng), pos(rng)};
        r.dir = rt::Normalize({g(rng), g(rng), g(rng)});
    }
    return rays;
}

constexpr std::size_t kRays = 1 << 16;

void RayCoreClosestHit(benchmark::State& state, const rt::Scene& scene) {
    const rt::RayCore core(scene);
    const std::vector<Ray> rays = RandomRays(scene, kRays);
    std::size_t i = 0, hits = 0;
    for (auto _ : state) {
        const Ray& r = rays[i++ & (kRays - 1)];
        if (core.Intersect(r.org, r.dir, 0)) ++hits;
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["hit%"] = 100.0 * static_cast<double>(hits) / static_cast<double>(state.iterations());
}

void BM_RayCore_Room(benchmark::State& state) {
    static const rt::Scene room = Room();
    RayCoreClosestHit(state, room);
}
BENCHMARK(BM_RayCore_Room);

void BM_RayCore_Cornell(benchmark::State& state) { RayCoreClosestHit(state, Cornell()); }
BENCHMARK(BM_RayCore_Cornell);

// Shadow rays as the direct calculation sends them: from points on the
// surfaces (closest hits of random rays) to random points on the lamp,
// stopping just short of it. Exercises the interior layer that leaves the
// room's bounding polygons out (raycore/hull.h).
void BM_RayCore_ShadowRays_Cornell(benchmark::State& state) {
    const rt::Scene& scene = Cornell();
    const rt::RayCore core(scene);
    const auto lamp = std::find_if(scene.surfaces.begin(), scene.surfaces.end(),
                                   [](const rt::Surface& s) { return s.name == "lamp_panel"; });
    const auto& corners = std::get<rt::Polygon>(lamp->shape).vertices;
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Ray> segments;
    std::vector<double> lengths;
    for (const Ray& r : RandomRays(scene, kRays)) {
        const auto hit = core.Intersect(r.org, r.dir, 0);
        if (!hit || hit->surface == lamp - scene.surfaces.begin()) continue;
        const rt::Vec3 target = corners[0] + (corners[1] - corners[0]) * u(rng) +
                                (corners[3] - corners[0]) * u(rng);
        const rt::Vec3 d = target - hit->point;
        const double length = rt::Length(d);
        segments.push_back({hit->point, d / length});
        lengths.push_back(length * (1 - 1e-7));
    }
    std::size_t i = 0, blocked = 0;
    for (auto _ : state) {
        const std::size_t k = i++ % segments.size();
        if (core.Occluded(segments[k].org, segments[k].dir, lengths[k])) ++blocked;
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["blocked%"] =
        100.0 * static_cast<double>(blocked) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_RayCore_ShadowRays_Cornell);

// The cornell polygons as one Embree triangle mesh (fans: its polygons are
// convex), single precision, nothing else: the raw baselines' scene.
struct RawCornell {
    RTCDevice device = nullptr;
    RTCScene rtc = nullptr;
    RawCornell();
    ~RawCornell() {
        rtcReleaseScene(rtc);
        rtcReleaseDevice(device);
    }
    RawCornell(const RawCornell&) = delete;
    RawCornell& operator=(const RawCornell&) = delete;
};

RawCornell::RawCornell() {
    const rt::Scene& scene = Cornell();
    std::vector<float> vertices;
    std::vector<unsigned> triangles;
    for (const rt::Surface& s : scene.surfaces) {
        const auto* poly = std::get_if<rt::Polygon>(&s.shape);
        if (poly == nullptr) {
            continue;
        }
        const auto base = static_cast<unsigned>(vertices.size() / 3);
        for (const rt::Vec3& v : poly->vertices) {
            vertices.insert(vertices.end(), {static_cast<float>(v.x), static_cast<float>(v.y),
                                             static_cast<float>(v.z)});
        }
        for (std::size_t k = 2; k < poly->vertices.size(); ++k) {
            triangles.insert(triangles.end(), {base, base + static_cast<unsigned>(k) - 1,
                                               base + static_cast<unsigned>(k)});
        }
    }
    device = rtcNewDevice(nullptr);
    rtc = rtcNewScene(device);
    RTCGeometry mesh = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(
        mesh, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertices.size() / 3));
    std::copy(vertices.begin(), vertices.end(), vb);
    auto* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        mesh, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangles.size() / 3));
    std::copy(triangles.begin(), triangles.end(), ib);
    rtcCommitGeometry(mesh);
    rtcAttachGeometry(rtc, mesh);
    rtcReleaseGeometry(mesh);
    rtcCommitScene(rtc);
}

// A raw Embree ray from (org, dir), float, tnear 1e-6, tfar `tfar`, no hit yet.
RTCRayHit RawRay(const rt::Vec3& org, const rt::Vec3& dir, float tfar) {
    RTCRayHit rh{};
    rh.ray.org_x = static_cast<float>(org.x);
    rh.ray.org_y = static_cast<float>(org.y);
    rh.ray.org_z = static_cast<float>(org.z);
    rh.ray.dir_x = static_cast<float>(dir.x);
    rh.ray.dir_y = static_cast<float>(dir.y);
    rh.ray.dir_z = static_cast<float>(dir.z);
    rh.ray.tnear = 1e-6f;
    rh.ray.tfar = tfar;
    rh.ray.mask = 0xffffffffu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

// Closest hit with rtcIntersect1 on random rays.
void BM_RawEmbree_Cornell(benchmark::State& state) {
    const RawCornell raw;
    const std::vector<Ray> rays = RandomRays(Cornell(), kRays);
    std::size_t i = 0, hits = 0;
    RTCIntersectContext context;
    for (auto _ : state) {
        const Ray& r = rays[i++ & (kRays - 1)];
        RTCRayHit rh = RawRay(r.org, r.dir, 1e30f);
        rtcInitIntersectContext(&context);
        rtcIntersect1(raw.rtc, &context, &rh);
        if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) ++hits;
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["hit%"] = 100.0 * static_cast<double>(hits) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_RawEmbree_Cornell);

// Input rays "ox oy oz dx dy dz" per line.
std::vector<Ray> ReadRays(const std::string& path) {
    std::ifstream in(path);
    std::vector<Ray> rays;
    Ray r;
    while (in >> r.org.x >> r.org.y >> r.org.z >> r.dir.x >> r.dir.y >> r.dir.z) {
        r.dir = rt::Normalize(r.dir);
        rays.push_back(r);
    }
    return rays;
}

// The full shading path. Items are input rays; "rays/s" counts every ray the
// renderer traced (hemisphere, specular and shadow rays included), the number
// to compare with raw Embree's closest-hit rate.
void FullShading(benchmark::State& state, const std::string& input, rt::ShadingOptions shading,
                 rt::AmbientOptions ambient) {
    const rt::Scene& scene = Cornell();
    const rt::RayCore core(scene);
    rt::Renderer renderer(scene, core, shading, ambient, [](const std::string&) {});
    const std::vector<Ray> rays = ReadRays(std::string(RT_SOURCE_DIR) + input);
    if (rays.empty()) {
        state.SkipWithError("no input rays");
        return;
    }
    std::uint64_t index = 0;
    for (auto _ : state) {
        const Ray& r = rays[index % rays.size()];
        benchmark::DoNotOptimize(renderer.TraceInput(r.org, r.dir, 0, index++));
    }
    const rt::RenderStats& stats = renderer.Stats();
    state.SetItemsProcessed(state.iterations());
    state.counters["rays/s"] = benchmark::Counter(
        static_cast<double>(stats.raysTraced + stats.shadowRays), benchmark::Counter::kIsRate);
    state.counters["shadow share"] =
        static_cast<double>(stats.shadowRays) /
        static_cast<double>(std::max<std::uint64_t>(1, stats.raysTraced + stats.shadowRays));
}

// -ab 0: eye rays of the 32x32 view, direct light only.
void BM_FullShading_Cornell_ab0(benchmark::State& state) {
    FullShading(state, "/scenes/cornell/cam32.rays", {}, {});
}
BENCHMARK(BM_FullShading_Cornell_ab0);

// -I -ab 2 -aa 0 -ad 64 -as 0: irradiance at the floor points, no cache.
rt::ShadingOptions NoCacheShading() {
    rt::ShadingOptions shading;
    shading.irradiance = rt::IrradianceMode::Immediate;
    return shading;
}
rt::AmbientOptions NoCacheAmbient() {
    rt::AmbientOptions ambient;
    ambient.bounces = 2;
    ambient.accuracy = 0;
    ambient.divisions = 64;
    ambient.superSamples = 0;
    return ambient;
}
const char* const kFloorPoints = "/scenes/cornell/floor.pts";

void BM_FullShading_Cornell_I_ab2_nocache(benchmark::State& state) {
    FullShading(state, kFloorPoints, NoCacheShading(), NoCacheAmbient());
}
BENCHMARK(BM_FullShading_Cornell_I_ab2_nocache);

// Raw Embree on the same rays as BM_FullShading_Cornell_I_ab2_nocache: every
// closest-hit and occlusion query that run makes (all 84 floor points once,
// logged by RayCore::SetQueryLog), replayed in order on RawCornell with
// rtcIntersect1 / rtcOccluded1 and the queries' own tmax. Unlike random rays
// from anywhere in the box, these start on surfaces, and half of them are
// shadow rays, cheaper for Embree; lazyrad answers some shadow rays without
// Embree (raycore/hull.h, source_plane.h), which raw Embree still traces.
const std::vector<rt::RayCore::LoggedQuery>& NoCacheQueries() {
    static const std::vector<rt::RayCore::LoggedQuery> log = [] {
        const rt::Scene& scene = Cornell();
        std::vector<rt::RayCore::LoggedQuery> queries;
        rt::RayCore core(scene);
        rt::Renderer renderer(scene, core, NoCacheShading(), NoCacheAmbient(),
                              [](const std::string&) {});
        core.SetQueryLog(&queries);
        const std::vector<Ray> points = ReadRays(std::string(RT_SOURCE_DIR) + kFloorPoints);
        for (std::size_t k = 0; k < points.size(); ++k) {
            renderer.TraceInput(points[k].org, points[k].dir, 0, k);
        }
        core.SetQueryLog(nullptr);
        return queries;
    }();
    return log;
}

void BM_RawEmbree_Cornell_SameRays(benchmark::State& state) {
    const std::vector<rt::RayCore::LoggedQuery>& log = NoCacheQueries();
    if (log.empty()) {
        state.SkipWithError("no queries logged");
        return;
    }
    const RawCornell raw;
    std::size_t i = 0, answered = 0, occlusions = 0;
    RTCIntersectContext context;
    for (auto _ : state) {
        const rt::RayCore::LoggedQuery& q = log[i++ % log.size()];
        RTCRayHit rh = RawRay(q.org, q.dir, q.tmax > 0 ? static_cast<float>(q.tmax) : 1e30f);
        rtcInitIntersectContext(&context);
        if (q.occlusion) {
            ++occlusions;
            rtcOccluded1(raw.rtc, &context, &rh.ray);
            if (rh.ray.tfar < 0) ++answered;  // -inf: occluded
        } else {
            rtcIntersect1(raw.rtc, &context, &rh);
            if (rh.hit.geomID != RTC_INVALID_GEOMETRY_ID) ++answered;
        }
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["queries logged"] = static_cast<double>(log.size());
    state.counters["shadow share"] =
        static_cast<double>(occlusions) / static_cast<double>(state.iterations());
    state.counters["hit or blocked%"] =
        100.0 * static_cast<double>(answered) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_RawEmbree_Cornell_SameRays);

// lazyrad's ray core on the same queries (without the shading's `leaving`
// normals and ignored surfaces, which it does not log): what the ray core
// itself adds to raw Embree on these rays.
void BM_RayCore_Cornell_SameRays(benchmark::State& state) {
    const std::vector<rt::RayCore::LoggedQuery>& log = NoCacheQueries();
    if (log.empty()) {
        state.SkipWithError("no queries logged");
        return;
    }
    const rt::RayCore core(Cornell());
    std::size_t i = 0, answered = 0;
    for (auto _ : state) {
        const rt::RayCore::LoggedQuery& q = log[i++ % log.size()];
        if (q.occlusion ? core.Occluded(q.org, q.dir, q.tmax, rt::Occluders::Opaque)
                        : core.Intersect(q.org, q.dir, q.tmax).has_value()) {
            ++answered;
        }
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["hit or blocked%"] =
        100.0 * static_cast<double>(answered) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_RayCore_Cornell_SameRays);

}  // namespace
