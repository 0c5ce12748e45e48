// SPDX-License-Identifier: MIT
//
// Fuzz target: arbitrary bytes as a BSDF file (Klems matrices or tensor
// trees) through ParseBsdf, then every query the BSDF materials make (evaluation,
// patch sizes, hemispherical totals, sampling) for directions on both
// sides, grazing and along the axis. rt::Error is the expected way to
// reject input; any other exception, a crash, UB, a hang or memory out of
// proportion to the input is a finding.
#include <cmath>
#include <string>
#include <string_view>

#include "core/error.h"
#include "scene/bsdf_data.h"
#include "tests/fuzz/fuzz_entry.h"

extern "C" int RT_FUZZ_ENTRY(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const rt::BsdfData b = rt::ParseBsdf(text, "fuzz.xml");
        const rt::Vec3 dirs[] = {rt::Vec3(0, 0, 1),
                                 rt::Vec3(0, 0, -1),
                                 rt::Normalize(rt::Vec3(.3, .2, .9)),
                                 rt::Normalize(rt::Vec3(-.5, .1, -.4)),
                                 rt::Normalize(rt::Vec3(1, 0, 1e-9)),
                                 rt::Vec3(1, 0, 0)};
        for (const rt::Vec3& a : dirs) {
            for (const rt::Vec3& c : dirs) {
                static_cast<void>(b.Evaluate(a, c));
                double psa[2];
                b.Size(psa, a, &c, false);
            }
            double psa[2];
            b.Size(psa, a, nullptr, true);
            for (const bool t : {false, true}) {
                static_cast<void>(b.DirectHemispherical(a, t));
                const rt::BsdfComponent* comp =
                    t ? b.Transmission(a.z > 0) : b.Reflection(a.z > 0);
                if (!comp) continue;
                for (const double x : {0.0, 0.37, 0.999999}) {
                    static_cast<void>(comp->Sample(a, x, 0.5, 0.25));
                }
            }
        }
    } catch (const rt::Error& e) {
        rt::fuzz::ExpectRefusal(e);
        // Rejected input: expected.
    }
    return 0;
}
