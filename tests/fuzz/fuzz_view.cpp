// SPDX-License-Identifier: MIT
//
// Fuzz target: arbitrary bytes as the header of a view file (`-vf`, read by
// rvimage and vwrays) through ApplyViewHeader, ReadViewFile's loop, then
// SetupView, then ViewRay across the image, its corners
// and beyond it. rt::Error is the expected way to refuse a view; a view that
// SetupView accepts must give, for every pixel, either no ray (outside a
// fisheye) or a finite origin, a unit direction and a finite, non-negative
// aft distance. A crash, UB, a hang or a broken invariant (abort) is a finding.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "core/error.h"
#include "tests/fuzz/fuzz_entry.h"
#include "view/view.h"

namespace {

bool Finite(const rt::Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

extern "C" int RT_FUZZ_ENTRY(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    rt::View view;
    static_cast<void>(rt::ApplyViewHeader(in, view));
    try {
        const rt::PreparedView prepared = rt::SetupView(view);
        constexpr double kCoords[] = {0.0, 0.5, 1.0, 0.013, 0.987, -0.5, 1.5};
        for (double x : kCoords) {
            for (double y : kCoords) {
                const auto ray = rt::ViewRay(prepared, x, y);
                if (!ray) continue;
                const double length = rt::Length(ray->direction);
                if (!Finite(ray->origin) || !Finite(ray->direction) ||
                    !(std::fabs(length - 1.0) < 1e-6) || !std::isfinite(ray->maxDistance) ||
                    ray->maxDistance < 0) {
                    std::fprintf(stderr, "fuzz_view: bad ray at (%g, %g) for%s\n", x, y,
                                 rt::FormatView(view).c_str());
                    std::abort();
                }
            }
        }
        static_cast<void>(rt::ViewAspect(prepared));
    } catch (const rt::Error& e) {
        rt::fuzz::ExpectRefusal(e);
        // Refused view: expected.
    }
    return 0;
}
