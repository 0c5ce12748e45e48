// SPDX-License-Identifier: MIT
//
// Radiance's materials whose directional reflection or transmission is
// given as functions (m_brdf.c):
// - plasfunc, metfunc, transfunc and their *data forms (m_brdf2()): a
//   diffuse part as plastic's, plus for each light source sample the
//   function of the light's direction times the specularity. There are no
//   specular rays: the indirect light reaches the whole non-transmitted part
//   (diffuse and directional) through the ambient term. Shadow rays never
//   pass.
// - BRTDfunc (m_brdf()): a mirror ray and a straight transmitted ray whose
//   coefficients are expressions, diffuse parts per side, directional
//   functions per channel; shadow rays pass with the transmission.
#include <cmath>
#include <optional>
#include <string>
#include <variant>

#include "shading/materials.h"
#include "shading/patterns.h"
#include "shading/ray_tree.h"

namespace rt {
namespace {

/// Radiance warns "compute error" at every evaluation that sets errno; once
/// per material here.
void WarnComputeError(ThreadState& ts, const Material& m) {
    if (ts.brdfWarned.insert(&m).second) {
        ts.Warn("compute error for " + std::string(MaterialTypeName(m.type)) + " \"" + m.name +
                "\"");
    }
}

}  // namespace

void ShadeBrdf(const RayTree& tree, ThreadState& ts, TracedRay& ray, const Material& m) {
    if (ray.crtype & kShadowRay) return;  // "always a shadow"
    const ShadingSetup& setup = tree.setup();
    const BrdfParams& p = std::get<BrdfParams>(m.params);
    if (!FaceTheRay(tree, ts, ray)) return;
    const bool transmits = m.type == MaterialType::TransFunc || m.type == MaterialType::TransData;
    const double rspec = p.specularity;
    const double trans = transmits ? p.transmissivity * (1.0 - rspec) : 0.0;
    const double tspec = trans * p.transmittedSpecular;
    // Both diffuse parts and the function's colour take the pattern colour.
    const Rgb mcolor = p.color * ray.pcol;
    const Rgb rdiff = mcolor * (1.0 - trans - rspec);
    const Rgb tdiff = mcolor * (trans - tspec);
    Vec3 pnorm = ray.ron;
    double pdot = ray.rod;
    if (ray.Textured()) pdot = PerturbedNormal(setup.scene, ts, ray, pnorm);
    // Only metfunc's reflection and transfunc's transmission are coloured.
    const bool colouredReflection = m.type == MaterialType::MetFunc || m.type == MaterialType::MetData;
    const BrdfInputs inputs{pnorm, pdot, mcolor};

    // Direct light's coefficient per source sample (Radiance's dirbrdf()).
    auto coefficient = [&](const Vec3& ldir, double omega) {
        Rgb cval;
        const double ldot = Dot(pnorm, ldir);
        if (ldot <= kFtiny && ldot >= -kFtiny) return cval;  // too close to grazing
        if (ldot < 0.0 ? trans <= kFtiny : trans >= 1.0 - kFtiny) return cval;  // wrong side
        cval = (ldot > 0.0 ? rdiff : tdiff) * (std::fabs(ldot) * omega / kPi);
        if (ldot > 0.0 ? rspec <= kFtiny : tspec <= kFtiny) return cval;  // diffuse only
        const std::optional<Rgb> brdf =
            EvaluateBrdf(setup.scene, ts, ray, m.function, inputs, ldir, omega);
        if (!brdf) {
            WarnComputeError(ts, m);
            return cval;
        }
        const double f = brdf->r;  // one function: grey
        if (f <= kFtiny) return cval;
        if (ldot > 0.0) {
            const Rgb c = colouredReflection ? mcolor * f : Rgb::Grey(f);
            cval += c * (ldot * omega * rspec);
        } else {
            const Rgb c = transmits ? mcolor * f : Rgb::Grey(f);
            cval += c * (-ldot * omega * tspec);
        }
        return cval;
    };
    // Indirect light, from this side (for the whole reflection) and from the
    // other (for the whole transmission), then the direct light.
    const Rgb front = mcolor * (1.0 - trans);
    const Rgb back = mcolor * trans;
    AddIndirectAndDirect(tree, ts, ray, pnorm, trans < 1.0 - kFtiny ? &front : nullptr,
                         trans > kFtiny ? &back : nullptr, coefficient);
}

void ShadeBrtd(const RayTree& tree, ThreadState& ts, TracedRay& ray, const Material& m) {
    // BRTDfunc (m_brdf()): two-sided by its own arguments, -bv aside. The
    // transmission it gives as expressions reaches shadow rays too.
    const ShadingSetup& setup = tree.setup();
    const BrtdParams& p = std::get<BrtdParams>(m.params);
    const bool front = ray.rod > 0.0;
    Rgb rdiff = front ? p.frontDiffuse : p.backDiffuse;
    Rgb tdiff = p.diffuseTransmission;
    const bool textured = ray.Textured();
    Vec3 pnorm = ray.ron;
    double pdot = ray.rod;
    if (textured) pdot = PerturbedNormal(setup.scene, ts, ray, pnorm);
    if (!front) {
        // Oriented toward the ray; Radiance turns the ray's perturbation too.
        pdot = -pdot;
        pnorm = -pnorm;
        ray.pert = -ray.pert;
    }
    const Rgb mcolor = ray.pcol;  // CrP…: the pattern colour alone
    rdiff *= mcolor;
    tdiff *= mcolor;
    const bool hasRefl = Bright(rdiff) > kFtiny;
    const bool hasTrans = Bright(tdiff) > kFtiny;
    const BrdfInputs inputs{pnorm, pdot, mcolor};

    // Specular transmission straight through (bent by a texture, except
    // for shadow and ambient rays, which must reach what they aim at).
    double transTest = 0, transDistance = 0;
    if (const auto coef = EvaluateBrdfColour(setup.scene, ts, ray, m.function, inputs, 3); !coef) {
        WarnComputeError(ts, m);
    } else {
        TracedRay child;
        if (tree.StartChild(ts, child, ray, kTransRay, &*coef)) {
            child.dir = ray.dir;
            if (textured && !(ray.crtype & (kShadowRay | kAmbientRay))) {
                const Vec3 bent = ray.dir - ray.pert;
                if (LengthSquared(bent) > 0.0) {
                    child.dir = Normalize(bent);
                } else if (ray.surface >= 0 &&
                           ts.perturbationWarned
                               .insert(&setup.scene.HitSurface(ray.instance, ray.surface))
                               .second) {
                    ts.Warn("illegal perturbation for BRTDfunc \"" + m.name + "\"");
                }
            }
            tree.Trace(ts, child);
            const Rgb c = child.rcol * child.rcoef;
            ray.rcol += c;
            if (!textured) {
                transTest = 2.0 * Bright(c);
                transDistance = ray.rot + child.EffectiveDistance();
            }
        }
    }
    if (ray.crtype & kShadowRay) return;

    // Specular reflection in the (perturbed) mirror direction.
    if (const auto coef = EvaluateBrdfColour(setup.scene, ts, ray, m.function, inputs, 0); !coef) {
        WarnComputeError(ts, m);
    } else {
        TracedRay child;
        if (tree.StartChild(ts, child, ray, kReflectedRay, &*coef)) {
            child.dir = Normalize(ray.dir + pnorm * (2.0 * pdot));
            tree.Trace(ts, child);
            const Rgb c = child.rcol * child.rcoef;
            ray.mcol = c;
            ray.rcol += c;
            ray.rmt = ray.rot;
            if (IsFlatHit(setup.scene, ray) && (!textured || (ray.crtype & kAmbientRay))) {
                ray.rmt += child.EffectiveDistance();
            }
        }
    }

    // Direct light (dirbrdf() with both specular shares 1): the diffuse part
    // of the side the light is on, plus the directional functions.
    auto coefficient = [&](const Vec3& ldir, double omega) {
        Rgb cval;
        const double ldot = Dot(pnorm, ldir);
        if (ldot <= kFtiny && ldot >= -kFtiny) return cval;  // too close to grazing
        cval = (ldot > 0.0 ? rdiff : tdiff) * (std::fabs(ldot) * omega / kPi);
        const std::optional<Rgb> f =
            EvaluateBrdf(setup.scene, ts, ray, m.function, inputs, ldir, omega);
        if (!f) {
            WarnComputeError(ts, m);
            return cval;
        }
        if (Bright(*f) <= kFtiny) return cval;
        return cval + *f * (std::fabs(ldot) * omega);
    };
    // The indirect light is gathered facing the ray, whichever side it hit.
    if (!front) ray.FlipSurface();
    const Pattern& functions = setup.scene.patterns[static_cast<std::size_t>(m.function)];
    AddIndirectAndDirect(tree, ts, ray, pnorm, hasRefl ? &rdiff : nullptr,
                         hasTrans ? &tdiff : nullptr, coefficient,
                         hasRefl || hasTrans || functions.data.functions[0].slot >= 0);
    if (!front) {
        // The ray keeps its surface's orientation, and Radiance's negated
        // perturbation.
        ray.FlipSurface();
        ray.pert = -ray.pert;
    }
    if (transTest > Bright(ray.mcol)) ray.rxt = transDistance;
}

}  // namespace rt
