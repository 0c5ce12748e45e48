// SPDX-License-Identifier: MIT
//
// SphereOctree against a brute-force scan: every containing sphere reported
// exactly once, whatever the radii or where the centres are; plus pruning,
// depth bound, move and input-check behaviour.
#include "octree/sphere_octree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <thread>
#include <type_traits>
#include <vector>

namespace rt {
namespace {

struct Sphere {
    Vec3 centre;
    double radius;
    std::uint32_t id;
};

// The containment predicate the octree documents, evaluated the same way.
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

// Sorted ids reported by the octree, duplicates kept so the test sees them.
std::vector<std::uint32_t> Query(const SphereOctree& tree, const Vec3& p) {
    std::vector<std::uint32_t> ids;
    tree.ForEachContaining(p, [&ids](std::uint32_t id) { ids.push_back(id); });
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

TEST(SphereOctree, MatchesBruteForceOnRandomSpheres) {
    const RandomScene scene = MakeRandomScene(12345, 10000, 10000);
    SphereOctree tree(kOrigin, kSize);
    for (const Sphere& s : scene.spheres) {
        tree.Insert(s.centre, s.radius, s.id);
    }
    ASSERT_EQ(tree.size(), scene.spheres.size());
    EXPECT_GT(tree.Stats().outsideItems, 0u);

    std::size_t totalHits = 0;
    for (const Vec3& p : scene.queries) {
        const std::vector<std::uint32_t> expected = BruteForce(scene.spheres, p);
        const std::vector<std::uint32_t> got = Query(tree, p);
        ASSERT_EQ(got, expected) << "query point " << p;
        totalHits += got.size();
    }
    // Guard against a vacuous pass: most queries should hit something.
    EXPECT_GT(totalHits, scene.queries.size());
}

TEST(SphereOctree, ReportsPointsExactlyOnTheSphere) {
    SphereOctree tree(Vec3(0, 0, 0), 1.0);
    const Vec3 centre(0.375, 0.5, 0.625);
    const double radius = 0.125;  // dyadic: centre +- radius is exact
    tree.Insert(centre, radius, 7);
    for (int axis = 0; axis < 3; ++axis) {
        for (double sign : {-1.0, 1.0}) {
            Vec3 p = centre;
            p[axis] += sign * radius;
            EXPECT_EQ(Query(tree, p), std::vector<std::uint32_t>{7}) << p;
            p[axis] += sign * 1e-12;
            EXPECT_TRUE(Query(tree, p).empty()) << p;
        }
    }
}

TEST(SphereOctree, SpheresOnCellBoundariesAreFoundFromBothSides) {
    // Centres on the root's split planes (and its faces), small radii, so the
    // sphere straddles cells it is not stored in.
    SphereOctree tree(Vec3(0, 0, 0), 1.0);
    std::vector<Sphere> spheres;
    std::uint32_t id = 0;
    for (double x : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        for (double y : {0.0, 0.5, 1.0}) {
            for (double r : {1e-3, 0.01, 0.1}) {
                spheres.push_back({Vec3(x, y, 0.5), r, id});
                tree.Insert(Vec3(x, y, 0.5), r, id++);
            }
        }
    }
    for (const Sphere& s : spheres) {
        for (int axis = 0; axis < 3; ++axis) {
            for (double f : {-1.0, -0.5, 0.5, 1.0}) {
                Vec3 p = s.centre;
                p[axis] += f * s.radius;
                EXPECT_EQ(Query(tree, p), BruteForce(spheres, p)) << p;
            }
        }
    }
}

TEST(SphereOctree, EmptyTreeReportsNothing) {
    SphereOctree tree(Vec3(0, 0, 0), 1.0);
    EXPECT_EQ(tree.size(), 0u);
    for (const Vec3& p : {Vec3(0, 0, 0), Vec3(0.5, 0.5, 0.5), Vec3(-10, 5, 1e9)}) {
        EXPECT_TRUE(Query(tree, p).empty());
        EXPECT_LE(tree.CountVisits(p).nodesVisited, 1u);
    }
    EXPECT_EQ(tree.Stats().nodes, 0u);
}

TEST(SphereOctree, DuplicateCentresAreAllReported) {
    SphereOctree tree(Vec3(0, 0, 0), 1.0);
    const Vec3 c(0.3, 0.3, 0.3);
    std::vector<Sphere> spheres;
    for (std::uint32_t i = 0; i < 50; ++i) {
        const double r = (i % 2 == 0) ? 0.01 : 0.001 * (1 + i);
        spheres.push_back({c, r, i});
        tree.Insert(c, r, i);
    }
    // The same sphere and id twice are two items, so the id is reported twice.
    tree.Insert(c, 0.01, 0);
    spheres.push_back({c, 0.01, 0});
    EXPECT_EQ(tree.size(), 51u);

    const std::vector<std::uint32_t> atCentre = Query(tree, c);
    EXPECT_EQ(atCentre.size(), 51u);
    EXPECT_EQ(std::count(atCentre.begin(), atCentre.end(), 0u), 2);
    for (const Vec3& p : {Vec3(0.305, 0.3, 0.3), Vec3(0.3, 0.32, 0.3), Vec3(0.3, 0.3, 0.35)}) {
        EXPECT_EQ(Query(tree, p), BruteForce(spheres, p)) << p;
    }
}

TEST(SphereOctree, CentresOutsideTheCubeAndHugeRadiiAreFound) {
    SphereOctree tree(Vec3(0, 0, 0), 1.0);
    tree.Insert(Vec3(5, 5, 5), 0.5, 1);              // outside, small
    tree.Insert(Vec3(-1e6, 0, 0), 2e6, 2);           // far outside, covers the cube
    tree.Insert(Vec3(0.5, 0.5, 0.5), 1e3, 3);        // inside, radius >> cube
    tree.Insert(Vec3(1.0, 1.0, 1.0), 0.1, 4);        // on the cube's far corner
    tree.Insert(Vec3(1.0 + 1e-15, 0.5, 0.5), 0.1, 5);  // just outside a face

    EXPECT_EQ(Query(tree, Vec3(5.2, 5, 5)), (std::vector<std::uint32_t>{1, 2, 3}));
    EXPECT_EQ(Query(tree, Vec3(0.5, 0.5, 0.5)), (std::vector<std::uint32_t>{2, 3}));
    EXPECT_EQ(Query(tree, Vec3(1.05, 1.05, 1.0)), (std::vector<std::uint32_t>{2, 3, 4}));
    EXPECT_EQ(Query(tree, Vec3(0.95, 0.5, 0.5)), (std::vector<std::uint32_t>{2, 3, 5}));
    EXPECT_EQ(Query(tree, Vec3(-600, 0, 0)), (std::vector<std::uint32_t>{2, 3}));
    EXPECT_EQ(Query(tree, Vec3(1e7, 0, 0)), std::vector<std::uint32_t>{});

    const SphereOctree::TreeStats stats = tree.Stats();
    EXPECT_EQ(stats.outsideItems, 3u);
    EXPECT_EQ(stats.rootItems, 4u);  // the three outside plus the huge one
}

TEST(SphereOctree, FarQueriesVisitFewNodes) {
    // A dense cluster of small spheres in one corner of the cube.
    SphereOctree tree(Vec3(0, 0, 0), 1.0);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (std::uint32_t i = 0; i < 20000; ++i) {
        const Vec3 c(0.1 * unit(rng), 0.1 * unit(rng), 0.1 * unit(rng));
        tree.Insert(c, 0.001 + 0.004 * unit(rng), i);
    }
    const SphereOctree::TreeStats stats = tree.Stats();
    ASSERT_GT(stats.nodes, 1000u);

    // Opposite corner, a point outside the cube, and one just past the
    // cluster's reach: only the root (and, at most, a short path) is entered.
    for (const Vec3& p : {Vec3(0.9, 0.9, 0.9), Vec3(-5, 0.05, 0.05), Vec3(0.2, 0.05, 0.05)}) {
        const SphereOctree::QueryStats q = tree.CountVisits(p);
        EXPECT_EQ(q.itemsFound, 0u) << p;
        EXPECT_LE(q.nodesVisited, 6u) << p;
        EXPECT_EQ(q.itemsTested, 0u) << p;
    }

    // Inside the cluster, the work is a small fraction of the tree.
    const SphereOctree::QueryStats inside = tree.CountVisits(Vec3(0.05, 0.05, 0.05));
    EXPECT_GT(inside.itemsFound, 0u);
    EXPECT_EQ(inside.itemsFound, Query(tree, Vec3(0.05, 0.05, 0.05)).size());
    EXPECT_LT(inside.nodesVisited, stats.nodes / 20);
    EXPECT_LT(inside.itemsTested, tree.size() / 20);
}

TEST(SphereOctree, DepthIsBoundedForTinyRadii) {
    SphereOctree tree(Vec3(0, 0, 0), 1.0);
    std::vector<Sphere> spheres;
    for (std::uint32_t i = 0; i < 100; ++i) {
        const Vec3 c(0.123456789 + 1e-13 * i, 0.5, 0.5);
        const double r = 1e-12 * (1 + i % 5);
        spheres.push_back({c, r, i});
        tree.Insert(c, r, i);
    }
    const SphereOctree::TreeStats stats = tree.Stats();
    EXPECT_EQ(stats.maxDepth, SphereOctree::kMaxDepth);
    EXPECT_LE(stats.nodes, 1u + 8u * SphereOctree::kMaxDepth);
    for (const Sphere& s : spheres) {
        EXPECT_EQ(Query(tree, s.centre), BruteForce(spheres, s.centre));
    }
}

TEST(SphereOctree, PlacementFollowsRadianceRuleWithSlack) {
    // avinsert with slack k: descend while cellSize/2 > k·r, so an item of
    // radius r sits at the depth d where size/2^(d+1) <= k·r < size/2^d.
    const double k = SphereOctree::kPlacementSlack;
    for (int depth = 0; depth <= 6; ++depth) {
        SphereOctree tree(Vec3(0, 0, 0), 1.0);
        const double cell = std::ldexp(1.0, -depth);
        tree.Insert(Vec3(0.3, 0.6, 0.9), 0.5 * cell / k, 1);  // exactly s/2k: stops here
        EXPECT_EQ(tree.Stats().maxDepth, depth);
        tree.Insert(Vec3(0.3, 0.6, 0.9), 0.49 * cell / k, 2);  // one level deeper
        EXPECT_EQ(tree.Stats().maxDepth, depth + 1);
    }
}

TEST(SphereOctree, StdFunctionOverloadMatchesTemplate) {
    const RandomScene scene = MakeRandomScene(99, 2000, 500);
    SphereOctree tree(kOrigin, kSize);
    for (const Sphere& s : scene.spheres) {
        tree.Insert(s.centre, s.radius, s.id);
    }
    for (const Vec3& p : scene.queries) {
        std::vector<std::uint32_t> viaFunction;
        const std::function<void(std::uint32_t)> visit = [&](std::uint32_t id) {
            viaFunction.push_back(id);
        };
        tree.ForEachContaining(p, visit);
        std::sort(viaFunction.begin(), viaFunction.end());
        EXPECT_EQ(viaFunction, Query(tree, p));
        EXPECT_EQ(tree.CountVisits(p).itemsFound, viaFunction.size());
    }
}

TEST(SphereOctree, IsMoveOnlyAndMovedFromIsEmpty) {
    static_assert(!std::is_copy_constructible_v<SphereOctree>);
    static_assert(!std::is_copy_assignable_v<SphereOctree>);
    static_assert(std::is_nothrow_move_constructible_v<SphereOctree>);
    static_assert(std::is_nothrow_move_assignable_v<SphereOctree>);

    SphereOctree a(Vec3(0, 0, 0), 1.0);
    a.Insert(Vec3(0.5, 0.5, 0.5), 0.1, 3);
    a.Insert(Vec3(9, 9, 9), 0.1, 4);
    SphereOctree b(std::move(a));
    EXPECT_EQ(b.size(), 2u);
    EXPECT_EQ(Query(b, Vec3(0.5, 0.5, 0.5)), std::vector<std::uint32_t>{3});
    EXPECT_EQ(a.size(), 0u);  // NOLINT(bugprone-use-after-move): documented state
    EXPECT_TRUE(Query(a, Vec3(0.5, 0.5, 0.5)).empty());

    SphereOctree c(Vec3(-1, -1, -1), 2.0);
    c = std::move(b);
    EXPECT_EQ(c.size(), 2u);
    EXPECT_EQ(Query(c, Vec3(9, 9, 9.05)), std::vector<std::uint32_t>{4});
    EXPECT_EQ(c.Stats().outsideItems, 1u);

    // A moved-from tree accepts new items.
    a.Insert(Vec3(0.2, 0.2, 0.2), 0.05, 8);
    EXPECT_EQ(Query(a, Vec3(0.2, 0.2, 0.2)), std::vector<std::uint32_t>{8});
}

TEST(SphereOctree, ConcurrentQueriesAgree) {
    const RandomScene scene = MakeRandomScene(4242, 5000, 2000);
    SphereOctree tree(kOrigin, kSize);
    for (const Sphere& s : scene.spheres) {
        tree.Insert(s.centre, s.radius, s.id);
    }
    std::vector<std::vector<std::uint32_t>> expected;
    for (const Vec3& p : scene.queries) {
        expected.push_back(Query(tree, p));
    }
    constexpr int kThreads = 4;
    std::vector<int> mismatches(kThreads, 0);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t) {
        threads.emplace_back([&, t] {
            for (std::size_t i = 0; i < scene.queries.size(); ++i) {
                if (Query(tree, scene.queries[i]) != expected[i]) {
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

TEST(SphereOctree, RejectsInvalidInput) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    SphereOctree tree(Vec3(0, 0, 0), 1.0);
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_DEATH(tree.Insert(Vec3(0.5, 0.5, 0.5), 0.0, 1), "check failed");
    EXPECT_DEATH(tree.Insert(Vec3(0.5, 0.5, 0.5), -1.0, 1), "check failed");
    EXPECT_DEATH(tree.Insert(Vec3(0.5, 0.5, 0.5), nan, 1), "check failed");
    EXPECT_DEATH(tree.Insert(Vec3(0.5, 0.5, 0.5), inf, 1), "check failed");
    EXPECT_DEATH(tree.Insert(Vec3(nan, 0.5, 0.5), 0.1, 1), "check failed");
    EXPECT_DEATH(tree.Insert(Vec3(0.5, inf, 0.5), 0.1, 1), "check failed");
    EXPECT_DEATH(SphereOctree(Vec3(0, 0, 0), 0.0), "check failed");
    EXPECT_DEATH(SphereOctree(Vec3(0, 0, 0), -1.0), "check failed");
    EXPECT_DEATH(SphereOctree(Vec3(nan, 0, 0), 1.0), "check failed");
    EXPECT_EQ(tree.size(), 0u);
}

}  // namespace
}  // namespace rt
