// SPDX-License-Identifier: MIT
//
// BSDF and aBSDF: Radiance's materials whose scattering is a BSDF file
// (m_bsdf.c), Klems matrices or tensor trees (scene/bsdf_data.h). The file's
// Lambertian parts, plus the diffuse parts the reals add, take the indirect
// light through the ambient term and the direct light as a diffuse
// surface's. The rest is sampled with rays when its hemispherical share
// exceeds -st, and otherwise joins the ambient term; the direct light adds
// it per source, averaged over the source and the view direction's patch.
//
// The frame: +z along the (perturbed) surface normal, y along the up
// vector. A BSDF of non-zero thickness is a proxy: rays other than sampled
// and ambient ones pass it, as do rays hitting its hidden side, and its
// transmitted light leaves `thickness` behind the surface. An aBSDF passes
// view and shadow rays with its "through" peak, if it has one.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <variant>

#include "shading/materials.h"
#include "shading/patterns.h"
#include "shading/ray_tree.h"

namespace rt {
namespace {

/// One hit's frame and parts (m_bsdf.c's BSDFDAT).
struct BsdfHit {
    BsdfHit(const BsdfData& s, const TracedRay& r, double ss) : sd(s), ray(r), specJitter(ss) {}

    const BsdfData& sd;
    const TracedRay& ray;
    double specJitter;          // -ss
    Vec3 x, y, z;               // the frame's axes in render space
    Vec3 pnorm;                 // perturbed normal, turned toward the ray
    Vec3 vray;                  // toward the viewer, local
    double srVpsa[2] = {0, 0};  // square roots of the view patch's smallest and largest
                                // projected solid angles
    double thickness = 0;
    Rgb cthru, cthruSurround;  // aBSDF's through peak and its surround (BTDF)
    Rgb rdiff, tdiff;          // diffuse parts, pattern applied
    Rgb runsamp, tunsamp;      // matrix shares left to the ambient term

    Vec3 ToLocal(const Vec3& w) const { return Normalize(Vec3(Dot(x, w), Dot(y, w), Dot(z, w))); }
    Vec3 ToWorld(const Vec3& l) const { return Normalize(x * l.x + y * l.y + z * l.z); }

    /// bsdf_jitter(): the view direction moved at random by up to half of
    /// `sr` (a patch's size) on each axis, less with -ss below 1.
    Vec3 Jittered(double sr, Rng& rng) const {
        if (specJitter < 1.0) sr *= specJitter;
        if (sr <= kFtiny) return vray;
        Vec3 v = vray;
        v.x += sr * (0.5 - rng.Uniform());
        v.y += sr * (0.5 - rng.Uniform());
        return Normalize(v);
    }

