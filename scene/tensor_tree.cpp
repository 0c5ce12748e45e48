// SPDX-License-Identifier: MIT
#include "scene/tensor_tree.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include "core/conventions.h"
#include "core/error.h"
#include "scene/bsdf_xml.h"

namespace rt {
namespace {

/// Finest cells accepted: 2^16 a side, libBSDF's resolution for its
/// sampling tables (its cell widths are integers of 2^-16; finer ones
/// would have width 0 there).
constexpr int kMaxLog2 = 16;
/// Cells kept over all cached distributions of one tree before the cache
/// starts afresh (about 100 MB at most).
constexpr std::size_t kMaxCachedCells = std::size_t(1) << 22;

/// z-axis rotation by `angle` (radians, counter-clockwise), as spinvector().
void Spin(double& x, double& y, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    const double nx = x * c - y * s;
    y = y * c + x * s;
    x = nx;
}

/// The position along the Hilbert curve of 2^16 steps a side of the cell
/// (c0, c1) (each in [0, 2^16)), in the orientation of libBSDF's
/// hilbert_c2i() and of HilbertSquare(): the inverse of the standard
/// d2xy() with x = c1, y = c0.
std::uint64_t HilbertIndex(std::uint32_t c0, std::uint32_t c1) {
    constexpr std::uint32_t kSide = 1u << 16;
    std::uint32_t x = c1, y = c0;
    std::uint64_t d = 0;
    for (std::uint32_t s = kSide / 2; s > 0; s /= 2) {
        const std::uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
        d += std::uint64_t(s) * s * ((3 * rx) ^ ry);
        if (ry == 0) {
            if (rx == 1) {
                x = kSide - 1 - x;
                y = kSide - 1 - y;
            }
            std::swap(x, y);
        }
    }
    return d;
}

}  // namespace

void SquareToDisk(double sx, double sy, double disk[2]) {
    const double a = 2.0 * sx - 1.0, b = 2.0 * sy - 1.0;
    double r, phi;
    if (a > -b) {
        if (a > b) {
            r = a;
            phi = (kPi / 4.0) * (b / a);
        } else {
            r = b;
            phi = (kPi / 4.0) * (2.0 - a / b);
        }
    } else if (a < b) {
        r = -a;
        phi = (kPi / 4.0) * (4.0 + b / a);
    } else {
        r = -b;
        phi = b != 0.0 ? (kPi / 4.0) * (6.0 - a / b) : 0.0;
    }
    disk[0] = r * std::cos(phi);
    disk[1] = r * std::sin(phi);
}

void DiskToSquare(double dx, double dy, double square[2]) {
    const double r = std::sqrt(dx * dx + dy * dy);
    double phi = std::atan2(dy, dx);
    double a, b;
    if (phi < -kPi / 4.0) phi += 2.0 * kPi;  // [-π/4, 7π/4)
    if (phi < kPi / 4.0) {
        a = r;
        b = phi * a / (kPi / 4.0);
    } else if (phi < 3.0 * kPi / 4.0) {
        b = r;
        a = -(phi - kPi / 2.0) * b / (kPi / 4.0);
    } else if (phi < 5.0 * kPi / 4.0) {
        a = -r;
        b = (phi - kPi) * a / (kPi / 4.0);
    } else {
        b = -r;
        a = -(phi - 3.0 * kPi / 2.0) * b / (kPi / 4.0);
    }
    square[0] = (a + 1.0) * 0.5;
    square[1] = (b + 1.0) * 0.5;
}

TreeComponent::TreeComponent(int dims, TreeSide side, std::vector<Node> nodes,
                             std::vector<float> values)
    : dims_(dims), side_(side), nodes_(std::move(nodes)), values_(std::move(values)) {
    // get_extrema(), on the values as read: the smallest cell, and the
    // largest mean over incident cells of at least 1/32 a side.
    double step = SmallestLeaf(0);
    smallest_ = step;
    minProjSA_ = kPi * step * step;
    step = std::max(step, 1.0 / 32.0);
    double bmin[4] = {0, 0, 0, 0}, bmax[4] = {1, 1, 1, 1};
    double best = 0;
    if (dims_ == 3) {
        for (bmin[0] = 0; bmin[0] < 0.5 - kFtiny; bmin[0] += step) {
            bmax[0] = bmin[0] + step;
            best = std::max(best, BoxMean(0, bmin, bmax));
        }
    } else {
        for (bmin[0] = 0; bmin[0] < 1.0 - kFtiny; bmin[0] += step) {
            bmax[0] = bmin[0] + step;
            for (bmin[1] = 0; bmin[1] < 1.0 - kFtiny; bmin[1] += step) {
                bmax[1] = bmin[1] + step;
                best = std::max(best, BoxMean(0, bmin, bmax));
            }
        }
    }
    maxHemi_ = best * kPi;
    // subtract_min_Y(): the smallest value (of the live half, for
    // isotropic data) is the Lambertian part, unless it is negligible or
    // so large (1.5/π) that the data is better left whole.
    constexpr float kLargest = float(1.5 / kPi);
    const float lowest = Minimum(0, dims_ == 3);
    if (lowest < kLargest && lowest > float(0.01 / kPi)) {
        for (float& v : values_) v = std::max(v - lowest, 0.0f);
        lambertian_ = kPi * double(lowest);
        maxHemi_ -= lambertian_;
    }
}

double TreeComponent::SmallestLeaf(std::uint32_t node) const {
    const Node& n = nodes_[node];
    if (n.log2Grid >= 0) return 1.0 / double(1 << n.log2Grid);
    double least = 1.0;
    for (std::uint32_t c = 0; c < (1u << dims_); ++c)
        least = std::min(least, SmallestLeaf(n.first + c));
    return 0.5 * least;
}

float TreeComponent::Minimum(std::uint32_t node, bool liveHalfOnly) const {
    const Node& n = nodes_[node];
    if (!liveHalfOnly) {
        float least = std::numeric_limits<float>::max();
        if (n.log2Grid < 0) {
            for (std::uint32_t c = 0; c < (1u << dims_); ++c)
                least = std::min(least, Minimum(n.first + c, false));
        } else {
            const std::size_t count = std::size_t(1) << (dims_ * n.log2Grid);
            least = *std::min_element(values_.begin() + n.first, values_.begin() + n.first + count);
        }
        return least;
    }
    // Isotropic data: only incident coordinates below 0.5 hold data. As
    // libBSDF, a single value counts whatever its size; otherwise the
    // search starts from the largest value worth taking out.
    if (n.log2Grid == 0) return values_[n.first];
    float least = float(1.5 / kPi);
    if (n.log2Grid < 0) {
        for (std::uint32_t c = 0; c < 8; c += 2)
            least = std::min(least, Minimum(n.first + c, false));
    } else {
        const std::size_t half = std::size_t(1) << (3 * n.log2Grid - 1);
        for (std::size_t k = 0; k < half; ++k) least = std::min(least, values_[n.first + k]);
    }
    return least;
}

double TreeComponent::BoxMean(std::uint32_t node, const double* bmin, const double* bmax) const {
    for (int i = 0; i < dims_; ++i) {
        if (bmin[i] >= 1.0 || bmax[i] <= 0.0 || bmin[i] >= bmax[i]) return 0.0;
    }
    const Node& n = nodes_[node];
    if (n.log2Grid < 0) {
        double sum = 0, wsum = 1e-20;
        for (std::uint32_t c = 0; c < (1u << dims_); ++c) {
            double sbmin[4], sbmax[4], w = 1.0;
            for (int i = 0; i < dims_; ++i) {
                const double shift = (c >> i) & 1;
                sbmin[i] = std::max(2.0 * bmin[i] - shift, 0.0);
                sbmax[i] = std::min(2.0 * bmax[i] - shift, 1.0);
                if (sbmin[i] >= sbmax[i]) {
                    w = 0;
                    break;
                }
                w *= sbmax[i] - sbmin[i];
            }
            if (w > 1e-10) {
                sum += w * BoxMean(n.first + c, sbmin, sbmax);
                wsum += w;
            }
        }
        return sum / wsum;
    }
    const int res = 1 << n.log2Grid;
    int lo[4] = {0, 0, 0, 0}, hi[4] = {1, 1, 1, 1};
    long long count = 1;
    for (int i = 0; i < dims_; ++i) {
        lo[i] = bmin[i] <= 0.0 ? 0 : int(res * bmin[i]);
        hi[i] = bmax[i] >= 1.0 ? res : int(res * bmax[i] + 0.999999);
        count *= hi[i] - lo[i];
    }
    if (count <= 0) return 0.0;
    double sum = 0;
    int c[4] = {lo[0], lo[1], lo[2], dims_ == 4 ? lo[3] : 0};
    const int last = dims_ - 1;
    for (;;) {
        std::size_t at = 0;
        for (int i = 0; i < dims_; ++i) at = at * std::size_t(res) + std::size_t(c[i]);
        sum += values_[n.first + at];
        int i = last;
        while (i >= 0 && ++c[i] == hi[i]) {
            c[i] = lo[i];
            --i;
        }
        if (i < 0) break;
    }
    return sum / double(count);
}

float TreeComponent::Lookup(const double pos[4], double* edge) const {
    double p[4] = {pos[0], pos[1], pos[2], dims_ == 4 ? pos[3] : 0.0};
    double size = 1.0;
    const Node* n = &nodes_[0];
    while (n->log2Grid < 0) {
        std::uint32_t child = 0;
        size *= 0.5;
        for (int i = 0; i < dims_; ++i) {
            const double s = 2.0 * p[i];
            const int t = s >= 1.0;
            child |= std::uint32_t(t) << i;
            p[i] = s - t;
        }
        n = &nodes_[n->first + child];
    }
    const int res = 1 << n->log2Grid;
    if (edge) *edge = size / res;
    std::size_t at = 0;
    for (int i = 0; i < dims_; ++i) {
        // A coordinate of exactly 1 (a grazing direction) stays in the
        // last cell.
        const double q = res * p[i];
        const int c = q >= res - 1 ? res - 1 : q > 0.0 ? int(q) : 0;  // NaN: 0
        at = at * std::size_t(res) + std::size_t(c);
    }
    return values_[n->first + at];
}

bool TreeComponent::Position(const Vec3& outVec, const Vec3& inVec, double pos[4]) const {
    Vec3 out = outVec, in = inVec;
    switch (side_) {
        case TreeSide::FrontReflection:
            if (out.z < 0.0 || in.z < 0.0) return false;
            break;
        case TreeSide::BackReflection:
            if (out.z > 0.0 || in.z > 0.0) return false;
            break;
        case TreeSide::FrontTransmission:
            if (out.z > 0.0) {
                if (in.z > 0.0) return false;
                std::swap(out, in);  // reciprocity
            } else if (in.z < 0.0) {
                return false;
            }
            break;
        case TreeSide::BackTransmission:
            if (in.z > 0.0) {
                if (out.z > 0.0) return false;
                std::swap(out, in);
            } else if (out.z < 0.0) {
                return false;
            }
            break;
    }
    if (dims_ == 3) {
        double x = out.x, y = out.y;
        Spin(x, y, -std::atan2(-in.y, -in.x));
        pos[0] = (0.5 - kFtiny) - 0.5 * std::sqrt(in.x * in.x + in.y * in.y);
        DiskToSquare(x, y, pos + 1);
    } else {
        DiskToSquare(-in.x, -in.y, pos);
        DiskToSquare(out.x, out.y, pos + 2);
    }
    return true;
}

std::optional<double> TreeComponent::Value(const Vec3& out, const Vec3& in) const {
    double pos[4];
    if (!Position(out, in, pos)) return std::nullopt;
    return Lookup(pos, nullptr);
}

void TreeComponent::FoldProjectedSolidAngle(double psa[2], const Vec3& v1, const Vec3* v2,
                                            bool minAndMax) const {
    double least = 0, most = 0;
    if (v2) {
        double pos[4], edge;
        // libBSDF reports an error for a pair not on this tree's sides;
        // BsdfData::Size never asks for one but at z = 0.
        if (!Position(v1, *v2, pos)) return;
        Lookup(pos, &edge);
        least = most = kPi * edge * edge;
    } else if (const auto d = DistributionFor(v1)) {
        least = kPi * d->minWidth * d->minWidth;
        most = kPi * d->maxWidth * d->maxWidth;
    }
    if (minAndMax) psa[1] = std::max(psa[1], most);
    if (least > 0.0 && least < psa[0]) psa[0] = least;
}

double TreeComponent::Total(const Vec3& in) const {
    const auto d = DistributionFor(in);
    return d ? d->total : 0.0;
}

std::optional<Vec3> TreeComponent::Sample(const Vec3& in, double x, double j0, double j1) const {
    const auto d = DistributionFor(in);
    if (!d || d->total <= 1e-7) return std::nullopt;
    const std::vector<double>& cum = d->cumulative;
    const std::size_t n = d->cells.size();
    const double target = x * cum[n];
    const std::size_t k = std::min<std::size_t>(
        std::size_t(std::upper_bound(cum.begin() + 1, cum.end(), target) - (cum.begin() + 1)),
        n - 1);
    const double width = cum[k + 1] - cum[k];
    const double local = width > 0 ? std::clamp((target - cum[k]) / width, 0.0, 1.0) : 0.5;
    // The point at that share of the cell's stretch of the curve
    // (SDsampTreCDist(), there on a curve of 2^32 steps a side).
    const auto& cell = d->cells[k];
    const double r = (double(cell.start) + local * double(cell.length)) / 4294967296.0;
    double t[2];
    HilbertSquare(std::min(r, std::nextafter(1.0, 0.0)), j0, j1, t);
    double disk[2];
    SquareToDisk(t[0], t[1], disk);
    double z = 1.0 - disk[0] * disk[0] - disk[1] * disk[1];
    z = z > 0.0 ? std::sqrt(z) : 0.0;
    // Which way the light leaves: back for back reflection and for light
    // entering from the front.
    TreeSide emits = side_;
    if (d->reversed) {
        emits = side_ == TreeSide::BackTransmission ? TreeSide::FrontTransmission
                                                    : TreeSide::BackTransmission;
    }
    if (emits == TreeSide::BackReflection || emits == TreeSide::FrontTransmission) z = -z;
    if (dims_ == 3) Spin(disk[0], disk[1], std::atan2(-in.y, -in.x));
    return Vec3(disk[0], disk[1], z);
}

std::shared_ptr<const TreeComponent::Distribution> TreeComponent::DistributionFor(
    const Vec3& in) const {
    bool reversed = false;
    switch (side_) {
        case TreeSide::FrontReflection:
            if (in.z < 0.0) return nullptr;
            break;
        case TreeSide::BackReflection:
            if (in.z > 0.0) return nullptr;
            break;
        case TreeSide::FrontTransmission:
            reversed = in.z < 0.0;
            break;
        case TreeSide::BackTransmission:
            reversed = in.z > 0.0;
            break;
    }
    double c[2] = {0, 0};
    if (dims_ == 3) {
        if (reversed) return nullptr;  // libBSDF: "unhandled reciprocity"
        c[0] = (0.5 - kFtiny) - 0.5 * std::sqrt(in.x * in.x + in.y * in.y);
    } else if (reversed) {
        DiskToSquare(in.x, in.y, c);
    } else {
        DiskToSquare(-in.x, -in.y, c);
    }
    // Leaves are aligned to their size, none smaller than `smallest_`: all
    // incident coordinates in one aligned box of that size meet the same
    // leaves, so the box selects the distribution (libBSDF reuses one over
    // the box of the slice's smallest cell, which holds the same).
    std::uint64_t key = reversed;
    for (int i = 0; i < dims_ - 2; ++i) {
        const double bin = std::floor(c[i] / smallest_);
        c[i] = (bin + 0.5) * smallest_;
        if (!(c[i] >= 0.0 && c[i] < 1.0)) return nullptr;
        key |= std::uint64_t(bin) << (1 + 24 * i);
    }
    {
        const std::lock_guard<std::mutex> lock(cacheLock_);
        if (const auto found = cache_.find(key); found != cache_.end()) return found->second;
    }
    auto d = Build(c, reversed);
    const std::lock_guard<std::mutex> lock(cacheLock_);
    if (cachedCells_ + d->cells.size() > kMaxCachedCells) {
        cache_.clear();
        cachedCells_ = 0;
    }
    if (cache_.emplace(key, d).second) cachedCells_ += d->cells.size();
    return d;
}

std::shared_ptr<const TreeComponent::Distribution> TreeComponent::Build(const double pos[2],
                                                                        bool reversed) const {
    // The slice of the cube at the incident coordinates: fixed axes 0
    // (and 1) normally, 2 and 3 when the light comes from the side the data
    // is not for; the other two axes are the output square.
    const int fixedFirst = reversed ? 2 : 0, fixedCount = dims_ - 2;
    const int outFirst = reversed ? 0 : dims_ - 2;
    double fixedPos[4] = {0, 0, 0, 0};
    for (int i = 0; i < fixedCount; ++i) fixedPos[fixedFirst + i] = pos[i];
    const auto fixed = [&](int axis) {
        return axis >= fixedFirst && axis < fixedFirst + fixedCount;
    };

    struct Entry {
        double u, v, width;
        float value;
        std::uint64_t order, length;
    };
    std::vector<Entry> entries;
    const auto add = [&](float value, const double* cmin, double size) {
        double u = cmin[outFirst], v = cmin[outFirst + 1];
        if (reversed) {  // the output square of the other side: its point reflection
            u = 1.0 - u - size;
            v = 1.0 - v - size;
        }
        entries.push_back({u, v, size, value, 0, 0});
    };
    // Depth-first over the nodes the slice meets.
    const auto visit = [&](const auto& self, std::uint32_t node, const double* cmin,
                           double size) -> void {
        const Node& n = nodes_[node];
        if (n.log2Grid < 0) {
            size *= 0.5;
            for (std::uint32_t c = 0; c < (1u << dims_); ++c) {
                double child[4];
                bool meets = true;
                for (int i = 0; i < dims_; ++i) {
                    const bool upper = (c >> i) & 1;
                    child[i] = cmin[i] + (upper ? size : 0.0);
                    if (fixed(i) && upper != (fixedPos[i] >= cmin[i] + size)) meets = false;
                }
                if (meets) self(self, n.first + c, child, size);
            }
            return;
        }
        const int res = 1 << n.log2Grid;
        size /= res;
        int lo[4] = {0, 0, 0, 0}, hi[4] = {1, 1, 1, 1};
        for (int i = 0; i < dims_; ++i) {
            if (fixed(i)) {
                const double q = (fixedPos[i] - cmin[i]) / size;
                lo[i] = q >= res - 1 ? res - 1 : q > 0.0 ? int(q) : 0;
                hi[i] = lo[i] + 1;
            } else {
                lo[i] = 0;
                hi[i] = res;
            }
        }
        int c[4] = {lo[0], lo[1], lo[2], dims_ == 4 ? lo[3] : 0};
        for (;;) {
            std::size_t at = 0;
            double corner[4];
            for (int i = 0; i < dims_; ++i) {
                at = at * std::size_t(res) + std::size_t(c[i]);
                corner[i] = cmin[i] + size * c[i];
            }
            add(values_[n.first + at], corner, size);
            int i = dims_ - 1;
            while (i >= 0 && ++c[i] == hi[i]) {
                c[i] = lo[i];
                --i;
            }
            if (i < 0) break;
        }
    };
    const double origin[4] = {0, 0, 0, 0};
    visit(visit, 0, origin, 1.0);

    // Cells in the order of the Hilbert curve over the output square, as
    // libBSDF's build_scaffold() sorts them: each cell's stretch starts at
    // the index of its first point, any point's with the low bits cleared.
    for (Entry& e : entries) {
        const auto u = std::uint32_t(e.u * 65536.0 + 0.5), v = std::uint32_t(e.v * 65536.0 + 0.5);
        const auto side = std::uint64_t(e.width * 65536.0 + 0.5);
        e.length = side * side;
        e.order = HilbertIndex(u, v) & ~(e.length - 1);
    }
    std::sort(entries.begin(), entries.end(),
              [](const Entry& a, const Entry& b) { return a.order < b.order; });
    auto d = std::make_shared<Distribution>();
    d->reversed = reversed;
    d->cells.reserve(entries.size());
    d->cumulative.reserve(entries.size() + 1);
    d->cumulative.push_back(0.0);
    d->minWidth = 1.0;
    for (const Entry& e : entries) {
        d->cells.push_back({e.order, e.length});
        d->cumulative.push_back(d->cumulative.back() + double(e.value) * e.width * e.width);
        d->minWidth = std::min(d->minWidth, e.width);
        d->maxWidth = std::max(d->maxWidth, e.width);
    }
    d->total = kPi * d->cumulative.back();
    return d;
}

namespace {

/// bsdf_t.c's load_tree_data() over one ScatteringData text, with byte
/// offsets for messages.
class TreeParser {
public:
    TreeParser(const char* text, int dims, const std::string& path, long long base)
        : begin_(text), p_(text), dims_(dims), path_(path), base_(base) {}

