// SPDX-License-Identifier: MIT
//
// A spatial index of spheres (centre, radius) -> id that answers "which
// spheres contain point p" while visiting only octree cells whose spheres can
// reach p. The generic core of Radiance's AMBTREE (ambient.c): an item is
// stored in the cell whose size matches its radius, so lookups descend only
// into cells near p. Knows nothing of ambient records.
//
//   SphereOctree tree(cubeOrigin, cubeSize);
//   tree.Insert(centre, radius, id);
//   tree.ForEachContaining(p, [&](std::uint32_t id) { ... });
//
// Layout and placement (radiance-notes.md §4.9):
// * Each cell owns a flat list of items (centre, radius², id) and, once
//   something is pushed below it, its 8 children, allocated together. Cell
//   bounds are not stored; queries derive them from the root cube.
// * An item whose centre lies in the root cube descends from the root while
//   cellSize/2 > kPlacementSlack·radius (Radiance's avinsert rule has no
//   slack) and at most kMaxDepth levels, choosing the child whose half-open
//   side holds the centre (upper half when centre > midpoint, as avinsert).
// * An item whose centre lies outside the root cube is kept in the root's own
//   list, which every query scans. The root does not grow: callers size the
//   root to hold (nearly) everything, and Stats().outsideItems reports misses.
// * Each cell also keeps the largest radius² in its subtree. A query enters a
//   child only when the Euclidean distance from p to the child cube is within
//   that radius, which is never looser than Radiance's "child cube grown by
//   its own size" test, since placement keeps radius < cell size below the
//   root.
//
// Containment is evaluated as dx*dx + dy*dy + dz*dz <= radius*radius in double
// (d = p - centre), so points exactly on a sphere are inside. The pruning
// test is computed so that rounding can never drop a sphere that passes it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "core/vecmath.h"

namespace rt {

class SphereOctree {
public:
    /// The root cell is the cube [origin, origin + size]^3 (size > 0). Items
    /// whose centre lies outside it are still stored and found.
    SphereOctree(const Vec3& origin, double size);
    ~SphereOctree();
    SphereOctree(SphereOctree&&) noexcept;
    SphereOctree& operator=(SphereOctree&&) noexcept;

    /// Adds a sphere; radius must be > 0 and finite. Not thread-safe against
    /// concurrent queries (callers serialise writers).
    void Insert(const Vec3& centre, double radius, std::uint32_t id);

    /// Calls visit(id) once for every inserted sphere with |p - centre| <= radius
    /// (exactly those), in an unspecified order. Thread-safe with other queries.
    void ForEachContaining(const Vec3& p, const std::function<void(std::uint32_t)>& visit) const;

    std::size_t size() const { return count_; }

    /// Deepest level an item is pushed to (root = 0). Cells stop halving at
    /// size * 2^-20 (about 1e-6 of the root); smaller spheres share the
    /// deepest cell's list, so the depth stays bounded whatever the radii.
    static constexpr int kMaxDepth = 20;

    /// Items stop descending while the cell is still up to 2·kPlacementSlack
    /// times their radius: two levels above Radiance's avinsert rule. A query
    /// then walks fewer cells, each a pointer chase and a likely cache miss,
    /// and tests a few more items per cell, which lie together in memory
    /// (docs/benchmarks.md, "Record index").
    static constexpr double kPlacementSlack = 4;

    /// Same contract as the std::function overload, without its indirect call
    /// per hit; visit is called as visit(std::uint32_t). Use this on hot paths.
    template <class F>
    void ForEachContaining(const Vec3& p, F&& visit) const;

    /// Work done by one query, for pruning tests and tuning.
    struct QueryStats {
        std::size_t nodesVisited = 0;  ///< cells entered, root included
        std::size_t itemsTested = 0;   ///< distance tests made
        std::size_t itemsFound = 0;    ///< spheres containing p
    };
    /// Runs the ForEachContaining traversal for p and counts instead of visiting.
    QueryStats CountVisits(const Vec3& p) const;

    /// Shape of the tree, for tests and diagnostics. O(number of cells).
    struct TreeStats {
        std::size_t nodes = 0;         ///< cells allocated, root included
        std::size_t rootItems = 0;     ///< items in the root list (scanned by every query)
        std::size_t outsideItems = 0;  ///< of those, items whose centre is outside the root cube
        int maxDepth = 0;              ///< deepest level holding an item (root = 0)
        std::size_t bytes = 0;         ///< heap bytes held by cells and item lists
    };
    TreeStats Stats() const;

private:
    struct Node;
    Vec3 origin_;
    double size_;
    std::unique_ptr<Node> root_;
    std::size_t count_ = 0;
    std::size_t outsideCount_ = 0;  // items kept in the root list because their centre is outside the cube