    /// The transmission component light from this side of the surface
    /// meets (pr->rod > 0: the front).
    const BsdfComponent* ViewTransmission() const { return sd.Transmission(ray.rod > 0.0); }
};

/// compute_through(): an aBSDF's peak around the straight-through
/// direction, from 29 probes a patch apart; sets cthru (already times its
/// solid angle) and the mean BTDF around it, or leaves both zero.
void ComputeThrough(BsdfHit& h) {
    static constexpr float kProbes[29][2] = {
        {0, 0},       {-0.6, 0},   {0, 0.6},     {0, -0.6},   {0.6, 0},     {-0.6, 0.6},
        {-0.6, -0.6}, {0.6, 0.6},  {0.6, -0.6},  {-1.2, 0},   {0, 1.2},     {0, -1.2},
        {1.2, 0},     {-1.2, 1.2}, {-1.2, -1.2}, {1.2, 1.2},  {1.2, -1.2},  {-1.8, 0},
        {0, 1.8},     {0, -1.8},   {1.8, 0},     {-1.8, 1.8}, {-1.8, -1.8}, {1.8, 1.8},
        {1.8, -1.8},  {-2.4, 0},   {0, 2.4},     {0, -2.4},   {2.4, 0}};
    const BsdfComponent* t = h.ViewTransmission();
    if (!t || Bright(h.ray.pcol) <= kFtiny) return;
    const double search = std::sqrt(t->minProjectedSolidAngle());
    struct Probe {
        double value;
        Vec3 dir;
    } probes[29];
    for (int i = 0; i < 29; ++i) {
        const Vec3 d = Normalize(Vec3(-h.vray.x + kProbes[i][0] * search,
                                      -h.vray.y + kProbes[i][1] * search, -h.vray.z));
        probes[i] = {h.sd.Evaluate(d, h.vray), d};
    }
    std::stable_sort(std::begin(probes), std::end(probes),
                     [](const Probe& a, const Probe& b) { return a.value > b.value; });
    if (probes[0].value <= kFtiny) return;
    double peak = 0, surround = 0, peakOmega = 0, surroundOmega = 0, peakSum = 0;
    int n = 0;
    for (int i = 0; i < 29; ++i) {
        if (i > 0 && probes[i].value == probes[i - 1].value) continue;  // the same patch
        double psa[2];
        h.sd.Size(psa, probes[i].dir, &h.vray, false);
        const double omega = psa[0];
        if (omega > 1.5 * t->minProjectedSolidAngle() || peakSum > 8.0 * probes[i].value * n) {
            if (i == 0) return;
            surround += probes[i].value * omega;
            surroundOmega += omega;
            continue;
        }
        peak += probes[i].value * omega;
        peakOmega += omega;
        peakSum += probes[i].value;
        ++n;
    }
    if (surroundOmega <= kFtiny) return;
    const double lamb = h.vray.z > 0.0 ? h.sd.tLambFront : h.sd.tLambBack;
    if ((peakSum / n - lamb / kPi) * peakOmega < 0.0005) return;  // below 0.05 %
    h.cthru = h.ray.pcol * peak;
    h.cthruSurround = h.ray.pcol * (surround / surroundOmega);
}

/// direct_specular_OK(): the matrix part (above the Lambertian) for light
/// from `ldir` over `omega`, averaged over the view patch;
/// nullopt when there is none. Grey, except near an aBSDF's through
/// direction, where it is the peak's surround (pattern applied).
std::optional<Rgb> DirectSpecular(const BsdfHit& h, const Vec3& ldir, double omega, Rng& rng) {
    const Vec3 vsrc = h.ToLocal(ldir);
    const bool srcFront = vsrc.z > 0.0, viewFront = h.vray.z > 0.0;
    double lamb;
    if (srcFront && viewFront) {
        if (!h.sd.rf) return std::nullopt;
        lamb = h.sd.rLambFront;
    } else if (!srcFront && !viewFront) {
        if (!h.sd.rb) return std::nullopt;
        lamb = h.sd.rLambBack;
    } else {
        if (!h.sd.Transmits()) return std::nullopt;
        // Radiance's choice: the front's for light from behind.
        lamb = viewFront ? h.sd.tLambFront : h.sd.tLambBack;
    }
    const double diffuse = lamb > kFtiny ? lamb / kPi : 0.0;
    omega *= std::fabs(vsrc.z);  // projected
    if (srcFront != viewFront && Bright(h.cthru) > kFtiny) {
        // Near the through direction the peak is already counted: only
        // its surround.
        const double dx = vsrc.x + h.vray.x, dy = vsrc.y + h.vray.y;
        const double m = h.ViewTransmission()->minProjectedSolidAngle();
        if (dx * dx + dy * dy <= (2.5 * 4.0 / kPi) * (omega + m + 2.0 * std::sqrt(omega * m))) {
            if (Bright(h.cthruSurround) <= kFtiny) return std::nullopt;
            return h.cthruSurround;
        }
    }
    // The view direction is the file's incident one and the light's the
    // outgoing one, as for the sampled rays: Radiance 5.4a's choice (its
    // binary, on data without reciprocity), in values and cell sizes alike.
    double psa[2];
    h.sd.Size(psa, vsrc, &h.vray, false);
    const double tomega = psa[0];
    // Radiance 5.4a's sampling: about 4·(-ss)·weight view directions
    // jittered over the view patch, all aimed at the source sample's
    // direction; those meeting only the Lambertian part are left out of
    // the mean rather than counted as zero.
    const double tsr = std::sqrt(tomega);
    int nsamp = 1;
    if (tsr > 0.0) {
        nsamp = static_cast<int>(4.0 * h.specJitter * h.ray.rweight + 0.5);
        nsamp += nsamp == 0;
    }
    double sum = 0, weight = 0;
    for (int i = nsamp; i--;) {
        const Vec3 vjit = h.Jittered(tsr, rng);
        const double f = h.sd.Evaluate(vsrc, vjit);
        if (f - diffuse <= kFtiny) continue;  // no matrix part
        // A much finer patch there (variable resolution) is not safe to use.
        h.sd.Size(psa, vsrc, &vjit, false);
        if (psa[0] < 0.12 * tomega) continue;
        sum += f;
        weight += 1.0;
    }
    if (weight <= kFtiny) return std::nullopt;
    return Rgb::Grey(std::max(sum / weight - diffuse, 0.0));
}

/// One component's sampled rays (sample_sdcomp()).
void SampleComponent(const RayTree& tree, ThreadState& ts, TracedRay& ray, const BsdfHit& h,
                     const BsdfComponent& c, bool transmission, const Vec3& frontNormal) {
    const double ss = h.specJitter;
    const bool hasThrough =
        transmission && !(ray.crtype & (kSpecularRay | kAmbientRay)) && Bright(h.cthru) > kFtiny;
    int target = 1;
    if (ss > 1.5) {
        target = static_cast<int>(ss * ray.rweight + 0.5);
        target += target == 0;
    }
    for (int n = 0; n < target; ++n) {
        double x = target == 1 ? ts.rng.Uniform() : (n + ts.rng.Uniform()) / target;
        if (target == 1 && ss < 1.0) x = 0.5 + ss * (x - 0.5);
        const Vec3 vinc = h.Jittered(h.srVpsa[0], ts.rng);
        const double total = c.Total(vinc);
        const std::optional<Vec3> vsmp = c.Sample(vinc, x, ts.rng.Uniform(), ts.rng.Uniform());
        if (!vsmp || total <= kFtiny) break;  // nothing to sample
        if (hasThrough) {
            const double dx = vinc.x + vsmp->x, dy = vinc.y + vsmp->y;
            if (dx * dx + dy * dy <= h.srVpsa[0] * h.srVpsa[0]) continue;  // the view ray's
        }
        Rgb coef = Rgb::Grey(total / target);
        if (transmission) coef *= ray.pcol;
        TracedRay child;
        if (!tree.StartChild(ts, child, ray, kSpecularRay, &coef)) {
            // The first of several refused (below -lw): as Radiance, start
            // again with fewer, heavier rays, in proportion to the weight
            // the ray lacked. Refused for another reason (-lr), the count
            // would not fall: give up.
            if (n == 0 && target > 1) {
                const int before = target;
                target = static_cast<int>(target * child.rweight /
                                          (tree.setup().shading.limits.weight + 1e-20));
                if (target >= before) break;
                n = -1;
            }
            continue;
        }
        child.dir = h.ToWorld(*vsmp);
        if (transmission && h.thickness != 0.0) child.org -= frontNormal * h.thickness;
        tree.Trace(ts, child);
        ray.rcol += child.rcol * child.rcoef;
    }
}

/// sample_sdf(): the reflected or transmitted matrix part, with rays when
/// its share exceeds -st, else left in `unsampled` for the ambient term.
void SampleMatrix(const RayTree& tree, ThreadState& ts, TracedRay& ray, BsdfHit& h,
                  bool transmission, const Vec3& frontNormal) {
    Rgb& unsampled = transmission ? h.tunsamp : h.runsamp;
    unsampled = Rgb();
    const BsdfComponent* c = transmission ? h.ViewTransmission() : h.sd.Reflection(ray.rod > 0.0);
    if (!c) return;
    double b = 0;  // the share the through ray took
    if (transmission && !(ray.crtype & (kSpecularRay | kAmbientRay)) && Bright(h.cthru) > kFtiny) {
        // The view ray straight through, with the peak's coefficient.
        TracedRay child;
        if (tree.StartChild(ts, child, ray, kTransRay, &h.cthru)) {
            child.dir = ray.dir;
            tree.Trace(ts, child);
            ray.rcol += child.rcol * child.rcoef;
            ray.rxt = ray.rot + child.EffectiveDistance();
            b = Bright(h.cthru);
        }
    }
    if (c->maxHemispherical() - b <= kFtiny) {
        b = 0;
    } else {
        b = std::max(h.sd.DirectHemispherical(h.Jittered(h.srVpsa[1], ts.rng), transmission) - b,
                     0.0);
    }
    if (b <= tree.setup().shading.specular.threshold + kFtiny) {
        // Below -st: joins the ambient term (no pattern on reflection).
        if (b > kFtiny) unsampled = transmission ? ray.pcol * b : Rgb::Grey(b);
        return;
    }
    SampleComponent(tree, ts, ray, h, *c, transmission, frontNormal);
}

}  // namespace

void ShadeBsdf(const RayTree& tree, ThreadState& ts, TracedRay& ray, const Material& m) {
    const ShadingSetup& setup = tree.setup();
    const auto& p = std::get<BsdfParams>(m.params);
    const bool hitFront = ray.rod > 0.0;
    const BsdfFrame frame = EvaluateBsdfFrame(setup.scene, ts, ray, m.function);
    const double thickness = m.type == MaterialType::Bsdf ? frame.thickness : 0.0;
    if (!hitFront && !setup.shading.backfaceVisible) {
        tree.PassThrough(ts, ray);
        return;
    }
    // A proxy hides itself from all but sampled and ambient rays, and from
    // rays meeting its hidden side.
    if (thickness != 0.0 &&
        ((ray.crtype & kShadowRay) || !(ray.crtype & (kSpecularRay | kAmbientRay)) ||
         ((thickness > 0.0) != hitFront))) {
        tree.PassThrough(ts, ray);
        return;
    }
    const BsdfData& sd = *p.data;
    // A zero-thickness BSDF stops shadow rays, as does any without transmission.
    if ((ray.crtype & kShadowRay) && (m.type == MaterialType::Bsdf || !sd.Transmits())) return;
    BsdfHit h(sd, ray, setup.shading.specular.sampling);
    h.thickness = thickness;
    // Diffuse parts: the file's Lambertian ones plus the reals'.
    if (hitFront) {
        h.rdiff = Rgb::Grey(sd.rLambFront) + p.frontDiffuse;
        h.tdiff = Rgb::Grey(sd.tLambFront);
    } else {
        h.rdiff = Rgb::Grey(sd.rLambBack) + p.backDiffuse;
        h.tdiff = Rgb::Grey(sd.tLambBack);
    }
    h.tdiff += p.diffuseTransmission;
    h.rdiff *= ray.pcol;
    h.tdiff *= ray.pcol;
    Vec3 pnorm = ray.ron;
    if (ray.Textured()) PerturbedNormal(setup.scene, ts, ray, pnorm);
    // The frame (SDcompXform()): x = up × n, y = n × x.
    h.z = pnorm;
    h.x = Cross(frame.up, h.z);
    const double xLength = Length(h.x);
    if (!(xLength > 0.0) || !std::isfinite(xLength)) {
        if (ts.orientationWarned.insert(&m).second) {
            ts.Warn(std::string("Illegal orientation vector for ") + MaterialTypeName(m.type) +
                    " \"" + m.name + "\"");
        }
        return;  // black, as Radiance leaves it
    }
    h.x *= 1.0 / xLength;
    h.y = Cross(h.z, h.x);
    h.vray = h.ToLocal(-ray.dir);
    if (m.type == MaterialType::ABsdf) {
        ComputeThrough(h);
        if (ray.crtype & kShadowRay) {
            // The through part passes the shadow ray, scaled.
            TracedRay child;
            if (!tree.StartChild(ts, child, ray, kTransRay, &h.cthru)) return;
            child.dir = ray.dir;
            tree.Trace(ts, child);
            ray.rcol = child.rcol * child.rcoef;
            return;
        }
    }
    sd.Size(h.srVpsa, h.vray, nullptr, true);
    h.srVpsa[0] = std::sqrt(h.srVpsa[0]);
    h.srVpsa[1] = std::sqrt(h.srVpsa[1]);
    const Vec3 frontNormal = ray.ron;  // the surface's own, for the proxy's offset
    h.pnorm = hitFront ? pnorm : -pnorm;

    SampleMatrix(tree, ts, ray, h, false, frontNormal);
    SampleMatrix(tree, ts, ray, h, true, frontNormal);

    // The ambient term from the ray's side for the reflection, from the
    // other for the transmission (a proxy's from behind its detail).
    const Rgb reflected = h.rdiff + h.runsamp;
    if (Bright(reflected) > kFtiny) {
        if (!hitFront) ray.FlipSurface();
        ray.rcol += tree.indirect().Ambient(ts, reflected, ray, h.pnorm);
        if (!hitFront) ray.FlipSurface();
    }
    const Rgb transmitted = h.tdiff + h.tunsamp;
    if (Bright(transmitted) > kFtiny) {
        TracedRay other = ray;
        if (hitFront) other.FlipSurface();
        other.rop += other.ron * thickness;
        ray.rcol += tree.indirect().Ambient(ts, transmitted, other, -h.pnorm);
    }

    // The direct light (dir_bsdf(), dir_brdf(), dir_btdf()).
    const auto diffusePart = [&](double ldot, double omega) {
        return (ldot > 0.0 ? h.rdiff : h.tdiff) * (std::fabs(ldot) * omega / kPi);
    };
    const auto reflection = [&](const Vec3& ldir, double omega) {
        const double ldot = Dot(h.pnorm, ldir);
        if (ldot <= kFtiny) return Rgb();
        Rgb c = Bright(h.rdiff) > kFtiny ? diffusePart(ldot, omega) : Rgb();
        if (const auto s = DirectSpecular(h, ldir, omega, ts.rng)) c += *s * (ldot * omega);
        return c;
    };
    const auto transmission = [&](const Vec3& ldir, double omega) {
        const double ldot = Dot(h.pnorm, ldir);
        if (ldot >= -kFtiny) return Rgb();
        Rgb c = Bright(h.tdiff) > kFtiny ? diffusePart(ldot, omega) : Rgb();
        if (const auto s = DirectSpecular(h, ldir, omega, ts.rng))
            c += *s * ray.pcol * (-ldot * omega);
        return c;
    };
    const auto both = [&](const Vec3& ldir, double omega) {
        const double ldot = Dot(h.pnorm, ldir);
        if (ldot >= -kFtiny && ldot <= kFtiny) return Rgb();
        return ldot > 0.0 ? reflection(ldir, omega) : transmission(ldir, omega);
    };
    if (Bright(h.tdiff) <= kFtiny && !sd.Transmits()) {
        tree.direct().Add(ts, ray, reflection);
    } else if (thickness == 0.0) {
        tree.direct().Add(ts, ray, both);
    } else {
        tree.direct().Add(ts, ray, reflection);
        TracedRay behind = ray;
        behind.rcol = Rgb();
        behind.rop -= frontNormal * thickness;
        tree.direct().Add(ts, behind, transmission);
        ray.rcol += behind.rcol;
    }
}

}  // namespace rt