    void Parse(std::vector<TreeComponent::Node>& nodes, std::vector<float>& values) {
        nodes_ = &nodes;
        values_ = &values;
        nodes.emplace_back();
        ParseNode(0, 0);
        SkipSpace();
        if (*p_) Fail("extra characters at end of ScatteringData");
    }

private:
    [[noreturn]] void Fail(const std::string& message) const {
        ThrowUserError(FileLoc{path_, 0, base_ < 0 ? -1 : base_ + (p_ - begin_)}, message);
    }
    void SkipSpace() {
        while (std::isspace(static_cast<unsigned char>(*p_))) ++p_;
    }
    bool Eat(char c) {
        SkipSpace();
        if (*p_ != c) return false;
        ++p_;
        return true;
    }
    static bool Delimiter(char c) {
        return c == '\0' || c == ',' || c == '}' || std::isspace(static_cast<unsigned char>(c));
    }

    /// One node at `depth` levels of halving below the root, into slot `at`.
    void ParseNode(std::size_t at, int depth) {
        if (!Eat('{')) Fail("missing '{' in tensor tree");
        SkipSpace();
        if (*p_ == '{') {
            if (depth >= kMaxLog2) Fail("tensor tree finer than 2^16 cells a side");
            const std::size_t first = nodes_->size();
            (*nodes_)[at] = {-1, static_cast<std::uint32_t>(first)};
            nodes_->resize(first + (std::size_t(1) << dims_));
            for (std::size_t c = 0; c < (std::size_t(1) << dims_); ++c)
                ParseNode(first + c, depth + 1);
        } else {
            // count_values(): tokens up to the closing brace.
            std::size_t count = 0;
            for (const char* q = p_;;) {
                while (std::isspace(static_cast<unsigned char>(*q))) ++q;
                if (*q == '}' || !*q) break;
                while (!Delimiter(*q)) ++q;
                ++count;
                while (std::isspace(static_cast<unsigned char>(*q))) ++q;
                if (*q == ',') ++q;
            }
            int log2 = -1;
            for (int k = 0; dims_ * k < 63; ++k) {
                if ((std::uint64_t(1) << (dims_ * k)) == count) {
                    log2 = k;
                    break;
                }
            }
            if (log2 < 0)
                Fail("illegal value count in tensor tree (" + std::to_string(count) + ")");
            if (depth + log2 > kMaxLog2) Fail("tensor tree finer than 2^16 cells a side");
            (*nodes_)[at] = {log2, static_cast<std::uint32_t>(values_->size())};
            for (std::size_t k = 0; k < count; ++k) {
                SkipSpace();
                char* end = nullptr;
                const double v = std::strtod(p_, &end);
                if (end == p_ || !Delimiter(*end)) Fail("real format error in tensor tree");
                if (!std::isfinite(v) || std::fabs(v) > std::numeric_limits<float>::max())
                    Fail("value out of range in tensor tree");
                p_ = end;
                values_->push_back(v < 0.0 ? 0.0f : static_cast<float>(v));
                Eat(',');
            }
        }
        if (!Eat('}')) Fail("missing '}' in tensor tree");
        Eat(',');
    }

