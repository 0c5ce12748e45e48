// SPDX-License-Identifier: MIT
//
// SphereOctree: insertion (Radiance's avinsert placement rule), the
// std::function query and the diagnostic walks. The query traversal itself is
// a template in the header.
#include "octree/sphere_octree.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/check.h"

namespace rt {

SphereOctree::SphereOctree(const Vec3& origin, double size) : origin_(origin), size_(size) {
    RT_CHECK(IsFinite(origin));
    RT_CHECK(std::isfinite(size) && size > 0);
    RT_CHECK(IsFinite(RootHi()));
}

SphereOctree::~SphereOctree() = default;

// Moved-from trees are empty (root_ == nullptr) and still usable.
SphereOctree::SphereOctree(SphereOctree&& other) noexcept
    : origin_(other.origin_),
      size_(other.size_),
      root_(std::move(other.root_)),
      count_(std::exchange(other.count_, 0)),
      outsideCount_(std::exchange(other.outsideCount_, 0)) {}

SphereOctree& SphereOctree::operator=(SphereOctree&& other) noexcept {
    if (this != &other) {
        origin_ = other.origin_;
        size_ = other.size_;
        root_ = std::move(other.root_);
        count_ = std::exchange(other.count_, 0);
        outsideCount_ = std::exchange(other.outsideCount_, 0);
    }
    return *this;
}

void SphereOctree::Insert(const Vec3& centre, double radius, std::uint32_t id) {
    RT_CHECK(IsFinite(centre));
    RT_CHECK(std::isfinite(radius) && radius > 0);
    if (!root_) {
        root_ = std::make_unique<Node>();
    }
    const Item item{centre, radius * radius, id};
    ++count_;

    Node* node = root_.get();
    node->reachSq = std::max(node->reachSq, item.radiusSq);
    Vec3 lo = origin_;
    Vec3 hi = RootHi();
    const bool inCube = lo.x <= centre.x && centre.x <= hi.x && lo.y <= centre.y &&
                        centre.y <= hi.y && lo.z <= centre.z && centre.z <= hi.z;
    if (!inCube) {
        // No child cube holds the centre, and the pruning test assumes every
        // item below the root lies inside its cell.
        ++outsideCount_;
        node->items.push_back(item);
        return;
    }

    // Descend while the half-size cell is still larger than the radius times
    // the slack (avinsert: while s/2 > r). Where an item sits only changes
    // how fast it is found: each lies inside its cell, which is all the
    // query's pruning needs.
    double cellSize = size_;
    for (int depth = 0; depth < kMaxDepth && 0.5 * cellSize > kPlacementSlack * radius; ++depth) {
        if (!node->children) {
            node->children = std::make_unique<Node[]>(8);
        }
        int child = 0;
        // Same split and side rule as the query: upper half only when strictly above mid.
        const double midX = detail::OctreeMid(lo.x, hi.x);
        const double midY = detail::OctreeMid(lo.y, hi.y);
        const double midZ = detail::OctreeMid(lo.z, hi.z);
        if (centre.x > midX) {
            child |= 1;
            lo.x = midX;
        } else {
            hi.x = midX;
        }
        if (centre.y > midY) {
            child |= 2;
            lo.y = midY;
        } else {
            hi.y = midY;
        }
        if (centre.z > midZ) {
            child |= 4;
            lo.z = midZ;
        } else {
            hi.z = midZ;
        }
        node = &node->children[child];
        node->reachSq = std::max(node->reachSq, item.radiusSq);
        cellSize *= 0.5;
    }
    node->items.push_back(item);
}

void SphereOctree::ForEachContaining(const Vec3& p,
                                     const std::function<void(std::uint32_t)>& visit) const {
    NoCount counter;
    Query(p, visit, counter);
}

SphereOctree::QueryStats SphereOctree::CountVisits(const Vec3& p) const {
    QueryStats stats;
    Counting counter{stats};
    auto ignore = [](std::uint32_t) {};
    Query(p, ignore, counter);
    return stats;
}

namespace {

// Recursive walk for Stats(); depth is bounded by kMaxDepth.
template <class NodeT, class Visit>
void WalkNodes(const NodeT& node, int depth, Visit& visit) {
    visit(node, depth);
    if (node.children) {
        for (int i = 0; i < 8; ++i) {
            WalkNodes(node.children[i], depth + 1, visit);
        }
    }
}

}  // namespace

SphereOctree::TreeStats SphereOctree::Stats() const {
    TreeStats stats;
    if (!root_) {
        return stats;
    }
    stats.rootItems = root_->items.size();
    stats.outsideItems = outsideCount_;
    stats.bytes = sizeof(Node);
    auto visit = [&stats](const Node& node, int depth) {
        ++stats.nodes;
        if (!node.items.empty()) {
            stats.maxDepth = std::max(stats.maxDepth, depth);
        }
        stats.bytes += node.items.capacity() * sizeof(Item);
        if (node.children) {
            stats.bytes += 8 * sizeof(Node);
        }
    };
    WalkNodes(*root_, 0, visit);
    return stats;
}

}  // namespace rt
