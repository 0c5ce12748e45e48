// SPDX-License-Identifier: MIT
//
// SphereGrid against a brute-force scan: every containing sphere reported
// exactly once, whatever the radii or where the centres are; plus the work a
// query does, the size classes and input checks.
#include "octree/sphere_grid.h"

#include "core/conventions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <thread>
#include <vector>

namespace rt {
namespace {

struct Sphere {
    Vec3 centre;
    double radius;
    std::uint32_t id;
};

// The containment predicate the grid documents, evaluated the same way.
bool Contains(const Sphere& s, const Vec3& p) {
    const double dx = p.x - s.centre.x;
    const double dy = p.y - s.centre.y;
    const double dz = p.z - s.centre.z;
    return dx * dx + dy * dy + dz * dz <= s.radius * s.radius;
}

std::vector<std::uint32_t> BruteForce(const std::vector<Sphere>& spheres, const Vec3& p) {
    std::vector<std::uint32_t> ids;
    for (const Sphere& s : spheres) {
        if (Contains(s, p)) {
            ids.push_back(s.id);
        }
    }
    std::sort(ids.begin(), ids.end());
    return ids;
}

// Sorted ids reported by the grid, duplicates kept so the test sees them.
std::vector<std::uint32_t> Query(const SphereGrid& grid, const Vec3& p) {
    std::vector<std::uint32_t> ids;
    grid.ForEachContaining(p, [&ids](std::uint32_t id) { ids.push_back(id); });
    std::sort(ids.begin(), ids.end());
    return ids;
}

// Root cube [-1, 3]^3, offset from the origin so the split points are not
// all "nice" numbers.
const Vec3 kOrigin(-1.0, -1.0, -1.0);
constexpr double kSize = 4.0;

struct RandomScene {
    std::vector<Sphere> spheres;
    std::vector<Vec3> queries;
};

// 10^4 spheres: radii log-uniform over 4 decades of the cube size, 5% of the
// centres outside the cube (some far), 1% with radii larger than the cube, and
// 10% with dyadic centres/radii so that queries at centre +- radius along an
// axis lie exactly on the sphere in double arithmetic.
RandomScene MakeRandomScene(std::uint32_t seed, std::size_t numSpheres, std::size_t numQueries) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto inCube = [&] {
        return Vec3(kOrigin.x + kSize * unit(rng), kOrigin.y + kSize * unit(rng),
                    kOrigin.z + kSize * unit(rng));
    };
    auto dyadic = [&](double lo, double hi) {  // multiple of 2^-10 in [lo, hi)
        return std::floor((lo + (hi - lo) * unit(rng)) * 1024.0) / 1024.0;
    };

    RandomScene scene;
    for (std::size_t i = 0; i < numSpheres; ++i) {
        const double kind = unit(rng);
        Sphere s{};
        s.id = static_cast<std::uint32_t>(i);
        s.radius = kSize * std::pow(10.0, -4.0 + 3.0 * unit(rng));  // 4e-4 .. 4
        if (kind < 0.05) {
            // Outside the cube, near it or very far away.
            const double reach = unit(rng) < 0.8 ? 3.0 * kSize : 1e6;
            s.centre = Vec3(reach * (2 * unit(rng) - 1), reach * (2 * unit(rng) - 1),
                            kOrigin.z + kSize + 0.01 + reach * unit(rng));
            if (unit(rng) < 0.5) {
                std::swap(s.centre.x, s.centre.z);
            }
            if (reach > 1e5) {
                s.radius = 1e6 * unit(rng) + 1.0;
            }
        } else if (kind < 0.06) {
            s.centre = inCube();
            s.radius = kSize * (1.0 + 100.0 * unit(rng));  // larger than the cube
        } else if (kind < 0.16) {
            s.centre = Vec3(dyadic(-1, 3), dyadic(-1, 3), dyadic(-1, 3));
            s.radius = std::max(dyadic(0, 0.5), 1.0 / 1024.0);
        } else {
            s.centre = inCube();
        }
        scene.spheres.push_back(s);
    }

