// SPDX-License-Identifier: MIT
//
// SphereGrid: classes, insertion and the hash tables' growth. The query
// itself is a template in the header.
#include "octree/sphere_grid.h"

#include <algorithm>
#include <cmath>

#include "core/check.h"

namespace rt {
namespace {

/// A sphere is listed in the cells its box widened by this much of its
/// radius meets: far more than the few ulps by which the containment test
/// can round, far less than a cell.
constexpr double kWiden = 1e-9;

}  // namespace

SphereGrid::SphereGrid(const Vec3& origin, double size)
    : origin_(origin), size_(size), classes_(kClasses) {
    RT_CHECK(IsFinite(origin));
    RT_CHECK(std::isfinite(size) && size > 0);
    RT_CHECK(IsFinite(origin + Vec3(size, size, size)));
    for (int k = 0; k < kClasses; ++k) {
        Class& c = classes_[static_cast<std::size_t>(k)];
        c.scale = std::ldexp(1.0, k) / size;
        c.last = std::int64_t{1} << k;
        c.shift = std::max(0, k - 5);
    }
}

int SphereGrid::ClassOf(double radius) const {
    const double width = 2.0 * radius * (1.0 + kWiden);
    if (!(width <= size_)) return -1;
    // The finest class whose cells (size·2^-k) are at least `width` wide.
    const double ratio = size_ / width;
    if (!(ratio < std::ldexp(1.0, kClasses - 1))) return kClasses - 1;
    return std::ilogb(ratio);
}

void SphereGrid::Grow(Class& c) {
    const std::size_t capacity = c.keys.empty() ? 16 : 2 * c.keys.size();
    std::vector<std::uint64_t> keys(capacity, kEmpty);
    std::vector<std::uint32_t> listOf(capacity);
    const std::size_t mask = capacity - 1;
    for (std::size_t s = 0; s < c.keys.size(); ++s) {
        if (c.keys[s] == kEmpty) continue;
        std::size_t t = Slot(c.keys[s], mask);
        while (keys[t] != kEmpty) t = (t + 1) & mask;
        keys[t] = c.keys[s];
        listOf[t] = c.listOf[s];
    }
    c.keys = std::move(keys);
    c.listOf = std::move(listOf);
}

std::vector<SphereGrid::Item>& SphereGrid::FindOrAdd(Class& c, std::uint64_t key) {
    // At most half full, so that a probe for a missing cell ends soon.
    if (2 * (c.lists.size() + 1) > c.keys.size()) Grow(c);
    const std::size_t mask = c.keys.size() - 1;
    std::size_t s = Slot(key, mask);
    for (; c.keys[s] != kEmpty; s = (s + 1) & mask) {
        if (c.keys[s] == key) return c.lists[c.listOf[s]];
    }
    c.keys[s] = key;
    c.listOf[s] = static_cast<std::uint32_t>(c.lists.size());
    return c.lists.emplace_back();
}

void SphereGrid::Insert(const Vec3& centre, double radius, std::uint32_t id) {
    RT_CHECK(IsFinite(centre));
    RT_CHECK(std::isfinite(radius) && radius > 0);
    const Item item{centre, radius * radius, id};
    ++count_;
    const Vec3 hi = origin_ + Vec3(size_, size_, size_);
    const bool inCube = origin_.x <= centre.x && centre.x <= hi.x && origin_.y <= centre.y &&
                        centre.y <= hi.y && origin_.z <= centre.z && centre.z <= hi.z;
    const int k = ClassOf(radius);
    if (!inCube || k < 0) {
        loose_.push_back(item);
        return;
    }
    Class& c = classes_[static_cast<std::size_t>(k)];
    // Every cell the widened box meets. The cell coordinate is monotone in
    // the position, so a point the containment test accepts, which lies
    // inside the widened box, falls in one of them. With the centre in the
    // cube and the box at most a cell wide they run from -1 to c.last; only
    // a cube far from the origin for its size rounds positions coarsely
    // enough to leave that range, and then the sphere is kept loose, which
    // is what lets a query skip a class whose range it lies outside.
    const double reach = radius * (1.0 + kWiden);
    std::int64_t lo[3], up[3];
    const double ctr[3] = {centre.x, centre.y, centre.z};
    const double org[3] = {origin_.x, origin_.y, origin_.z};
    for (int a = 0; a < 3; ++a) {
        const double l = CellOf(ctr[a] - reach, org[a], c.scale);
        const double u = CellOf(ctr[a] + reach, org[a], c.scale);
        if (!(l >= -1 && u <= static_cast<double>(c.last))) {
            loose_.push_back(item);
            return;
        }
        lo[a] = static_cast<std::int64_t>(l);
        up[a] = static_cast<std::int64_t>(u);
    }
    if (c.occupied.empty()) c.occupied.assign(std::size_t{1} << 9, 0);  // 32^3 bits
    for (std::int64_t i = lo[0]; i <= up[0]; ++i) {
        for (std::int64_t j = lo[1]; j <= up[1]; ++j) {
            for (std::int64_t l = lo[2]; l <= up[2]; ++l) {
                FindOrAdd(c, Key(i, j, l)).push_back(item);
                const std::size_t block = c.Block(i, j, l);
                c.occupied[block >> 6] |= std::uint64_t{1} << (block & 63);
            }
        }
    }
    ++c.items;
    used_ |= std::uint32_t{1} << k;
}

SphereGrid::QueryStats SphereGrid::CountVisits(const Vec3& p) const {
    QueryStats stats;
    Counting counter{stats};
    auto ignore = [](std::uint32_t) {};
    Query(p, ignore, counter);
    return stats;
}

SphereGrid::Shape SphereGrid::GetShape() const {
    Shape shape;
    shape.looseItems = loose_.size();
    for (const Class& c : classes_) {
        if (c.items > 0) ++shape.classesUsed;
        shape.cells += c.lists.size();
        for (const auto& list : c.lists) shape.listed += list.size();
    }
    return shape;
}

}  // namespace rt
