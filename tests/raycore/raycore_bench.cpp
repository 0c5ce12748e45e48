// SPDX-License-Identifier: MIT
//
// Closest-hit throughput on a simple room (Cornell-box-like: six walls, two
// blocks, a ceiling light panel, a sphere), rays from random points inside in
// random directions; or, given .rad files, that scene with ray origins in
// the middle 90% of its bounding cube. Not a test: run by hand.
//   raycore_bench [rays per thread, default 2000000] [threads, default 1] [scene.rad ...]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "raycore/raycore.h"
#include "scene/loader.h"
#include "tests/raycore/test_scenes.h"

namespace {

rt::Scene Room() {
    rt::testing::SceneBuilder b;
    const int white = b.AddMaterial(rt::MaterialType::Plastic);
    const int light = b.AddMaterial(rt::MaterialType::Light);
    // Walls facing inwards: the box quads face outwards, so build the room
    // as a box (orientation does not matter to the ray core).
    b.AddBox({0, 0, 0}, {5.5, 5.5, 5.5}, white);
    b.AddBox({1.3, 0.65, 0}, {2.9, 2.25, 1.65}, white);
    b.AddBox({2.65, 2.95, 0}, {4.3, 4.6, 3.3}, white);
    b.AddPolygon({{2.1, 2.1, 5.49}, {3.4, 2.1, 5.49}, {3.4, 3.4, 5.49}, {2.1, 3.4, 5.49}}, light);
    b.AddSphere({4.2, 1.2, 0.8}, 0.8, false, white);
    b.scene().cubeOrigin = {-1e-5, -1e-5, -1e-5};
    b.scene().cubeSize = 5.5 + 2e-5;
    return b.scene();
}

}  // namespace

int main(int argc, char** argv) {
    const long count = argc > 1 ? std::atol(argv[1]) : 2000000;
    const int threads = argc > 2 ? std::atoi(argv[2]) : 1;
    std::vector<std::string> files(argv + std::min(argc, 3), argv + argc);
    const rt::Scene scene =
        files.empty() ? Room() : rt::LoadScene(files, {}, [](const std::string&) {});
    const rt::Vec3 lo = scene.cubeOrigin + rt::Vec3{1, 1, 1} * (0.05 * scene.cubeSize);
    const double span = 0.9 * scene.cubeSize;
    const rt::RayCore core(scene);

    // Rays are generated before timing so only the queries are measured.
    struct Ray {
        rt::Vec3 org, dir;
    };
    std::vector<std::vector<Ray>> work(static_cast<size_t>(threads));
    for (int t = 0; t < threads; ++t) {
        std::mt19937 rng(static_cast<unsigned>(17 + t));
        std::uniform_real_distribution<double> pos(0, span);
        std::normal_distribution<double> g;
        auto& rays = work[static_cast<size_t>(t)];
        rays.reserve(static_cast<size_t>(count));
        for (long i = 0; i < count; ++i) {
            rays.push_back({lo + rt::Vec3{pos(rng), pos(rng), pos(rng)},
                            rt::Normalize({g(rng), g(rng), g(rng)})});
        }
    }
    std::vector<long> hits(static_cast<size_t>(threads), 0);
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) {
        pool.emplace_back([&, t] {
            long n = 0;
            for (const Ray& r : work[static_cast<size_t>(t)]) {
                if (core.Intersect(r.org, r.dir, 0)) ++n;
            }
            hits[static_cast<size_t>(t)] = n;
        });
    }
    for (auto& th : pool) th.join();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    long total = 0;
    for (long h : hits) total += h;
    const double rays = static_cast<double>(count) * threads;
    std::printf("%d thread(s), %.0f closest-hit queries in %.3f s: %.2f Mrays/s (%.1f%% hit)\n",
                threads, rays, seconds, rays / seconds / 1e6,
                100.0 * static_cast<double>(total) / rays);
    return 0;
}
