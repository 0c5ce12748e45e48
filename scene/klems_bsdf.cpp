// SPDX-License-Identifier: MIT
#include "scene/klems_bsdf.h"

#include "scene/bsdf_xml.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <pugixml.hpp>

#include "core/conventions.h"
#include "core/error.h"

namespace rt {
namespace {

constexpr double kDegrees = kPi / 180.0;

/// libBSDF's built-in bases (bsdf_m.c's abase_list): ring lower bounds in
/// degrees, with patches per ring.
struct BuiltIn {
    const char* name;
    std::vector<std::pair<double, int>> rings;
};
const BuiltIn kBuiltIns[] = {
    {"LBNL/Klems Full",
     {{0, 1}, {5, 8}, {15, 16}, {25, 20}, {35, 24}, {45, 24}, {55, 24}, {65, 16}, {75, 12}}},
    {"LBNL/Klems Half",
     {{0, 1}, {6.5, 8}, {19.5, 12}, {32.5, 16}, {46.5, 20}, {61.5, 12}, {76.5, 4}}},
    {"LBNL/Klems Quarter", {{0, 1}, {9, 8}, {27, 12}, {46, 12}, {66, 8}}},
};

/// Most patches lazyrad accepts in one basis: the largest libBSDF builds
/// in has 145; this only keeps a hostile file from asking for gigabytes.
constexpr int kMaxPatches = 100000;

std::shared_ptr<KlemsBasis> MakeBasis(std::string name,
                                      const std::vector<std::pair<double, int>>& rings,
                                      double last) {
    auto b = std::make_shared<KlemsBasis>();
    b->name = std::move(name);
    for (const auto& [theta, n] : rings) {
        b->thetaMin.push_back(theta);
        b->phis.push_back(n);
        b->first.push_back(b->count);
        b->count += n;
    }
    b->thetaMin.push_back(last);
    return b;
}

Vec3 ToFrontOut(const Vec3& v, KlemsSide side) {
    switch (side) {
        case KlemsSide::FrontOut:
            return v;
        case KlemsSide::FrontIn:
            return Vec3(-v.x, -v.y, v.z);
        case KlemsSide::BackOut:
            return Vec3(v.x, v.y, -v.z);
        case KlemsSide::BackIn:
            return -v;
    }
    return v;
}

}  // namespace

int KlemsBasis::Index(const Vec3& v) const {
    if (!(v.z >= 0.0) || v.z > 1.0) return -1;
    const double pol = std::acos(v.z) / kDegrees;
    double azi = std::atan2(v.y, v.x) / kDegrees;
    if (azi < 0.0) azi += 360.0;
    const std::size_t rings = phis.size();
    std::size_t li = 1;
    for (; thetaMin[li] <= pol; ++li) {
        if (li == rings) return -1;  // at or past the last bound
    }
    --li;
    int ndx = static_cast<int>(azi / 360.0 * phis[li] + 0.5);
    if (ndx >= phis[li]) ndx = 0;
    return first[li] + ndx;
}

namespace {
/// The ring of patch `index` (0 <= index < count).
std::size_t RingOf(const KlemsBasis& b, int index) {
    std::size_t li = 0;
    while (li + 1 < b.first.size() && b.first[li + 1] <= index) ++li;
    return li;
}
}  // namespace

Vec3 KlemsBasis::Direction(int index, double u0, double u1) const {
    // Uniform in projected solid angle: cos²θ linear in u0 (Radiance 5.4a;
    // earlier libBSDF spread θ itself linearly).
    const std::size_t li = RingOf(*this, index);
    const double c0 = std::cos(kDegrees * thetaMin[li]), c1 = std::cos(kDegrees * thetaMin[li + 1]);
    const double cosPol = std::sqrt((1.0 - u0) * c0 * c0 + u0 * c1 * c1);
    const double azi = 2.0 * kPi * (index - first[li] + u1 - 0.5) / phis[li];
    const double s = std::sqrt(std::max(0.0, 1.0 - cosPol * cosPol));
    return Vec3(std::cos(azi) * s, std::sin(azi) * s, cosPol);
}

double KlemsBasis::ProjectedSolidAngle(int index) const {
    if (index < 0 || index >= count) return -1.0;
    const std::size_t li = RingOf(*this, index);
    const double c0 = std::cos(kDegrees * thetaMin[li]), c1 = std::cos(kDegrees * thetaMin[li + 1]);
    return kPi * (c0 * c0 - c1 * c1) / phis[li];
}

int KlemsComponent::Side::Index(const Vec3& v) const { return basis->Index(ToFrontOut(v, side)); }

Vec3 KlemsComponent::Side::Direction(int index, double u0, double u1) const {
    return ToFrontOut(basis->Direction(index, u0, u1), side);
}

KlemsComponent::KlemsComponent(std::shared_ptr<const KlemsBasis> in, KlemsSide inSide,
                               std::shared_ptr<const KlemsBasis> out, KlemsSide outSide,
                               std::vector<float> values)
    : in_{std::move(in), inSide},
      out_{std::move(out), outSide},
      nin_(static_cast<std::size_t>(in_.basis->count)),
      nout_(static_cast<std::size_t>(out_.basis->count)),
      values_(std::move(values)) {
    // get_extrema(), on the values as read.
    minProjSA_ = kPi;
    for (std::size_t o = 0; o < nout_; ++o) minProjSA_ = std::min(minProjSA_, out_.Ohm(int(o)));
    for (std::size_t i = 0; i < nin_; ++i) {
        double hemi = 0;
        for (std::size_t o = 0; o < nout_; ++o) hemi += out_.Ohm(int(o)) * At(int(i), int(o));
        maxHemi_ = std::max(maxHemi_, hemi);
    }
    if (in_.basis != out_.basis) {
        for (std::size_t i = 0; i < nin_; ++i) minProjSA_ = std::min(minProjSA_, in_.Ohm(int(i)));
    }
    // subtract_min() and extract_diffuse(): the smallest value is the
    // Lambertian part, taken out of the matrix and out of its maximum.
    const float lowest = *std::min_element(values_.begin(), values_.end());
    if (lowest > kFtiny) {
        for (float& v : values_) v -= lowest;
        lambertian_ = double(lowest) * kPi;
        maxHemi_ -= lambertian_;
    }
    BuildTables();
}

void KlemsComponent::BuildTables() {
    forward_.assign(nin_ * (nout_ + 1), 0.0);
    for (std::size_t i = 0; i < nin_; ++i) {
        double* cum = &forward_[i * (nout_ + 1)];
        for (std::size_t o = 0; o < nout_; ++o)
            cum[o + 1] = cum[o] + At(int(i), int(o)) * out_.Ohm(int(o));
    }
    reverse_.assign(nout_ * (nin_ + 1), 0.0);
    for (std::size_t o = 0; o < nout_; ++o) {
        double* cum = &reverse_[o * (nin_ + 1)];
        for (std::size_t i = 0; i < nin_; ++i)
            cum[i + 1] = cum[i] + At(int(i), int(o)) * in_.Ohm(int(i));
    }
}

std::optional<double> KlemsComponent::Value(const Vec3& out, const Vec3& in) const {
    int i = in_.Index(in), o = out_.Index(out);
    if (i < 0 && o < 0) {
        i = in_.Index(out);
        o = out_.Index(in);
    }
    if (i < 0 || o < 0) return std::nullopt;
    return At(i, o);
}

void KlemsComponent::FoldProjectedSolidAngle(double psa[2], const Vec3& v1, const Vec3* v2,
                                             bool minAndMax) const {
    double outPsa = out_.Ohm(out_.Index(v1));
    double incPsa = in_.Ohm(in_.Index(v2 ? *v2 : v1));
    if (v2 && outPsa <= 0 && incPsa <= 0) {
        incPsa = out_.Ohm(out_.Index(*v2));
        outPsa = in_.Ohm(in_.Index(v1));
    }
    if (minAndMax) psa[1] = std::max({psa[1], incPsa, outPsa});
    if (incPsa > 0 && incPsa < psa[0]) psa[0] = incPsa;
    if (outPsa > 0 && outPsa < psa[0]) psa[0] = outPsa;
}

bool KlemsComponent::FiniteTotals() const {
    for (std::size_t i = 0; i < nin_; ++i) {
        if (!std::isfinite(forward_[i * (nout_ + 1) + nout_])) return false;
    }
    for (std::size_t o = 0; o < nout_; ++o) {
        if (!std::isfinite(reverse_[o * (nin_ + 1) + nin_])) return false;
    }
    return std::isfinite(maxHemi_);
}

double KlemsComponent::Total(const Vec3& in) const {
    if (const int i = in_.Index(in); i >= 0) return forward_[std::size_t(i) * (nout_ + 1) + nout_];
    if (const int o = out_.Index(in); o >= 0) return reverse_[std::size_t(o) * (nin_ + 1) + nin_];
    return 0.0;
}

std::optional<Vec3> KlemsComponent::Sample(const Vec3& in, double x, double j0, double j1) const {
    const double* cum = nullptr;
    std::size_t n = 0;
    const Side* drawn = nullptr;
    if (const int i = in_.Index(in); i >= 0) {
        cum = &forward_[std::size_t(i) * (nout_ + 1)];
        n = nout_;
        drawn = &out_;
    } else if (const int o = out_.Index(in); o >= 0) {
        cum = &reverse_[std::size_t(o) * (nin_ + 1)];
        n = nin_;
        drawn = &in_;
    } else {
        return std::nullopt;
    }
    if (cum[n] <= 1e-7) return std::nullopt;
    const double target = x * cum[n];
    // The patch whose share of the total holds `target` (never one of none).
    const std::size_t k = std::min<std::size_t>(
        std::size_t(std::upper_bound(cum + 1, cum + n + 1, target) - (cum + 1)), n - 1);
    const double width = cum[k + 1] - cum[k];
    const double local = width > 0 ? std::clamp((target - cum[k]) / width, 0.0, 1.0) : 0.5;
    double t[2];
    HilbertSquare(std::min(local, std::nextafter(1.0, 0.0)), j0, j1, t);
    return drawn->Direction(int(k), t[0], t[1]);
}

namespace {

class Reader {
public:
    explicit Reader(const std::string& path) : path_(path) {
        for (const BuiltIn& b : kBuiltIns) bases_.push_back(MakeBasis(b.name, b.rings, 90.0));
    }