    for (std::size_t i = 0; i < numQueries; ++i) {
        const double kind = unit(rng);
        const Sphere& s = scene.spheres[rng() % scene.spheres.size()];
        Vec3 p;
        if (kind < 0.4) {
            // Uniform over a box larger than the cube.
            p = Vec3(-3 + 8 * unit(rng), -3 + 8 * unit(rng), -3 + 8 * unit(rng));
        } else if (kind < 0.7) {
            // Near a sphere's boundary, inside or out.
            const Vec3 dir = Normalize(Vec3(2 * unit(rng) - 1, 2 * unit(rng) - 1,
                                            2 * unit(rng) - 1) + Vec3(1e-9, 0, 0));
            p = s.centre + dir * (s.radius * (0.999 + 0.002 * unit(rng)));
        } else {
            // Exactly on the boundary of a (dyadic) sphere, along an axis.
            const Sphere* d = &s;
            for (std::size_t j = 0; !(d->radius * 1024 == std::floor(d->radius * 1024) &&
                                      d->centre.x * 1024 == std::floor(d->centre.x * 1024));
                 ++j) {
                d = &scene.spheres[(s.id + j) % scene.spheres.size()];
            }
            const int axis = static_cast<int>(rng() % 3);
            const double sign = unit(rng) < 0.5 ? -1.0 : 1.0;
            p = d->centre;
            p[axis] += sign * d->radius;
        }
        scene.queries.push_back(p);
    }
    return scene;
}

TEST(SphereGrid, MatchesBruteForceOnRandomSpheres) {
    const RandomScene scene = MakeRandomScene(12345, 10000, 10000);
    SphereGrid grid(kOrigin, kSize);
    for (const Sphere& s : scene.spheres) {
        grid.Insert(s.centre, s.radius, s.id);
    }
    ASSERT_EQ(grid.size(), scene.spheres.size());
    EXPECT_GT(grid.GetShape().looseItems, 0u);
    EXPECT_GT(grid.GetShape().classesUsed, 8);

    std::size_t totalHits = 0;
    for (const Vec3& p : scene.queries) {
        const std::vector<std::uint32_t> expected = BruteForce(scene.spheres, p);
        const std::vector<std::uint32_t> got = Query(grid, p);
        ASSERT_EQ(got, expected) << "query point " << p;
        EXPECT_EQ(grid.CountVisits(p).itemsFound, got.size());
        totalHits += got.size();
    }
    // Guard against a vacuous pass: most queries should hit something.
    EXPECT_GT(totalHits, scene.queries.size());
}

TEST(SphereGrid, ReportsPointsExactlyOnTheSphere) {
    SphereGrid grid(Vec3(0, 0, 0), 1.0);
    const Vec3 centre(0.375, 0.5, 0.625);
    const double radius = 0.125;  // dyadic: centre +- radius is exact, and on a cell face
    grid.Insert(centre, radius, 7);
    for (int axis = 0; axis < 3; ++axis) {
        for (double sign : {-1.0, 1.0}) {
            Vec3 p = centre;
            p[axis] += sign * radius;
            EXPECT_EQ(Query(grid, p), std::vector<std::uint32_t>{7}) << p;
            p[axis] += sign * 1e-12;
            EXPECT_TRUE(Query(grid, p).empty()) << p;
        }
    }
}

TEST(SphereGrid, SpheresOnCellBoundariesAreFoundFromAllSides) {
    // Centres on cell faces of every class, and radii that end exactly on
    // them: each sphere is listed in the cells on both sides.
    SphereGrid grid(Vec3(0, 0, 0), 1.0);
    std::vector<Sphere> spheres;
    std::uint32_t id = 0;
    for (double x : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        for (double y : {0.0, 0.5, 1.0}) {
            for (double r : {1e-3, 0.01, 0.1, 0.125, 0.25}) {
                spheres.push_back({Vec3(x, y, 0.5), r, id});
                grid.Insert(Vec3(x, y, 0.5), r, id++);
            }
        }
    }
    for (const Sphere& s : spheres) {
        for (int axis = 0; axis < 3; ++axis) {
            for (double f : {-1.0, -0.5, 0.5, 1.0}) {
                Vec3 p = s.centre;
                p[axis] += f * s.radius;
                EXPECT_EQ(Query(grid, p), BruteForce(spheres, p)) << p;
            }
        }
    }
}

TEST(SphereGrid, EmptyGridReportsNothing) {
    SphereGrid grid(Vec3(0, 0, 0), 1.0);
    EXPECT_EQ(grid.size(), 0u);
    for (const Vec3& p : {Vec3(0, 0, 0), Vec3(0.5, 0.5, 0.5), Vec3(-10, 5, 1e9)}) {
        EXPECT_TRUE(Query(grid, p).empty());
        EXPECT_EQ(grid.CountVisits(p).cellsProbed, 0u);
    }
    EXPECT_EQ(grid.GetShape().cells, 0u);
}

TEST(SphereGrid, DuplicateCentresAreAllReported) {
    SphereGrid grid(Vec3(0, 0, 0), 1.0);
    const Vec3 c(0.3, 0.3, 0.3);
    std::vector<Sphere> spheres;
    for (std::uint32_t i = 0; i < 50; ++i) {
        const double r = (i % 2 == 0) ? 0.01 : 0.001 * (1 + i);
        spheres.push_back({c, r, i});
        grid.Insert(c, r, i);
    }
    // The same sphere and id twice are two items, so the id is reported twice.
    grid.Insert(c, 0.01, 0);
    spheres.push_back({c, 0.01, 0});
    EXPECT_EQ(grid.size(), 51u);

    const std::vector<std::uint32_t> atCentre = Query(grid, c);
    EXPECT_EQ(atCentre.size(), 51u);
    EXPECT_EQ(std::count(atCentre.begin(), atCentre.end(), 0u), 2);
    for (const Vec3& p : {Vec3(0.305, 0.3, 0.3), Vec3(0.3, 0.32, 0.3), Vec3(0.3, 0.3, 0.35)}) {
        EXPECT_EQ(Query(grid, p), BruteForce(spheres, p)) << p;
    }
}

TEST(SphereGrid, CentresOutsideTheCubeAndHugeRadiiAreFound) {
    SphereGrid grid(Vec3(0, 0, 0), 1.0);
    grid.Insert(Vec3(5, 5, 5), 0.5, 1);                // outside, small
    grid.Insert(Vec3(-1e6, 0, 0), 2e6, 2);             // far outside, covers the cube
    grid.Insert(Vec3(0.5, 0.5, 0.5), 1e3, 3);          // inside, radius >> cube
    grid.Insert(Vec3(1.0, 1.0, 1.0), 0.1, 4);          // on the cube's far corner
    grid.Insert(Vec3(1.0 + 1e-15, 0.5, 0.5), 0.1, 5);  // just outside a face

    EXPECT_EQ(Query(grid, Vec3(5.2, 5, 5)), (std::vector<std::uint32_t>{1, 2, 3}));
    EXPECT_EQ(Query(grid, Vec3(0.5, 0.5, 0.5)), (std::vector<std::uint32_t>{2, 3}));
    EXPECT_EQ(Query(grid, Vec3(1.05, 1.05, 1.0)), (std::vector<std::uint32_t>{2, 3, 4}));
    EXPECT_EQ(Query(grid, Vec3(0.95, 0.5, 0.5)), (std::vector<std::uint32_t>{2, 3, 5}));
    EXPECT_EQ(Query(grid, Vec3(-600, 0, 0)), (std::vector<std::uint32_t>{2, 3}));
    EXPECT_EQ(Query(grid, Vec3(1e7, 0, 0)), std::vector<std::uint32_t>{});
    // The three outside and the huge one are scanned by every query.
    EXPECT_EQ(grid.GetShape().looseItems, 4u);
    EXPECT_EQ(grid.ClassOf(0.49), 0);
    EXPECT_EQ(grid.ClassOf(0.5), -1);  // its box, widened, is wider than the cube
}

TEST(SphereGrid, AQueryTestsOnlyTheSpheresOfItsCell) {
    // Records of one size on a floor, as a sensor grid makes them: 10 000
    // spheres of radius r on the plane z = 0.3, about two over any point.
    SphereGrid grid(Vec3(0, 0, 0), 1.0);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double r = std::sqrt(2.0 / (kPi * 10000));
    std::vector<Sphere> spheres;
    for (std::uint32_t i = 0; i < 10000; ++i) {
        spheres.push_back({Vec3(unit(rng), unit(rng), 0.3), r, i});
        grid.Insert(spheres.back().centre, r, i);
    }
    // Each sphere's box meets at most two cells per axis of its class; on
    // a plane inside one layer of cells, four at most.
    const SphereGrid::Shape shape = grid.GetShape();
    EXPECT_EQ(shape.classesUsed, 1);
    EXPECT_LE(shape.listed, 4u * spheres.size());
    std::size_t tested = 0, found = 0;
    for (int q = 0; q < 2000; ++q) {
        const Vec3 p(unit(rng), unit(rng), 0.3);
        const SphereGrid::QueryStats stats = grid.CountVisits(p);
        EXPECT_EQ(stats.cellsProbed, 1u);
        ASSERT_EQ(Query(grid, p), BruteForce(spheres, p));
        tested += stats.itemsTested;
        found += stats.itemsFound;
    }
    // A cell is 2r to 4r wide (here 4r: 1/32 against r = 0.008), so a query
    // tests the spheres within r of it, (4r + 2r)² ρ = 36/π·2 ≈ 23 on
    // average, for the 2 it finds (an octree's cells, a few cells deep, made
    // it test about 50).
    EXPECT_NEAR(double(found) / 2000, 2.0, 0.2);
    EXPECT_LT(double(tested) / 2000, 26.0);
}

TEST(SphereGrid, FarQueriesProbeNothing) {
    // A dense cluster of small spheres in one corner of the cube.
    SphereGrid grid(Vec3(0, 0, 0), 1.0);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (std::uint32_t i = 0; i < 20000; ++i) {
        const Vec3 c(0.1 * unit(rng), 0.1 * unit(rng), 0.1 * unit(rng));
        grid.Insert(c, 0.001 + 0.004 * unit(rng), i);
    }
    ASSERT_GT(grid.GetShape().cells, 1000u);

    // Opposite corner, a point outside the cube, and one just past the
    // cluster's reach: the occupancy bits spare every table probe.
    for (const Vec3& p : {Vec3(0.9, 0.9, 0.9), Vec3(-5, 0.05, 0.05), Vec3(0.2, 0.05, 0.05)}) {
        const SphereGrid::QueryStats q = grid.CountVisits(p);
        EXPECT_EQ(q.itemsFound, 0u) << p;
        EXPECT_EQ(q.cellsProbed, 0u) << p;
        EXPECT_EQ(q.itemsTested, 0u) << p;
    }

    // Inside the cluster, the work is a small fraction of the whole.
    const SphereGrid::QueryStats inside = grid.CountVisits(Vec3(0.05, 0.05, 0.05));
    EXPECT_GT(inside.itemsFound, 0u);
    EXPECT_EQ(inside.itemsFound, Query(grid, Vec3(0.05, 0.05, 0.05)).size());
    EXPECT_LE(inside.cellsProbed, 3u);
    EXPECT_LT(inside.itemsTested, grid.size() / 50);
}

TEST(SphereGrid, ClassIsTheFinestWhoseCellsSpanTheDiameter) {
    SphereGrid grid(Vec3(0, 0, 0), 1.0);
    for (int k = 0; k + 1 < SphereGrid::kClasses; ++k) {
        const double cell = std::ldexp(1.0, -k);
        EXPECT_EQ(grid.ClassOf(0.49 * cell), k) << k;          // too wide for class k + 1
        EXPECT_EQ(grid.ClassOf(0.24 * cell), k + 1) << k;      // fits class k + 1
    }
    // Spheres too small for the finest cells share them.
    EXPECT_EQ(grid.ClassOf(1e-12), SphereGrid::kClasses - 1);
    std::vector<Sphere> spheres;
    for (std::uint32_t i = 0; i < 100; ++i) {
        const Vec3 c(0.123456789 + 1e-13 * i, 0.5, 0.5);
        const double r = 1e-12 * (1 + i % 5);
        spheres.push_back({c, r, i});
        grid.Insert(c, r, i);
    }
    EXPECT_EQ(grid.GetShape().classesUsed, 1);
    for (const Sphere& s : spheres) {
        EXPECT_EQ(Query(grid, s.centre), BruteForce(spheres, s.centre));
    }
}

TEST(SphereGrid, ACubeFarFromTheOriginStillFindsExactlyTheContainingSpheres) {
    // Coordinates near 1e9 with a cube of 1e-3: positions round to about
    // 1e-7, a tenth of a millimetre's cell. Whatever lands where, every
    // containing sphere is found and no other.
    const Vec3 origin(1e9, -1e9, 5e8);
    SphereGrid grid(origin, 1e-3);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Sphere> spheres;
    for (std::uint32_t i = 0; i < 2000; ++i) {
        const Vec3 c = origin + Vec3(unit(rng), unit(rng), unit(rng)) * 1e-3;
        const double r = 1e-3 * std::pow(10.0, -3.0 + 3.0 * unit(rng));
        spheres.push_back({c, r, i});
        grid.Insert(c, r, i);
    }
    for (int q = 0; q < 4000; ++q) {
        const Sphere& s = spheres[rng() % spheres.size()];
        const Vec3 dir = Normalize(Vec3(2 * unit(rng) - 1, 2 * unit(rng) - 1, 2 * unit(rng) - 1));
        const Vec3 p = s.centre + dir * (s.radius * (0.99 + 0.02 * unit(rng)));
        ASSERT_EQ(Query(grid, p), BruteForce(spheres, p)) << q;
    }
}

TEST(SphereGrid, ConcurrentQueriesAgree) {
    const RandomScene scene = MakeRandomScene(4242, 5000, 2000);
    SphereGrid grid(kOrigin, kSize);
    for (const Sphere& s : scene.spheres) {
        grid.Insert(s.centre, s.radius, s.id);
    }
    std::vector<std::vector<std::uint32_t>> expected;
    for (const Vec3& p : scene.queries) {
        expected.push_back(Query(grid, p));
    }
    constexpr int kThreads = 4;
    std::vector<int> mismatches(kThreads, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t) {
        threads.emplace_back([&, t] {
            for (std::size_t i = 0; i < scene.queries.size(); ++i) {
                if (Query(grid, scene.queries[i]) != expected[i]) {
                    ++mismatches[static_cast<std::size_t>(t)];
                }
            }
        });
    }
    for (std::thread& th : threads) {
        th.join();
    }
    for (int m : mismatches) {
        EXPECT_EQ(m, 0);
    }
}

TEST(SphereGrid, RejectsInvalidInput) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    SphereGrid grid(Vec3(0, 0, 0), 1.0);
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_DEATH(grid.Insert(Vec3(0.5, 0.5, 0.5), 0.0, 1), "check failed");
    EXPECT_DEATH(grid.Insert(Vec3(0.5, 0.5, 0.5), -1.0, 1), "check failed");
    EXPECT_DEATH(grid.Insert(Vec3(0.5, 0.5, 0.5), nan, 1), "check failed");
    EXPECT_DEATH(grid.Insert(Vec3(0.5, 0.5, 0.5), inf, 1), "check failed");
    EXPECT_DEATH(grid.Insert(Vec3(nan, 0.5, 0.5), 0.1, 1), "check failed");
    EXPECT_DEATH(grid.Insert(Vec3(0.5, inf, 0.5), 0.1, 1), "check failed");
    EXPECT_DEATH(SphereGrid(Vec3(0, 0, 0), 0.0), "check failed");
    EXPECT_DEATH(SphereGrid(Vec3(0, 0, 0), -1.0), "check failed");
    EXPECT_DEATH(SphereGrid(Vec3(nan, 0, 0), 1.0), "check failed");
    EXPECT_EQ(grid.size(), 0u);
}

}  // namespace
}  // namespace rt
