// SPDX-License-Identifier: MIT
//
// Variable-resolution ("tensor tree") BSDFs as libBSDF's bsdf_t.c reads
// them: BSDF values (1/sr) over a unit hypercube of 3 (isotropic) or 4
// dimensions, cut in halves on every axis at each branch down to leaves
// that hold a grid of 2^k values a side. Directions map to the cube through
// the Shirley-Chiu concentric map, which keeps areas: a square's area times
// π is its disk's projected solid angle.
//   TensorTree4: axes 0,1 the square of (-in.x, -in.y), axes 2,3 that of
//     (out.x, out.y).
//   TensorTree3: axis 0 is 0.5 − 0.5·sinθ_in (only [0, 0.5) holds data),
//     axes 1,2 the square of `out` turned about z so that (-in.x, -in.y)
//     lies along +x.
// Lookups take the value of the leaf cell a point falls in (no
// interpolation), as libBSDF does.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <unordered_map>
#include <vector>

#include "scene/bsdf_data.h"

namespace rt {

/// Which light a tree describes (libBSDF's SD_FREFL ... SD_BXMIT):
/// reflection on the front (+z) or back, transmission of light entering
/// from the front or back.
enum class TreeSide { FrontReflection, BackReflection, FrontTransmission, BackTransmission };

/// Shirley and Chiu's concentric map of the unit square onto the unit disk
/// (SDsquare2disk()) and its inverse (SDdisk2square()), libBSDF's
/// orientation: the square's centre is the disk's, its right edge's middle
/// the disk's +x.
void SquareToDisk(double sx, double sy, double disk[2]);
void DiskToSquare(double dx, double dy, double square[2]);

class TreeComponent final : public BsdfComponent {
public:
    /// One node, in the order of bsdf_t.c's load_tree_data(): a branch
    /// (log2Grid < 0) whose 2^dims children are consecutive in the node
    /// list from `first` (child n covers the upper half of axis i when bit
    /// i of n is set), or a leaf grid of 2^log2Grid values a side from
    /// `first` in the value list, axis 0 slowest.
    struct Node {
        int log2Grid = 0;
        std::uint32_t first = 0;
    };

    /// `nodes[0]` is the root. Takes out the Lambertian part and finds the
    /// extrema (get_extrema(), subtract_min_Y()).
    TreeComponent(int dims, TreeSide side, std::vector<Node> nodes, std::vector<float> values);

    std::optional<double> Value(const Vec3& out, const Vec3& in) const override;
    void FoldProjectedSolidAngle(double psa[2], const Vec3& v1, const Vec3* v2,
                                 bool minAndMax) const override;
    double Total(const Vec3& in) const override;
    std::optional<Vec3> Sample(const Vec3& in, double x, double j0, double j1) const override;

    int dims() const { return dims_; }

private:
    /// The output cells for one incident direction (make_cdist()): each
    /// cell's corner and width on the output square, cumulative value ×
    /// area, and the extremes of the widths.
    struct Distribution {
        /// A cell as its stretch of the Hilbert curve over the output square
        /// (2^16 steps a side, libBSDF's hilbert_c2i() orientation): the
        /// cells, aligned squares, tile the square and so the curve.
        struct Cell {
            std::uint64_t start, length;  // in units of 2^-32 of the curve
        };
        std::vector<Cell> cells;
        std::vector<double> cumulative;  // cells+1 entries, from 0
        double total = 0;                // hemispherical: π × Σ value·area
        double minWidth = 0, maxWidth = 0;
        bool reversed = false;  // light from the side the data is not for
    };

    /// The leaf value at `pos` (dims_ coordinates in [0,1)), and the edge
    /// of its cell in `edge` (SDlookupTre()).
    float Lookup(const double pos[4], double* edge) const;
    /// The cube coordinates of a query, after the side checks and swaps
    /// of SDqueryTre(); false when the pair is not this tree's.
    bool Position(const Vec3& out, const Vec3& in, double pos[4]) const;
    /// The distribution for light from `in` (SDgetTreCDist()), built once
    /// per input cell and kept; null when `in` is on the wrong side or
    /// (isotropic data) would need reciprocity, which libBSDF leaves out.
    std::shared_ptr<const Distribution> DistributionFor(const Vec3& in) const;
    std::shared_ptr<const Distribution> Build(const double pos[2], bool reversed) const;
    /// Mean over a box of the cube (SDavgTreBox()).
    double BoxMean(std::uint32_t node, const double* bmin, const double* bmax) const;
    double SmallestLeaf(std::uint32_t node) const;
    float Minimum(std::uint32_t node, bool liveHalfOnly) const;

    int dims_;
    TreeSide side_;
    std::vector<Node> nodes_;
    std::vector<float> values_;
    double smallest_;  // the smallest leaf's edge: the distribution cache's bins

    mutable std::mutex cacheLock_;
    mutable std::unordered_map<std::uint64_t, std::shared_ptr<const Distribution>> cache_;
    mutable std::size_t cachedCells_ = 0;
};

}  // namespace rt
