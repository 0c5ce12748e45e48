// SPDX-License-Identifier: MIT
//
// Rough throughput of SphereGrid on an irradiance-cache-like load: records
// on surfaces (the 6 faces of a box plus 4 interior planes), radii
// log-uniform over one decade, queries on the same surfaces. Prints numbers;
// asserts nothing.
//
//   octree_bench [numRecords=1000000] [numQueries=2000000] [threads=4] [random|coherent]
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string_view>
#include <thread>
#include <vector>

#include "octree/sphere_grid.h"

namespace {

using rt::Vec3;
using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// A point on one of 10 axis-aligned planes in the unit cube.
Vec3 SurfacePoint(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Vec3 p(unit(rng), unit(rng), unit(rng));
    const int plane = static_cast<int>(rng() % 10);
    const int axis = plane % 3;
    const double offsets[] = {0.0, 1.0, 0.3, 0.7};
    p[axis] = offsets[plane / 3 < 4 ? plane / 3 : 0];
    return p;
}

}  // namespace

int main(int argc, char** argv) {
    const std::size_t numRecords = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1000000;
    const std::size_t numQueries = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 2000000;
    const int numThreads = argc > 3 ? std::atoi(argv[3]) : 4;

    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    // Radius chosen so each surface point is covered by ~10 records.
    const double surfaceArea = 10.0;
    const double baseRadius = std::sqrt(10.0 * surfaceArea / (3.14159 * static_cast<double>(numRecords)));

    std::vector<Vec3> centres(numRecords);
    std::vector<double> radii(numRecords);
    for (std::size_t i = 0; i < numRecords; ++i) {
        centres[i] = SurfacePoint(rng);
        radii[i] = baseRadius * std::pow(10.0, unit(rng) - 0.5);
    }
    std::vector<Vec3> queries(numQueries);
    for (Vec3& q : queries) {
        q = SurfacePoint(rng);
    }
    // A renderer's queries are spatially coherent (neighbouring pixels hit
    // neighbouring points); "coherent" sorts the queries to mimic that.
    const bool coherent = argc > 4 && std::string_view(argv[4]) == "coherent";
    if (coherent) {
        std::sort(queries.begin(), queries.end(), [](const Vec3& a, const Vec3& b) {
            const int ka = static_cast<int>(a.x * 64) * 4096 + static_cast<int>(a.y * 64) * 64 +
                           static_cast<int>(a.z * 64);
            const int kb = static_cast<int>(b.x * 64) * 4096 + static_cast<int>(b.y * 64) * 64 +
                           static_cast<int>(b.z * 64);
            return ka < kb;
        });
    }

    rt::SphereGrid tree(Vec3(-0.001, -0.001, -0.001), 1.002);
    auto start = Clock::now();
    for (std::size_t i = 0; i < numRecords; ++i) {
        tree.Insert(centres[i], radii[i], static_cast<std::uint32_t>(i));
    }
    const double insertSeconds = SecondsSince(start);
    const rt::SphereGrid::Shape shape = tree.GetShape();
    std::printf("records %zu  radius ~%.4g  insert %.3f s (%.2f M/s)\n", numRecords, baseRadius,
                insertSeconds, static_cast<double>(numRecords) / insertSeconds * 1e-6);
    std::printf("cells %zu  entries %zu (%.2f per record)  classes %d  loose %zu\n", shape.cells,
                shape.listed, static_cast<double>(shape.listed) / static_cast<double>(numRecords),
                shape.classesUsed, shape.looseItems);

    std::size_t sampleNodes = 0, sampleTested = 0, sampleFound = 0;
    for (std::size_t i = 0; i < std::min<std::size_t>(numQueries, 10000); ++i) {
        const auto q = tree.CountVisits(queries[i]);
        sampleNodes += q.cellsProbed;
        sampleTested += q.itemsTested;
        sampleFound += q.itemsFound;
    }
    const double sampleN = static_cast<double>(std::min<std::size_t>(numQueries, 10000));
    std::printf("per query: %.1f probes, %.1f tests, %.1f hits\n", sampleNodes / sampleN,
                sampleTested / sampleN, sampleFound / sampleN);

    // Single thread, a lambda visitor.
    std::uint64_t checksum = 0;
    start = Clock::now();
    for (const Vec3& q : queries) {
        tree.ForEachContaining(q, [&checksum](std::uint32_t id) { checksum += id; });
    }
    double seconds = SecondsSince(start);
    std::printf("1 thread, template:      %.2f M queries/s (checksum %llu)\n",
                static_cast<double>(numQueries) / seconds * 1e-6,
                static_cast<unsigned long long>(checksum));

    // Single thread, the visitor behind a std::function.
    std::uint64_t checksum2 = 0;
    const std::function<void(std::uint32_t)> visit = [&checksum2](std::uint32_t id) {
        checksum2 += id;
    };
    start = Clock::now();
    for (const Vec3& q : queries) {
        tree.ForEachContaining(q, visit);
    }
    seconds = SecondsSince(start);
    std::printf("1 thread, std::function: %.2f M queries/s (checksum %s)\n",
                static_cast<double>(numQueries) / seconds * 1e-6,
                checksum2 == checksum ? "same" : "DIFFERS");

    // Several threads, each over the whole query set.
    std::atomic<std::uint64_t> total{0};
    std::vector<std::thread> threads;
    start = Clock::now();
    for (int t = 0; t < numThreads; ++t) {
        threads.emplace_back([&] {
            std::uint64_t local = 0;
            for (const Vec3& q : queries) {
                tree.ForEachContaining(q, [&local](std::uint32_t id) { local += id; });
            }
            total += local;
        });
    }
    for (std::thread& th : threads) {
        th.join();
    }
    seconds = SecondsSince(start);
    std::printf("%d threads, template:     %.2f M queries/s total (%s)\n", numThreads,
                static_cast<double>(numQueries) * numThreads / seconds * 1e-6,
                total == checksum * static_cast<std::uint64_t>(numThreads) ? "consistent"
                                                                            : "INCONSISTENT");
    return 0;
}
