// SPDX-License-Identifier: MIT
//
// plasfunc, metfunc, transfunc and their *data forms: Radiance's materials
// whose directional reflection (or transmission) is a BRDF given as a
// function (m_brdf.c, m_brdf2()). A diffuse part as plastic's, plus for each
// light source sample the function of the light's direction times the
// specularity; there are no specular rays: the indirect light reaches the
// whole non-transmitted part (diffuse and directional) through the ambient
// term, as in Radiance. Shadow rays never pass.
#include <string>
#include <variant>

#include "shading/materials.h"
#include "shading/patterns.h"
#include "shading/ray_tree.h"

namespace rt {

void ShadeBrdf(const RayTree& tree, ThreadState& ts, TracedRay& ray, const Material& m) {
    if (ray.crtype & kShadowRay) return;  // "always a shadow"
    const ShadingSetup& setup = tree.setup();
    const BrdfParams& p = std::get<BrdfParams>(m.params);
    if (ray.rod < 0.0) {
        if (!setup.shading.backfaceVisible) {
            tree.PassThrough(ts, ray);
            return;
        }
        ray.FlipSurface();
    }
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
        const std::optional<double> f =
            EvaluateBrdf(setup.scene, ts, ray, m.function, inputs, ldir, omega);
        if (!f) {
            // Radiance warns at every call; once per material here.
            if (ts.brdfWarned.insert(&m).second) {
                ts.Warn("compute error for " + std::string(MaterialTypeName(m.type)) + " \"" +
                        m.name + "\"");
            }
            return cval;
        }
        if (*f <= kFtiny) return cval;
        if (ldot > 0.0) {
            const Rgb c = colouredReflection ? mcolor * *f : Rgb::Grey(*f);
            cval += c * (ldot * omega * rspec);
        } else {
            const Rgb c = transmits ? mcolor * *f : Rgb::Grey(*f);
            cval += c * (-ldot * omega * tspec);
        }
        return cval;
    };
    // Indirect light, from this side (for the whole reflection) and from the
    // other (for the whole transmission).
    if (trans < 1.0 - kFtiny) {
        const auto other = [&]() {
            TracedRay copy = ray;
            tree.direct().Add(ts, copy, coefficient);
            return Bright(copy.rcol);
        };
        const OtherRadianceRef otherRef(other);
        ray.rcol += tree.indirect().Ambient(ts, mcolor * (1.0 - trans), ray, pnorm, &otherRef);
    }
    if (trans > kFtiny) {
        ray.FlipSurface();
        ray.rcol += tree.indirect().Ambient(ts, mcolor * trans, ray, -pnorm);
        ray.FlipSurface();
    }
    tree.direct().Add(ts, ray, coefficient);
}

}  // namespace rt