    struct Item;
    struct NoCount;
    struct Counting;

    Vec3 RootHi() const { return origin_ + Vec3(size_, size_, size_); }
    template <class F, class Counter>
    void Query(const Vec3& p, F& visit, Counter& counter) const;
    template <class F, class Counter>
    static void VisitNode(const Node& node, const Vec3& lo, const Vec3& hi, const Vec3& p,
                          F& visit, Counter& counter);
};

// ---- implementation details needed by the template overload ----

/// 40 bytes; radius is kept squared because queries only compare squares.
struct SphereOctree::Item {
    Vec3 centre;
    double radiusSq;  // radius * radius, > 0 unless the radius underflows
    std::uint32_t id;
};

struct SphereOctree::Node {
    std::unique_ptr<Node[]> children;  // 8 cells (bit 0 = +x half, bit 1 = +y, bit 2 = +z) or null
    std::vector<Item> items;           // items placed at this cell, in insertion order
    double reachSq = -1;               // max radiusSq over this subtree; < 0 when the subtree is empty
};

struct SphereOctree::NoCount {
    void EnterNode() {}
    void TestItem() {}
    void Found() {}
};

struct SphereOctree::Counting {
    QueryStats& stats;
    void EnterNode() { ++stats.nodesVisited; }
    void TestItem() { ++stats.itemsTested; }
    void Found() { ++stats.itemsFound; }
};

namespace detail {

/// Split point of [lo, hi]. Insert and queries must both use this so an item
/// lands in exactly the child cube that queries later measure against; the
/// halves avoid overflow near DBL_MAX.
inline double OctreeMid(double lo, double hi) { return 0.5 * lo + 0.5 * hi; }

/// Squared distance from x to [lo, hi] along one axis. For any c in [lo, hi]
/// the rounded result is <= (x - c)^2 rounded, so the pruning test can never
/// reject a cube holding a sphere that contains p.
inline double OctreeGapSq(double x, double lo, double hi) {
    const double gap = x < lo ? lo - x : (x > hi ? x - hi : 0.0);
    return gap * gap;
}

}  // namespace detail

template <class F, class Counter>
void SphereOctree::VisitNode(const Node& node, const Vec3& lo, const Vec3& hi, const Vec3& p,
                             F& visit, Counter& counter) {
    counter.EnterNode();
    for (const Item& item : node.items) {
        counter.TestItem();
        const double dx = p.x - item.centre.x;
        const double dy = p.y - item.centre.y;
        const double dz = p.z - item.centre.z;
        if (dx * dx + dy * dy + dz * dz <= item.radiusSq) {
            counter.Found();
            visit(item.id);
        }
    }
    if (!node.children) {
        return;
    }
    const Vec3 mid(detail::OctreeMid(lo.x, hi.x), detail::OctreeMid(lo.y, hi.y),
                   detail::OctreeMid(lo.z, hi.z));
    // Per axis, squared gap from p to the lower [0] and upper [1] half. Summed
    // in x, y, z order like the item test so the rounding argument holds.
    const double gapX[2] = {detail::OctreeGapSq(p.x, lo.x, mid.x),
                            detail::OctreeGapSq(p.x, mid.x, hi.x)};
    const double gapY[2] = {detail::OctreeGapSq(p.y, lo.y, mid.y),
                            detail::OctreeGapSq(p.y, mid.y, hi.y)};
    const double gapZ[2] = {detail::OctreeGapSq(p.z, lo.z, mid.z),
                            detail::OctreeGapSq(p.z, mid.z, hi.z)};
    for (int i = 0; i < 8; ++i) {
        const Node& child = node.children[i];
        const int bx = i & 1, by = (i >> 1) & 1, bz = (i >> 2) & 1;
        if (gapX[bx] + gapY[by] + gapZ[bz] > child.reachSq) {
            continue;  // also skips empty subtrees (reachSq < 0)
        }
        const Vec3 childLo(bx ? mid.x : lo.x, by ? mid.y : lo.y, bz ? mid.z : lo.z);
        const Vec3 childHi(bx ? hi.x : mid.x, by ? hi.y : mid.y, bz ? hi.z : mid.z);
        VisitNode(child, childLo, childHi, p, visit, counter);
    }
}

template <class F, class Counter>
void SphereOctree::Query(const Vec3& p, F& visit, Counter& counter) const {
    if (!root_) {
        return;  // empty or moved-from
    }
    // The root is always entered: its list holds huge and out-of-cube spheres.
    VisitNode(*root_, origin_, RootHi(), p, visit, counter);
}

template <class F>
void SphereOctree::ForEachContaining(const Vec3& p, F&& visit) const {
    NoCount counter;
    Query(p, visit, counter);
}

}  // namespace rt