    void Read(const pugi::xml_node& layer, bool rows, BsdfData& bsdf) {
        const pugi::xml_node definition = layer.child("DataDefinition");
        for (pugi::xml_node b = definition.child("AngleBasis"); b;
             b = b.next_sibling("AngleBasis")) {
            ReadBasis(b);
        }
        for (pugi::xml_node w = layer.child("WavelengthData"); w;
             w = w.next_sibling("WavelengthData")) {
            // Only the photopic (Y) data; colour (CIE-X, CIE-Z) and solar
            // blocks are skipped.
            if (!EqualNoCase(XmlText(w.child("Wavelength")), "Visible")) continue;
            for (pugi::xml_node d = w.child("WavelengthDataBlock"); d;
                 d = d.next_sibling("WavelengthDataBlock")) {
                ReadBlock(d, rows, bsdf);
            }
        }
    }

private:
    [[noreturn]] void Fail(const std::string& message) const {
        ThrowUserError(FileLoc{path_, 0, -1}, message);
    }

    std::shared_ptr<const KlemsBasis> FindBasis(std::string_view name) const {
        for (const auto& b : bases_) {
            if (EqualNoCase(b->name, name)) return b;
        }
        return nullptr;
    }

    /// A basis the file defines (load_angle_basis()); one with a known
    /// name is taken to be that one.
    void ReadBasis(const pugi::xml_node& node) {
        const std::string name(XmlText(node.child("AngleBasisName")));
        if (name.empty()) Fail("AngleBasis without AngleBasisName");
        if (FindBasis(name)) return;
        std::vector<std::pair<double, int>> rings;
        double upper = 0;
        int total = 0;
        for (pugi::xml_node b = node.child("AngleBasisBlock"); b;
             b = b.next_sibling("AngleBasisBlock")) {
            const pugi::xml_node bounds = b.child("ThetaBounds");
            const double lower =
                rings.empty() ? 0.0 : Number(XmlText(bounds.child("LowerTheta")), name);
            if (!rings.empty() &&
                std::fabs(lower - upper) > 1e-6 * std::max(std::fabs(upper), 1e-300)) {
                Fail("theta values disagree in angle basis '" + name + "'");
            }
            const double nextUpper = Number(XmlText(bounds.child("UpperTheta")), name);
            const double phis = Number(XmlText(b.child("nPhis")), name);
            if (!(phis >= 1) || phis > kMaxPatches || (phis < 2 && upper > kFtiny) ||
                !(nextUpper > upper) || nextUpper > 90.0) {
                Fail("illegal ring in angle basis '" + name + "'");
            }
            rings.emplace_back(upper, int(phis));
            total += int(phis);
            if (total > kMaxPatches) Fail("too many patches in angle basis '" + name + "'");
            upper = nextUpper;
        }
        if (rings.empty()) Fail("angle basis '" + name + "' has no AngleBasisBlock");
        bases_.push_back(MakeBasis(name, rings, upper));
    }

