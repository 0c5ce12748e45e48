// SPDX-License-Identifier: MIT
//
// BSDF files as Radiance's BSDF and aBSDF materials read them (libBSDF's
// bsdf.c and the parts m_bsdf.c calls): the XML files LBNL WINDOW and
// genBSDF write, with BSDF values (1/sr) either as Klems matrices
// (scene/klems_bsdf.h) or as variable-resolution tensor trees
// (scene/tensor_tree.h).
//
// Directions are unit vectors in the BSDF's own frame: +z along the surface
// normal (Radiance's "front"; WINDOW's front is Radiance's back, so a
// file's "Transmission Back" is light entering from +z), y along the
// material's up vector. Every query takes the direction toward the viewer
// (`out`) and toward the light (`in`), both pointing away from the surface.
//
// What a file holds is split as libBSDF splits it: each component's
// smallest value is taken out as a Lambertian part (hemispherical, the
// minimum times π), the rest stays a matrix or tree. Colour data (CIE-X,
// CIE-Z, CIE-u, CIE-v blocks) is ignored: lazyrad's BSDFs are grey (README,
// "Differences").
//
//   const BsdfData b = ParseBsdf(text, "lib/blinds.xml");
//   double f = b.Evaluate(out, in);  // 1/sr
//
// A BsdfData is immutable once parsed and shared read-only between threads
// (a tree's sampling tables are built on first use, under a lock).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cal/search.h"
#include "core/diagnostics.h"
#include "core/vecmath.h"

namespace rt {

/// One scattering component (libBSDF's SDComponent with its extrema): the
/// values above the component's Lambertian part, with what sampling needs.
class BsdfComponent {
public:
    virtual ~BsdfComponent() = default;

    /// Value (1/sr) for light from `in` seen from `out` (getBSDFs): by
    /// reciprocity with the two swapped when neither lies on its side;
    /// nullopt when the pair is not this component's.
    virtual std::optional<double> Value(const Vec3& out, const Vec3& in) const = 0;
    /// Folds the projected solid angles of the cells `v1` (outgoing) and
    /// `v2` (incident) lie in, or with `v2` null those of the distribution
    /// for light from `v1`, into `psa` (queryProjSA): `minAndMax` keeps
    /// the smallest positive in psa[0] and the largest in psa[1],
    /// otherwise only the smallest.
    virtual void FoldProjectedSolidAngle(double psa[2], const Vec3& v1, const Vec3* v2,
                                         bool minAndMax) const = 0;
    /// The scattered share over the hemisphere for light from `in` (the
    /// cumulative distribution's total, cTotal); 0 when `in` is on
    /// neither side.
    virtual double Total(const Vec3& in) const = 0;
    /// Draws a scattered direction for light from `in` by the
    /// distribution (SDsampComponent()): x in [0,1) picks the cell, what is
    /// left of it places the direction in the cell along a Hilbert curve,
    /// and j0, j1 in [0,1) jitter it within the curve's cell. Its value is
    /// Total(in); nullopt when that is below libBSDF's 1e-7.
    virtual std::optional<Vec3> Sample(const Vec3& in, double x, double j0, double j1) const = 0;

    /// The smallest cell's projected solid angle.
    double minProjectedSolidAngle() const { return minProjSA_; }
    /// The largest hemispherical total over incident directions, above the
    /// Lambertian part (get_extrema() less extract_diffuse()'s share).
    double maxHemispherical() const { return maxHemi_; }
    /// The Lambertian part taken out of every value: the smallest value
    /// times π, 0 when libBSDF would not take one out.
    double lambertian() const { return lambertian_; }

protected:
    double minProjSA_ = 0, maxHemi_ = 0, lambertian_ = 0;
};

/// A loaded BSDF file (libBSDF's SDData).
struct BsdfData {
    std::string name;  // the path the file was read from, for messages
    /// Reflection seen from the front and back; transmission for light
    /// entering from the front and from the back. Absent: no such data, or
    /// nothing but its Lambertian part (libBSDF drops components whose
    /// hemispherical total above it is at most 0.001).
    std::unique_ptr<const BsdfComponent> rf, rb, tf, tb;
    /// The Lambertian parts, hemispherical (cieY): reflection on each side,
    /// transmission for light entering from each side.
    double rLambFront = 0, rLambBack = 0, tLambFront = 0, tLambBack = 0;

    const BsdfComponent* Reflection(bool front) const { return front ? rf.get() : rb.get(); }
    /// Transmission for light entering from the given side, the other
    /// side's by reciprocity when the file has only that (libBSDF's rule).
    const BsdfComponent* Transmission(bool front) const;
    bool Transmits() const { return tf || tb; }

    /// The whole BSDF (1/sr), Lambertian part included (SDevalBSDF()).
    double Evaluate(const Vec3& out, const Vec3& in) const;
    /// SDsizeBSDF(): the projected solid angles of the cells `v1` and `v2`
    /// (null: `v1` alone, every component of its side) lie in. psa[0] the
    /// smallest (10 when no cell counts, π when no component does), with
    /// `minAndMax` psa[1] the largest.
    void Size(double psa[2], const Vec3& v1, const Vec3* v2, bool minAndMax) const;
    /// SDdirectHemi() for the non-Lambertian part: the reflected (or
    /// transmitted) share above the Lambertian part for light from `in`.
    double DirectHemispherical(const Vec3& in, bool transmission) const;
};

/// Parses a BSDF file's XML text; `path` starts error messages
/// ("path: byte N: ..." for XML and tensor-tree syntax, "path: ..."
/// otherwise). Throws rt::Error (User): not a WindowElement, no optical
/// layer, an unknown data structure or angle basis, too few values, a
/// malformed tree.
BsdfData ParseBsdf(std::string_view text, const std::string& path);

/// libBSDF's SDmultiSamp() in two dimensions: `r` in [0,1) along a Hilbert
/// curve over the unit square (2^16 cells a side), `j0`, `j1` in [0,1)
/// placing the point in its cell; the result in t[0], t[1], each in [0,1).
/// The curve's first level visits (0,0), (1,0), (1,1), (0,1) in (t[0],
/// t[1]): narrowing r narrows the points, as Radiance's -ss below 1 does.
void HilbertSquare(double r, double j0, double j1, double t[2]);

/// Radiance's loadBSDF() checks: a warning `BSDF "name" has 126.8% front
/// reflection` for each side whose Lambertian part and largest
/// hemispherical total above it exceed 101 %, `name` the file's name
/// without folder and extension.
std::vector<std::string> ScatteringWarnings(const BsdfData& bsdf);

/// Each BSDF file a scene names, found on the search path and parsed once.
class BsdfFileCache {
public:
    explicit BsdfFileCache(cal::SearchPath path) : path_(std::move(path)) {}
    /// Throws rt::Error: System `cannot find BSDF file "name"` (after
    /// `requestedBy: `), or ParseBsdf's errors. A file's ScatteringWarnings()
    /// go to `warn` (when set) as it is read.
    std::shared_ptr<const BsdfData> Load(const std::string& name, const std::string& requestedBy,
                                         const WarningSink& warn = {});

private:
    cal::SearchPath path_;
    std::vector<std::pair<std::string, std::shared_ptr<const BsdfData>>> files_;
};

}  // namespace rt
