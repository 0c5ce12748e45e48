// SPDX-License-Identifier: MIT
//
// Matrix BSDFs as Radiance's BSDF and aBSDF materials read them (libBSDF's
// bsdf_m.c and the parts of bsdf.c m_bsdf.c calls): the XML files LBNL
// WINDOW and genBSDF write, with BSDF values (1/sr) on a Klems angle basis
// (the built-in "LBNL/Klems Full", "Half" and "Quarter", or one the file
// defines).
//
// Directions are unit vectors in the BSDF's own frame: +z along the surface
// normal (Radiance's "front"; WINDOW's front is Radiance's back, so a
// file's "Transmission Back" is light entering from +z), y along the
// material's up vector. Every query takes the direction toward the viewer
// (`out`) and toward the light (`in`), both pointing away from the surface.
//
// What a file holds is split as libBSDF splits it: each component's
// smallest value is taken out as a Lambertian part (hemispherical, the
// minimum times π), the rest stays a matrix. Colour data (CIE-X, CIE-Z
// blocks) is ignored: lazyrad's BSDFs are grey (README, "Differences").
//
//   const KlemsBsdf b = ParseKlemsBsdf(text, "lib/blinds.xml");
//   double f = b.Evaluate(out, in);  // 1/sr
//
// A KlemsBsdf is immutable once parsed (its sampling tables are built then)
// and shared read-only between threads.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cal/search.h"
#include "core/vecmath.h"

namespace rt {

/// A Klems angle basis (bsdf_m.c's ANGLE_BASIS): latitude rings from the
/// pole, each cut into equal azimuth patches, the first patch of a ring at
/// azimuth 0 (centred on +x), azimuths counter-clockwise toward +y.
struct KlemsBasis {
    std::string name;
    std::vector<double> thetaMin;  // degrees: each ring's lower bound, then 90
    std::vector<int> phis;         // patches per ring (the first ring: 1)
    std::vector<int> first;        // index of each ring's first patch
    int count = 0;                 // patches in all

    /// The patch a front-exiting direction (z >= 0, unit) falls in
    /// (fo_getndx()); -1 at or beyond the last bound.
    int Index(const Vec3& v) const;
    /// A direction in patch `index`, (u0, u1) in [0,1)² spread uniformly
    /// over its projected solid angle: u0 over cos²θ, u1 over the azimuth
    /// (fo_getvec()).
    Vec3 Direction(int index, double u0, double u1) const;
    /// The patch's projected solid angle π(cos²θ0 − cos²θ1)/nφ (io_getohm());
    /// -1 for an index out of range.
    double ProjectedSolidAngle(int index) const;
};

/// How a matrix side's directions map to the basis's front-exiting ones:
/// front incident negates x and y, back exiting negates z, back incident
/// negates all three (bsdf_m.c's fi_, bo_, bi_ functions).
enum class KlemsSide { FrontIn, FrontOut, BackIn, BackOut };

/// One scattering matrix (libBSDF's SDMat with its extrema): the values
/// above the component's Lambertian part, with its sampling tables.
class KlemsComponent {
public:
    KlemsComponent(std::shared_ptr<const KlemsBasis> in, KlemsSide inSide,
                   std::shared_ptr<const KlemsBasis> out, KlemsSide outSide,
                   std::vector<float> values);

    /// Value (1/sr) for light from `in` seen from `out` (SDgetMtxBSDF()):
    /// by reciprocity with the two swapped when neither lies on its side;
    /// nullopt when the pair is not this component's.
    std::optional<double> Value(const Vec3& out, const Vec3& in) const;
    /// Folds the projected solid angles of the patches `v1` (outgoing) and
    /// `v2` (incident; v1 when null) lie in into `psa` (SDqueryMtxProjSA()):
    /// `minAndMax` keeps the smallest positive in psa[0] and the largest in
    /// psa[1], otherwise only the smallest.
    void FoldProjectedSolidAngle(double psa[2], const Vec3& v1, const Vec3* v2,
                                 bool minAndMax) const;
    /// The scattered share over the hemisphere for light from `in` (the
    /// cumulative total of SDgetMtxCDist()); 0 when `in` is on neither side.
    double Total(const Vec3& in) const;
    /// Draws a scattered direction for light from `in` by the row's
    /// distribution (SDsampComponent()): x in [0,1) picks the patch, what
    /// is left of it places the direction in the patch along a Hilbert
    /// curve, and j0, j1 in [0,1) jitter it within the curve's cell. Its
    /// value is Total(in); nullopt when that is below libBSDF's 1e-7.
    std::optional<Vec3> Sample(const Vec3& in, double x, double j0, double j1) const;

