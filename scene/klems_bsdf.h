// SPDX-License-Identifier: MIT
//
// Klems matrices (libBSDF's bsdf_m.c): BSDF values (1/sr) on a Klems angle
// basis (the built-in "LBNL/Klems Full", "Half" and "Quarter", or one the
// file defines), one matrix per component. The file's reading and the
// conventions shared with tensor trees are in scene/bsdf_data.h.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/vecmath.h"
#include "scene/bsdf_data.h"

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
class KlemsComponent final : public BsdfComponent {
public:
    KlemsComponent(std::shared_ptr<const KlemsBasis> in, KlemsSide inSide,
                   std::shared_ptr<const KlemsBasis> out, KlemsSide outSide,
                   std::vector<float> values);

    std::optional<double> Value(const Vec3& out, const Vec3& in) const override;
    void FoldProjectedSolidAngle(double psa[2], const Vec3& v1, const Vec3* v2,
                                 bool minAndMax) const override;
    double Total(const Vec3& in) const override;
    std::optional<Vec3> Sample(const Vec3& in, double x, double j0, double j1) const override;

    /// False when some row's or column's total overflowed (absurd values).
    bool FiniteTotals() const;

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
};

}  // namespace rt
