// SPDX-License-Identifier: MIT
//
// Radiance's direct calculation (source.c direct(), srcvalue(), raycont() for
// shadow rays); radiance-notes.md §3.3–3.4.
#include <algorithm>
#include <cmath>

#include "shading/integrator.h"

namespace rt {
namespace {

/// Radiance tests at least this many shadow rays per shading point (MINSHADCNT)
/// before the -dt threshold may stop testing.
constexpr int kMinShadowTests = 2;

struct Contribution {
    int source = -1;
    Vec3 dir;
    Rgb coef;      // material coefficient for this sample
    Rgb value;     // unshadowed radiance ⊗ coef
    double bright = 0;
};

}  // namespace

Rgb Integrator::SourceValue(TracedRay& sray, int source) {
    const LightSource& src = sources_[source];
    const Surface& surface = scene_.surfaces[src.surface];
    if (src.shape == LightSource::Shape::Distant) {
        // Samples of a distant source lie inside its cone by construction.
        sray.surface = src.surface;
        sray.hitDistant = true;
        sray.rot = kFhuge;
        sray.rop = sray.org;
        sray.ron = -sray.dir;
        sray.geometricNormal = sray.ron;
        sray.rod = 1.0;
    } else {
        auto hit = core_.IntersectSurface(src.surface, sray.org, sray.dir);
        if (!hit) return Rgb();  // aiming failure: numerically missed the source
        sray.surface = src.surface;
        sray.rot = hit->t;
        sray.rop = hit->point;
        sray.ron = hit->normal;
        sray.geometricNormal = hit->normal;
        sray.rod = -Dot(sray.dir, hit->normal);
    }
    sray.rcol = Rgb();
    ShadeLight(sray, scene_.materials[surface.material]);
    return sray.rcol;
}

void Integrator::ContinueShadowRay(TracedRay& sray) {
    sray.rcol = Rgb();
    Shade(sray);
    Report(sray);
}

void Integrator::Direct(TracedRay& ray, const std::function<Rgb(const Vec3&, double)>& coef) {
    if (sources_.empty()) return;
    std::vector<SourceSample> samples;
    CollectSourceSamples(sources_, ray.rop, ray.rweight, shading_.direct, rng_, samples);
    if (samples.empty()) return;

    std::vector<Contribution> contribs;
    contribs.reserve(samples.size());
    for (const SourceSample& s : samples) {
        Contribution c;
        c.source = s.source;
        c.dir = s.dir;
        c.coef = coef(s.dir, s.omega);
        if (Bright(c.coef) <= 0.0) continue;
        TracedRay sray;
        StartChild(sray, ray, kShadowRay, nullptr);
        sray.dir = s.dir;
        sray.rsrc = s.source;
        c.value = SourceValue(sray, s.source) * c.coef;
        c.bright = Bright(c.value);
        if (c.bright > 0.0) contribs.push_back(c);
    }
    if (contribs.empty()) return;
    std::stable_sort(contribs.begin(), contribs.end(),
                     [](const Contribution& a, const Contribution& b) { return a.bright > b.bright; });
    const int n = static_cast<int>(contribs.size());
    // Tail sums: tail[k] = Σ_{m >= k} bright_m.
    std::vector<double> tail(n + 1, 0.0);
    for (int k = n - 1; k >= 0; --k) tail[k] = tail[k + 1] + contribs[k].bright;

    const int nshadcheck = static_cast<int>(std::pow(double(n), shading_.direct.certainty) + 0.5);
    const double threshold = shading_.direct.threshold / ray.rweight;
    int nhits = 0;
    double hwt = 0.0;
    int k = 0;
    for (; k < n; ++k) {
        // Stop once the untested remainder cannot matter (-dt), but only after
        // the minimum number of tests.
        double remaining = k + nshadcheck >= n ? tail[k] : tail[k] - tail[k + nshadcheck];
        if (k >= kMinShadowTests && remaining < threshold * Bright(ray.rcol)) break;
        Contribution& c = contribs[k];
        LightSource& src = sources_[c.source];
        src.ntests++;
        TracedRay sray;
        StartChild(sray, ray, kShadowRay, nullptr);
        sray.dir = c.dir;
        sray.rsrc = c.source;
        sray.rcoef = c.coef;
        bool blocked = false;
        // Something in between is followed through (opaque materials return
        // black, transparent ones transmit); with -oT every shadow ray is
        // followed so that it can be reported, as Radiance's SFOLLOW flag does.
        if (auto hit = core_.Intersect(sray.org, sray.dir, 0.0);
            hit && (hit->surface != src.surface || traceShadows_)) {
            sray.surface = hit->surface;
            sray.rot = hit->t;
            sray.rop = hit->point;
            sray.ron = hit->normal;
            sray.geometricNormal = hit->normal;
            sray.rod = -Dot(sray.dir, hit->normal);
            sray.rmt = sray.rxt = hit->t;
            ContinueShadowRay(sray);
            if (Bright(sray.rcol) <= kFtiny) {
                blocked = true;
            } else {
                c.value = sray.rcol * c.coef;
            }
        }
        if (!blocked) {
            ray.rcol += c.value;
            nhits++;
            src.nhits++;
        }
        hwt += double(src.nhits) / double(src.ntests);
    }
    hwt = hwt > kFtiny ? nhits / hwt : 0.5;
    for (; k < n; ++k) {
        const Contribution& c = contribs[k];
        const LightSource& src = sources_[c.source];
        double prob = std::min(1.0, hwt * double(src.nhits) / double(src.ntests));
        ray.rcol += c.value * prob;
    }
}

}  // namespace rt
