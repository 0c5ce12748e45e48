// SPDX-License-Identifier: MIT
//
// Radiance's obstructor cache layout (srcobstr.c: initobscache(),
// srcobstructp(), castshadow()); radiance-notes.md §3.6.
#include "shading/obstructors.h"

#include <cmath>
#include <variant>
#include <vector>

#include "core/conventions.h"

namespace rt {
namespace {

constexpr int kR = kObstructorResolution;

/// Radiance's (int) conversion of a cell coordinate (truncation toward
/// zero), or a value outside every table for coordinates too large to
/// convert or not numbers (a ray from very far outside the region), small
/// enough that the index arithmetic below cannot overflow.
int Truncate(double x) {
    if (!(std::fabs(x) < 1e6)) return -(1 << 20);
    return static_cast<int>(x);
}

/// `cell` if it lies in a table of `count` cells, else -1 (no cell).
int Bounded(long cell, int count) { return cell < 0 || cell >= count ? -1 : static_cast<int>(cell); }

}  // namespace

int ObstructorLayout::CellCount() const {
    switch (kind) {
        case Kind::Distant: return 4 * kR * kR;
        case Kind::Flat: return 3 * kR * kR + (kR & 1) * kR * 4;
        case Kind::Radial: return 6 * kR * kR;
        case Kind::None: break;
    }
    return 0;
}

int ObstructorLayout::Cell(const Vec3& org, const Vec3& dir) const {
    switch (kind) {
        case Kind::None: return -1;
        case Kind::Distant: {
            // Where the ray's line toward the source crosses the plane.
            const double t = (corner[axis] - org[axis]) / toSource[axis];
            if (t <= kFtiny) return -1;  // the point lies outside the region
            const int i = Truncate(2 * kR * inverseWidth1 *
                                   (org[axis1] + t * toSource[axis1] - corner[axis1]));
            const int j = Truncate(2 * kR * inverseWidth2 *
                                   (org[axis2] + t * toSource[axis2] - corner[axis2]));
            // As Radiance, only the combined index is bounded: a j past the
            // edge lands in the next row.
            return Bounded(2L * kR * i + j, CellCount());
        }
        case Kind::Flat: {
            // The direction from the source to the point, in the source's frame.
            const double s0 = -Dot(dir, u), s1 = -Dot(dir, v), s2 = -Dot(dir, normal);
            if (s2 < 0) return -1;  // behind the source
            const double m0 = std::fabs(s0), m1 = std::fabs(s1);
            constexpr double kScale = kR * (0.5 - kFtiny);
            long cell;
            if (s2 >= m0 && s2 >= m1) {  // the cube's front face
                cell = long{kR} * Truncate(kScale * (1 + s0 / s2)) + Truncate(kScale * (1 + s1 / s2));
            } else {
                constexpr int kHalf = ((kR + 1) >> 1) * kR;  // cells in one half side
                if (m0 >= m1) {  // the sides across u
                    cell = kR * kR + (s0 < 0 ? kHalf : 0) +
                           long{kR} * Truncate(kScale * (1 - s2 / m0)) +
                           Truncate(kScale * (1 + s1 / m0));
                } else {
                    cell = kR * kR + 2 * kHalf + (s1 < 0 ? kHalf : 0) +
                           long{kR} * Truncate(kScale * (1 - s2 / m1)) +
                           Truncate(kScale * (1 + s0 / m1));
                }
            }
            return Bounded(cell, CellCount());
        }
        case Kind::Radial: {
            // The cube face the direction to the source points through.
            int a = 0;
            double amax = 0;
            for (int k = 2; k >= 0; --k) {
                if (std::fabs(dir[k]) > amax) {
                    amax = std::fabs(dir[k]);
                    a = k;
                }
            }
            if (amax <= 0) return -1;
            const int a1 = (a + 1) % 3, a2 = (a + 2) % 3;
            constexpr double kScale = kR * (0.5 - kFtiny);
            return Bounded(2L * kR * kR * a + (dir[a] < 0 ? kR * kR : 0) +
                               long{kR} * Truncate(kScale * (1 + dir[a1] / amax)) +
                               Truncate(kScale * (1 + dir[a2] / amax)),
                           CellCount());
        }
    }
    return -1;
}

ObstructorLayout MakeObstructorLayout(const LightSource& src, const Vec3& cubeOrigin,
                                      double cubeSize) {
    ObstructorLayout layout;
    if (src.skip || src.proximity || src.spot || src.IsVirtual()) return layout;
    if (src.shape == LightSource::Shape::Distant) {
        if (!(cubeSize > 0)) return layout;
        layout.kind = ObstructorLayout::Kind::Distant;
        const Vec3& loc = src.location;
        double amax = 0;
        for (int k = 2; k >= 0; --k) {
            if (std::fabs(loc[k]) > amax) {
                amax = std::fabs(loc[k]);
                layout.axis = k;
            }
        }
        if (!(amax > 0)) return ObstructorLayout{};
        const int ax = layout.axis, ax1 = (ax + 1) % 3, ax2 = (ax + 2) % 3;
        layout.axis1 = ax1;
        layout.axis2 = ax2;
        layout.toSource = loc;
        // The cube's face toward the source, widened to take in the cube's
        // shadow cast along the source direction.
        layout.corner = cubeOrigin;
        if (loc[ax] > 0) layout.corner[ax] += cubeSize;
        if (loc[ax1] < 0) layout.corner[ax1] += cubeSize * loc[ax1] / amax;
        if (loc[ax2] < 0) layout.corner[ax2] += cubeSize * loc[ax2] / amax;
        layout.inverseWidth1 = 1.0 / (cubeSize * (1.0 + std::fabs(loc[ax1]) / amax));
        layout.inverseWidth2 = 1.0 / (cubeSize * (1.0 + std::fabs(loc[ax2]) / amax));
    } else if (src.shape == LightSource::Shape::Flat) {
        const double length = Length(src.size[0]);
        if (!(length > 0)) return layout;
        layout.kind = ObstructorLayout::Kind::Flat;
        layout.normal = src.normal;
        layout.u = src.size[0] / length;
        layout.v = Cross(src.normal, layout.u);
    } else {
        layout.kind = ObstructorLayout::Kind::Radial;
    }
    return layout;
}

namespace {

/// The directions of Radiance's fill rays for a flat or a radial table, by
/// cell: for a flat source in its frame (u, v, normal), for a radial one in
/// the world's axes. They are the same for every source of the kind, so they
/// are found once, by casting each of Radiance's directions back through
/// Cell(); initobscache() casts them in this order.
std::vector<Vec3> FillDirections(ObstructorLayout::Kind kind) {
    ObstructorLayout canonical;
    canonical.kind = kind;
    canonical.u = {1, 0, 0};
    canonical.v = {0, 1, 0};
    canonical.normal = {0, 0, 1};
    std::vector<Vec3> byCell(static_cast<std::size_t>(canonical.CellCount()));
    const auto add = [&](const Vec3& dir) {
        const int cell = canonical.Cell(Vec3{}, -dir);
        if (cell >= 0 && cell < canonical.CellCount()) byCell[static_cast<std::size_t>(cell)] = dir;
    };
    if (kind == ObstructorLayout::Kind::Flat) {
        // The front face of the cube around the normal...
        for (int i = kR - 1; i >= 0; --i) {
            for (int j = kR - 1; j >= 0; --j) {
                add(Normalize({2.0 / kR * (i + 0.5) - 1.0, 2.0 / kR * (j + 0.5) - 1.0, 1.0}));
            }
        }
        // ...and the front halves of its four sides.
        for (int k = 1; k >= 0; --k) {
            for (int i = kR - 1; i >= 0; --i) {
                for (int j = (kR >> 1) - 1; j >= 0; --j) {
                    const double d = 2.0 / kR * (i + 0.5) - 1.0;
                    Vec3 dir = k ? Vec3{1, d, 0} : Vec3{d, 1, 0};
                    dir.z = 1.0 - 2.0 / kR * (j + 0.5);
                    dir = Normalize(dir);
                    add(dir);
                    add({-dir.x, -dir.y, dir.z});  // mirrored about the normal
                }
            }
        }
    } else {
        for (int k = 5; k >= 0; --k) {
            const int a = k % 3, a1 = (k + 1) % 3, a2 = (k + 2) % 3;
            for (int i = kR - 1; i >= 0; --i) {
                for (int j = kR - 1; j >= 0; --j) {
                    Vec3 dir;
                    dir[a] = k < 3 ? 1.0 : -1.0;
                    dir[a1] = 2.0 / kR * (i + 0.5) - 1.0;
                    dir[a2] = 2.0 / kR * (j + 0.5) - 1.0;
                    add(Normalize(dir));
                }
            }
        }
    }
    return byCell;
}

}  // namespace

ObstructorFillRay MakeObstructorFillRay(const ObstructorLayout& layout, const LightSource& src,
                                        int cell) {
    switch (layout.kind) {
        case ObstructorLayout::Kind::Distant: {
            // Parallel to the source direction, into the scene, from the
            // centre of the cell on the plane.
            const int i = cell / (2 * kR), j = cell % (2 * kR);
            Vec3 org = layout.corner;
            org[layout.axis1] += (i + 0.5) / (2 * kR * layout.inverseWidth1);
            org[layout.axis2] += (j + 0.5) / (2 * kR * layout.inverseWidth2);
            return {org, -src.location};
        }
        case ObstructorLayout::Kind::Flat: {
            // From just in front of the centre, through the centre of the cell.
            static const std::vector<Vec3> kDirs = FillDirections(ObstructorLayout::Kind::Flat);
            const Vec3& d = kDirs[static_cast<std::size_t>(cell)];
            return {src.location + src.normal * (0.01 * src.radius),
                    layout.u * d.x + layout.v * d.y + src.normal * d.z};
        }
        case ObstructorLayout::Kind::Radial: {
            static const std::vector<Vec3> kDirs = FillDirections(ObstructorLayout::Kind::Radial);
            const Vec3& d = kDirs[static_cast<std::size_t>(cell)];
            return {src.location + d * (1.05 * src.radius), d};
        }
        case ObstructorLayout::Kind::None: break;
    }
    return {};
}

bool IsReliableBlocker(const Scene& scene, const Surface& surface) {
    if (std::holds_alternative<DistantSource>(surface.shape)) return false;
    if (scene.MayBeClipped(surface.modifierId)) return false;  // passed inside antimatter
    // No material: void, a hole, or a mixture (which ends the modifier chain
    // with no material, Surface::patterns), as findmaterial() finds none.
    if (surface.material < 0) return false;
    switch (scene.materials[static_cast<std::size_t>(surface.material)].type) {
        case MaterialType::Plastic:
        case MaterialType::Metal:
        case MaterialType::Plastic2:
        case MaterialType::Metal2:
        case MaterialType::Ashik2:
        case MaterialType::PlasFunc:
        case MaterialType::MetFunc:
        case MaterialType::PlasData:
        case MaterialType::MetData:
        case MaterialType::Light:
        case MaterialType::Spotlight:
            return true;
        default:
            return false;
    }
}

}  // namespace rt