    const char* begin_;
    const char* p_;
    int dims_;
    const std::string& path_;
    long long base_;
    std::vector<TreeComponent::Node>* nodes_ = nullptr;
    std::vector<float>* values_ = nullptr;
};

}  // namespace

void ReadTreeLayer(const pugi::xml_node& layer, int rank, const std::string& path, BsdfData& bsdf) {
    const auto fail = [&](const std::string& message) {
        ThrowUserError(FileLoc{path, 0, -1}, message);
    };
    for (pugi::xml_node w = layer.child("WavelengthData"); w;
         w = w.next_sibling("WavelengthData")) {
        // Only the photopic (Y) data; colour (CIE-u, CIE-v) is skipped.
        if (!EqualNoCase(XmlText(w.child("Wavelength")), "Visible")) continue;
        for (pugi::xml_node d = w.child("WavelengthDataBlock"); d;
             d = d.next_sibling("WavelengthDataBlock")) {
            const std::string_view direction = XmlText(d.child("WavelengthDataDirection"));
            // WINDOW's front is Radiance's back (bsdf_t.c's load_bsdf_data()).
            std::unique_ptr<const BsdfComponent>* target;
            TreeSide side;
            if (EqualNoCase(direction, "Transmission Front")) {
                target = &bsdf.tb, side = TreeSide::BackTransmission;
            } else if (EqualNoCase(direction, "Transmission Back")) {
                target = &bsdf.tf, side = TreeSide::FrontTransmission;
            } else if (EqualNoCase(direction, "Reflection Front")) {
                target = &bsdf.rb, side = TreeSide::BackReflection;
            } else if (EqualNoCase(direction, "Reflection Back")) {
                target = &bsdf.rf, side = TreeSide::FrontReflection;
            } else {
                continue;  // not a direction libBSDF knows: skipped, as there
            }
            const std::string_view basis = XmlText(d.child("AngleBasis"));
            if (basis.empty()) fail("missing angle basis for a tensor tree");
            if (!EqualNoCase(basis, "LBNL/Shirley-Chiu"))
                fail("unsupported angle basis '" + std::string(basis) + "' for a tensor tree");
            const pugi::xml_node data = d.child("ScatteringData");
            const pugi::xml_node pcdata = data.first_child();
            if (XmlText(data).empty()) fail("missing ScatteringData");
            const std::ptrdiff_t base = pcdata.offset_debug();
            std::vector<TreeComponent::Node> nodes;
            std::vector<float> values;
            TreeParser(data.child_value(), rank, path, base).Parse(nodes, values);
            *target =
                std::make_unique<TreeComponent>(rank, side, std::move(nodes), std::move(values));
        }
    }
}

}  // namespace rt
