// SPDX-License-Identifier: MIT
//
// A spatial index of spheres (centre, radius) -> id that answers "which
// spheres contain point p" by probing one cell per size class: the record
// index of the irradiance cache, which asks that about two million times in
// a dense sensor grid. Knows nothing of ambient records.
//
//   SphereGrid grid(cubeOrigin, cubeSize);
//   grid.Insert(centre, radius, id);
//   grid.ForEachContaining(p, [&](std::uint32_t id) { ... });
//
// Layout (docs/benchmarks.md, "Record index"):
// * Size class k (0 <= k < kClasses) is a uniform grid over the cube whose
//   cells have side size·2^-k. A sphere goes to the finest class whose cells
//   are at least its diameter wide (the finest class takes all smaller ones),
//   and into every cell of that class its bounding box meets: at most two per
//   axis, and for the records of one surface usually two to four in all.
// * A query looks, in each class holding something, at the one cell that
//   contains p, and tests the spheres listed there: a sphere that contains p
//   lies in that cell's list, so nothing else need be visited. A bit per
//   block of cells (32^3 blocks per class) says whether the block holds
//   anything; only then is the table probed.
// * Non-empty cells are kept in an open-addressing hash table per class,
//   keyed by their integer coordinates; each cell's list is contiguous.
// * Spheres whose centre lies outside the cube, or whose diameter exceeds
//   it, are kept in one list that every query scans (as are the few whose
//   cells would fall outside the class's range, which only a cube far from
//   the origin for its size can round them into).
//
// Against an octree (Radiance's AMBTREE and lazyrad's index before this one),
// a query makes one probe per class instead of walking from the root, and
// tests only the spheres of its own cell: most records of a run share one
// size (the largest -ar allows), and the octree's cells, several radii wide,
// made a query test many times the spheres it found (docs/benchmarks.md,
// "Record index", also for what that did and did not change in whole runs).
//
// Containment is evaluated as dx*dx + dy*dy + dz*dz <= radius*radius in double
// (d = p - centre), so points exactly on a sphere are inside. A sphere is
// listed in every cell its box, widened by 1e-9 of its radius, meets, which
// covers every point that test can accept whatever the rounding.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vecmath.h"

namespace rt {

class SphereGrid {
public:
    /// The grid covers the cube [origin, origin + size]^3 (size > 0). Spheres
    /// whose centre lies outside it are still stored and found.
    SphereGrid(const Vec3& origin, double size);

    /// Adds a sphere; radius must be > 0 and finite. Not thread-safe against
    /// concurrent queries (callers serialise writers).
    void Insert(const Vec3& centre, double radius, std::uint32_t id);

    /// Calls visit(id) once for every inserted sphere with |p - centre| <= radius
    /// (exactly those), in an unspecified order; visit is called as
    /// visit(std::uint32_t). Thread-safe with other queries.
    template <class F>
    void ForEachContaining(const Vec3& p, F&& visit) const;

    std::size_t size() const { return count_; }

    /// Classes of cell size size·2^-k, k < kClasses: the finest cells are
    /// about 1e-6 of the cube, and smaller spheres share them.
    static constexpr int kClasses = 21;

    /// Work done by one query, for tests and tuning.
    struct QueryStats {
        std::size_t cellsProbed = 0;  ///< hash-table probes: classes whose block around p holds something
        std::size_t itemsTested = 0;  ///< distance tests made
        std::size_t itemsFound = 0;   ///< spheres containing p
    };
    /// Runs the ForEachContaining query for p and counts instead of visiting.
    QueryStats CountVisits(const Vec3& p) const;

    /// Shape of the index, for tests and diagnostics.
    struct Shape {
        std::size_t cells = 0;         ///< non-empty cells over all classes
        std::size_t listed = 0;        ///< entries in the cells' lists (a sphere in up to 8)
        std::size_t looseItems = 0;    ///< spheres in the list every query scans
        int classesUsed = 0;           ///< classes holding at least one sphere
    };
    Shape GetShape() const;

    /// The class a sphere of `radius` goes to, or -1 for the loose list (its
    /// diameter, widened by 1e-9, above the cube's size). For tests.
    int ClassOf(double radius) const;

private:
    struct Item {
        Vec3 centre;
        double radiusSq;  // radius * radius, > 0 unless the radius underflows
        std::uint32_t id;
    };
    /// One size class: the cells' keys (kEmpty where free) and, in the same
    /// slot, the index of the cell's list in `lists`.
    struct Class {
        double scale = 0;  // cells per unit length: 2^k / size
        std::int64_t last = 0;  // largest cell coordinate a sphere of the class can meet
        std::vector<std::uint64_t> keys;
        std::vector<std::uint32_t> listOf;
        std::vector<std::vector<Item>> lists;
        std::size_t items = 0;
        /// Which blocks of cells hold something: 32^3 bits, block coordinate
        /// (cell + 1) >> shift (the last block takes what lies beyond). A
        /// query tests its bit before probing the table, so classes with a
        /// few spheres in corners cost it no cache miss elsewhere.
        int shift = 0;
        std::vector<std::uint64_t> occupied;
        std::size_t Block(std::int64_t i, std::int64_t j, std::int64_t k) const {
            const auto b = [this](std::int64_t x) {
                return std::min<std::size_t>(31, static_cast<std::size_t>(x + 1) >> shift);
            };
            return b(i) | (b(j) << 5) | (b(k) << 10);
        }
        bool Occupied(std::size_t block) const { return (occupied[block >> 6] >> (block & 63)) & 1; }
    };
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};