    /// False when some row's or column's total overflowed (absurd values).
    bool FiniteTotals() const;

    double minProjectedSolidAngle() const { return minProjSA_; }
    /// The largest hemispherical total over incident patches, above the
    /// Lambertian part (get_extrema() less extract_diffuse()'s share).
    double maxHemispherical() const { return maxHemi_; }
    /// The Lambertian part taken out of every entry: the smallest value
    /// times π (subtract_min()), 0 when that is below FTINY.
    double lambertian() const { return lambertian_; }

private:
    struct Side {
        std::shared_ptr<const KlemsBasis> basis;
        KlemsSide side;
        int Index(const Vec3& v) const;
        double Ohm(int index) const { return basis->ProjectedSolidAngle(index); }
        Vec3 Direction(int index, double u0, double u1) const;
    };
    double At(int i, int o) const { return values_[static_cast<std::size_t>(o) * nin_ + i]; }
    void BuildTables();

    Side in_, out_;
    std::size_t nin_, nout_;
    std::vector<float> values_;  // [o·nin + i]
    /// Cumulative sums per incident patch over the outgoing ones (value ×
    /// outgoing projected solid angle), nout+1 each; and per outgoing patch
    /// over the incident ones, for reciprocity.
    std::vector<double> forward_, reverse_;
    double minProjSA_ = 0, maxHemi_ = 0, lambertian_ = 0;
};

/// A loaded BSDF file (libBSDF's SDData for matrix data).
struct KlemsBsdf {
    std::string name;  // the path the file was read from, for messages
    /// Reflection seen from the front and back; transmission for light
    /// entering from the front and from the back. Absent: no such data, or
    /// nothing but its Lambertian part (libBSDF drops components whose
    /// hemispherical total above it is at most 0.001).
    std::optional<KlemsComponent> rf, rb, tf, tb;
    /// The Lambertian parts, hemispherical (cieY): reflection on each side,
    /// transmission for light entering from each side.
    double rLambFront = 0, rLambBack = 0, tLambFront = 0, tLambBack = 0;

    const KlemsComponent* Reflection(bool front) const {
        return front ? (rf ? &*rf : nullptr) : (rb ? &*rb : nullptr);
    }
    /// Transmission for light entering from the given side, the other
    /// side's by reciprocity when the file has only that (libBSDF's rule).
    const KlemsComponent* Transmission(bool front) const;
    bool Transmits() const { return tf || tb; }

    /// The whole BSDF (1/sr), Lambertian part included (SDevalBSDF()).
    double Evaluate(const Vec3& out, const Vec3& in) const;
    /// SDsizeBSDF(): the projected solid angles of the patches `v1` and
    /// `v2` (null: `v1` alone, every component of its side) lie in.
    /// psa[0] the smallest (10 when no patch counts, π when no component
    /// does), with `minAndMax` psa[1] the largest.
    void Size(double psa[2], const Vec3& v1, const Vec3* v2, bool minAndMax) const;
    /// SDdirectHemi() for the matrix part: the reflected (or transmitted)
    /// share above the Lambertian part for light from `in`.
    double DirectHemispherical(const Vec3& in, bool transmission) const;
};

/// Parses a BSDF file's XML text; `path` starts error messages
/// ("path: byte N: ..." for XML syntax, "path: ..." otherwise). Throws
/// rt::Error (User): not a WindowElement, no optical layer, a tensor tree
/// (unsupported), a missing or unknown angle basis, too few values.
KlemsBsdf ParseKlemsBsdf(std::string_view text, const std::string& path);

/// Each BSDF file a scene names, found on the search path and parsed once.
class BsdfFileCache {
public:
    explicit BsdfFileCache(cal::SearchPath path) : path_(std::move(path)) {}
    /// Throws rt::Error: System `cannot find BSDF file "name"` (after
    /// `requestedBy: `), or ParseKlemsBsdf's errors.
    std::shared_ptr<const KlemsBsdf> Load(const std::string& name, const std::string& requestedBy);

private:
    cal::SearchPath path_;
    std::vector<std::pair<std::string, std::shared_ptr<const KlemsBsdf>>> files_;
};

}  // namespace rt