    double Number(std::string_view text, const std::string& basis) const {
        const std::string s(text);
        char* end = nullptr;
        const double v = std::strtod(s.c_str(), &end);
        if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v)) {
            Fail("bad number '" + s + "' in angle basis '" + basis + "'");
        }
        return v;
    }

    void ReadBlock(const pugi::xml_node& block, bool rows, BsdfData& bsdf) const {
        const std::string_view direction = XmlText(block.child("WavelengthDataDirection"));
        // WINDOW's front is Radiance's back (bsdf_m.c's load_bsdf_data()).
        std::unique_ptr<const BsdfComponent>* target;
        KlemsSide inSide, outSide;
        if (EqualNoCase(direction, "Transmission Front")) {
            target = &bsdf.tb, inSide = KlemsSide::BackIn, outSide = KlemsSide::FrontOut;
        } else if (EqualNoCase(direction, "Transmission Back")) {
            target = &bsdf.tf, inSide = KlemsSide::FrontIn, outSide = KlemsSide::BackOut;
        } else if (EqualNoCase(direction, "Reflection Front")) {
            target = &bsdf.rb, inSide = KlemsSide::BackIn, outSide = KlemsSide::BackOut;
        } else if (EqualNoCase(direction, "Reflection Back")) {
            target = &bsdf.rf, inSide = KlemsSide::FrontIn, outSide = KlemsSide::FrontOut;
        } else {
            return;  // not a direction libBSDF knows: skipped, as there
        }
        const std::string_view columnName = XmlText(block.child("ColumnAngleBasis"));
        const std::string_view rowName = XmlText(block.child("RowAngleBasis"));
        if (columnName.empty()) Fail("missing column basis");
        if (rowName.empty()) Fail("missing row basis");
        const auto in = FindBasis(columnName);
        if (!in) Fail("undefined ColumnAngleBasis '" + std::string(columnName) + "'");
        const auto out = FindBasis(rowName);
        if (!out) Fail("undefined RowAngleBasis '" + std::string(rowName) + "'");
        const std::size_t nin = std::size_t(in->count), nout = std::size_t(out->count);
        const pugi::xml_node data = block.child("ScatteringData");
        const char* p = data.child_value();
        const std::size_t available = std::char_traits<char>::length(p);
        // Each value takes at least one character: refuse before allocating.
        if (nin * nout > available) Fail("bad or missing ScatteringData (too few values)");
        std::vector<float> values(nin * nout);
        for (std::size_t k = 0; k < nin * nout; ++k) {
            while (*p && (std::isspace(static_cast<unsigned char>(*p)) || *p == ',')) ++p;
            char* end = nullptr;
            const double v = std::strtod(p, &end);
            if (end == p || !std::isfinite(v)) {
                Fail("bad or missing ScatteringData (value " + std::to_string(k + 1) + " of " +
                     std::to_string(nin * nout) + ")");
            }
            p = end;
            // "Rows": each row one incident direction; "Columns": each row
            // one outgoing direction. Stored [o·nin + i]; negatives are 0.
            const std::size_t at = rows ? (k % nout) * nin + k / nout : k;
            values[at] = v < 0.0 ? 0.0f : static_cast<float>(v);
        }
        auto component =
            std::make_unique<KlemsComponent>(in, inSide, out, outSide, std::move(values));
        // Values so large that their sums overflow would sample nonsense.
        if (!component->FiniteTotals()) Fail("ScatteringData values too large");
        *target = std::move(component);
    }

    const std::string& path_;
    std::vector<std::shared_ptr<const KlemsBasis>> bases_;
};

}  // namespace

void ReadKlemsLayer(const pugi::xml_node& layer, bool rows, const std::string& path,
                    BsdfData& bsdf) {
    Reader(path).Read(layer, rows, bsdf);
}

}  // namespace rt