    Vec3 origin_;
    double size_;
    std::vector<Class> classes_;
    std::vector<Item> loose_;
    std::uint32_t used_ = 0;  // bit k: class k holds something
    std::size_t count_ = 0;

    /// Cell coordinate of x along one axis of a class with `scale` cells per
    /// unit length, as a double: monotone in x, whatever the rounding.
    static double CellOf(double x, double origin, double scale) {
        return std::floor((x - origin) * scale);
    }
    static std::uint64_t Key(std::int64_t i, std::int64_t j, std::int64_t k) {
        // Coordinates run from -1 to 2^20 at most: 21 bits each after the shift.
        return static_cast<std::uint64_t>(i + 1) | (static_cast<std::uint64_t>(j + 1) << 21) |
               (static_cast<std::uint64_t>(k + 1) << 42);
    }
    static std::size_t Slot(std::uint64_t key, std::size_t mask) {
        return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 32) & mask;
    }
    /// The list of cell `key` in class c, or null.
    static const std::vector<Item>* Find(const Class& c, std::uint64_t key);
    std::vector<Item>& FindOrAdd(Class& c, std::uint64_t key);
    static void Grow(Class& c);

    template <class F, class Counter>
    void Query(const Vec3& p, F& visit, Counter& counter) const;
    struct NoCount {
        void Probe() {}
        void TestItem() {}
        void Found() {}
    };
    struct Counting {
        QueryStats& stats;
        void Probe() { ++stats.cellsProbed; }
        void TestItem() { ++stats.itemsTested; }
        void Found() { ++stats.itemsFound; }
    };
    template <class F, class Counter>
    static void Scan(const std::vector<Item>& items, const Vec3& p, F& visit, Counter& counter);
};

// ---- implementation details needed by the template ----

inline const std::vector<SphereGrid::Item>* SphereGrid::Find(const Class& c, std::uint64_t key) {
    const std::size_t mask = c.keys.size() - 1;
    for (std::size_t s = Slot(key, mask);; s = (s + 1) & mask) {
        const std::uint64_t k = c.keys[s];
        if (k == key) return &c.lists[c.listOf[s]];
        if (k == kEmpty) return nullptr;
    }
}

template <class F, class Counter>
void SphereGrid::Scan(const std::vector<Item>& items, const Vec3& p, F& visit,
                      Counter& counter) {
    for (const Item& item : items) {
        counter.TestItem();
        const double dx = p.x - item.centre.x;
        const double dy = p.y - item.centre.y;
        const double dz = p.z - item.centre.z;
        if (dx * dx + dy * dy + dz * dz <= item.radiusSq) {
            counter.Found();
            visit(item.id);
        }
    }
}

template <class F, class Counter>
void SphereGrid::Query(const Vec3& p, F& visit, Counter& counter) const {
    if (!loose_.empty()) Scan(loose_, p, visit, counter);
    for (std::uint32_t used = used_; used != 0; used &= used - 1) {
        const Class& c = classes_[static_cast<std::size_t>(__builtin_ctz(used))];
        const double i = CellOf(p.x, origin_.x, c.scale);
        const double j = CellOf(p.y, origin_.y, c.scale);
        const double k = CellOf(p.z, origin_.z, c.scale);
        // Beyond the cells any sphere of the class can meet (also NaN).
        const double last = static_cast<double>(c.last);
        if (!(i >= -1 && i <= last && j >= -1 && j <= last && k >= -1 && k <= last)) continue;
        const auto ii = static_cast<std::int64_t>(i), jj = static_cast<std::int64_t>(j),
                   kk = static_cast<std::int64_t>(k);
        if (!c.Occupied(c.Block(ii, jj, kk))) continue;
        counter.Probe();
        const std::vector<Item>* items = Find(c, Key(ii, jj, kk));
        if (items) Scan(*items, p, visit, counter);
    }
}

template <class F>
void SphereGrid::ForEachContaining(const Vec3& p, F&& visit) const {
    NoCount counter;
    Query(p, visit, counter);
}

}  // namespace rt
