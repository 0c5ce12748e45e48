// SPDX-License-Identifier: MIT
//
// Radiance's direct calculation (source.c direct(), srcvalue(), raycont() for
// shadow rays); radiance-notes.md §3.3–3.4.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "shading/integrator.h"

namespace rt {
namespace {

/// Radiance tests at least this many shadow rays per shading point (MINSHADCNT)
/// before the -dt threshold may stop testing.
constexpr int kMinShadowTests = 2;

/// Stable sort by decreasing brightness, without allocating per call
/// (std::stable_sort allocates a buffer each time, and this runs at every
/// shading point). Most points have few contributions: one insertion sort.
template <typename Contribution>
void SortBrightestFirst(std::vector<Contribution>& c, std::vector<Contribution>& buffer) {
    const auto brighter = [](const Contribution& a, const Contribution& b) {
        return a.bright > b.bright;
    };
    // Insertion sort on runs of kRun, then stable bottom-up merges through
    // `buffer` (kept by the caller, so no allocation once it has grown).
    constexpr size_t kRun = 16;
    const size_t n = c.size();
    for (size_t start = 0; start < n; start += kRun) {
        const size_t end = std::min(n, start + kRun);
        for (size_t i = start + 1; i < end; ++i) {
            if (!brighter(c[i], c[i - 1])) continue;
            const Contribution moving = c[i];
            size_t j = i;
            for (; j > start && brighter(moving, c[j - 1]); --j) c[j] = c[j - 1];
            c[j] = moving;
        }
    }
    if (n <= kRun) return;
    buffer.resize(n);
    for (size_t width = kRun; width < n; width *= 2) {
        for (size_t lo = 0; lo < n; lo += 2 * width) {
            const size_t mid = std::min(n, lo + width), hi = std::min(n, lo + 2 * width);
            // Stable: on ties the left run's element comes first.
            std::merge(c.begin() + static_cast<long>(lo), c.begin() + static_cast<long>(mid),
                       c.begin() + static_cast<long>(mid), c.begin() + static_cast<long>(hi),
                       buffer.begin() + static_cast<long>(lo), brighter);
        }
        c.swap(buffer);
    }
}

}  // namespace

Rgb Integrator::SourceValue(TracedRay& sray, int source, double distance) {
    const LightSource& src = sources_[source];
    const Surface& surface = scene_.surfaces[src.surface];
    if (src.shape == LightSource::Shape::Distant) {
        // Samples of a distant source lie inside its cone by construction.
        sray.SetDistantHit(src.surface);
    } else if (src.parallelogram) {
        // The sample point lies on the source by construction: no need to
        // intersect it again.
        sray.surface = src.surface;
        sray.rot = distance;
        sray.rop = sray.org + sray.dir * distance;
        sray.ron = src.normal;
        sray.geometricNormal = src.normal;
        sray.rod = -Dot(sray.dir, src.normal);
    } else {
        auto hit = core_.IntersectSurface(src.surface, sray.org, sray.dir);
        LightSource& aimed = sources_[source];
        if (!hit) {
            // The sample missed the source (a partition of a non-parallelogram
            // polygon reaching past its edge, or rounding at grazing angles).
            if (aimed.aimSuccess >= 0) {
                aimed.aimSuccess -= LightSource::kAimRequired;
                if (aimed.aimSuccess < 0 && warn_) {
                    warn_("aiming failure for light source \"" + surface.name + "\"");
                }
            }
            return Rgb();
        }
        if (aimed.aimSuccess < 0) {
            aimed.aimSuccess = 1;  // warn again at the next failure
        } else if (aimed.aimSuccess < LightSource::kAimCredit) {
            ++aimed.aimSuccess;
        }
        sray.SetHit(*hit, scene_.PatternSpace(hit->instance));
    }
    sray.rcol = Rgb();
    if (!ApplyModifiers(sray, surface.patterns)) {
        ShadeMaterial(sray, scene_.materials[surface.material]);
    }
    return sray.rcol;
}

void Integrator::ContinueShadowRay(TracedRay& sray) {
    sray.rcol = Rgb();
    Shade(sray);
    Report(sray);
}

void Integrator::EnableTiming(bool on) {
    timing_ = on;
    if (!on) return;
    // The fastest of a few back-to-back reads: the clock's own cost.
    double fastest = 1.0;
    for (int i = 0; i < 64; ++i) {
        const auto a = std::chrono::steady_clock::now();
        const auto b = std::chrono::steady_clock::now();
        fastest = std::min(fastest, std::chrono::duration<double>(b - a).count());
    }
    clockReadSeconds_ = fastest;
}

void Integrator::Direct(TracedRay& ray, FunctionRef<Rgb(const Vec3&, double)> coef) {
    if (sources_.empty()) return;
    if (!timing_) {
        DirectUntimed(ray, coef);
        return;
    }
    // Reading the clock twice around each of a run's millions of calls would
    // slow the run measurably (README, "Options", -t), so every
    // kDirectTimingStride-th call is timed and stands for the others.
    timing_ = false;  // calls nested in this one are part of it
    if (++directCalls_ % kDirectTimingStride == 0) {
        const auto start = std::chrono::steady_clock::now();
        DirectUntimed(ray, coef);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        stats_.secondsDirect += kDirectTimingStride * std::max(0.0, seconds - clockReadSeconds_);
    } else {
        DirectUntimed(ray, coef);
    }
    timing_ = true;
}

void Integrator::DirectUntimed(TracedRay& ray, FunctionRef<Rgb(const Vec3&, double)> coef) {
    // Direct() is not re-entered while it runs, but keep one scratch set per
    // depth so that a future material that shades inside a shadow path
    // cannot clobber a caller's buffers.
    if (directScratch_.size() <= static_cast<size_t>(directDepth_)) {
        directScratch_.resize(directDepth_ + 1);
    }
    DirectScratch& scratch = directScratch_[directDepth_];
    ++directDepth_;
    struct DepthGuard {
        int& depth;
        ~DepthGuard() { --depth; }
    } guard{directDepth_};

    // Radiance's deterministic partition centres (-dj 0), also for rays of
    // the indirect calculation: jittering them there converges to the exact
    // integral, which differs from Radiance's own converged answers in
    // penumbrae (README, "Differences"); lazyrad's contract is Radiance's
    // answer.
    CollectSourceSamples(sources_, ray.rop, ray.sourceWeight, shading_.direct, rng_,
                         scratch.samples, scratch.partitions);
    if (scratch.samples.empty()) return;

    auto& contribs = scratch.contributions;
    contribs.clear();
    for (const SourceSample& s : scratch.samples) {
        DirectContribution c;
        c.source = s.source;
        c.dir = s.dir;
        c.distance = s.distance;
        c.coef = coef(s.dir, s.omega);
        if (Bright(c.coef) <= 0.0) continue;
        const LightSource& src = sources_[s.source];
        if ((src.shape == LightSource::Shape::Distant || src.parallelogram) && !src.patterned) {
            // The sample lands on the source: its radiance is the material's
            // colour from the front (spot cones and proximity were checked
            // when sampling), black from behind.
            const bool front = src.shape == LightSource::Shape::Distant ||
                               Dot(s.dir, src.normal) < 0.0;
            const Rgb& color = std::get<LightParams>(scene_.materials[src.material].params).color;
            c.value = front ? color * c.coef : Rgb();
        } else {
            TracedRay sray;
            StartChild(sray, ray, kShadowRay, nullptr);
            sray.dir = s.dir;
            sray.rsrc = s.source;
            c.value = SourceValue(sray, s.source, s.distance) * c.coef;
            // The shadow ray must stop where it enters the source's surface,
            // not at the sample point: a sphere's or cylinder's sample points
            // lie inside it, behind its own surface, which an any-hit query
            // would count as the source blocking itself.
            c.distance = sray.rot;
        }
        c.bright = Bright(c.value);
        if (c.bright > 0.0) contribs.push_back(c);
    }
    if (contribs.empty()) return;
    SortBrightestFirst(contribs, scratch.sortBuffer);
    const int n = static_cast<int>(contribs.size());
    // Tail sums: tail[k] = Σ_{m >= k} bright_m.
    auto& tail = scratch.tail;
    tail.assign(n + 1, 0.0);
    for (int k = n - 1; k >= 0; --k) tail[k] = tail[k + 1] + contribs[k].bright;

    const int nshadcheck =
        n < static_cast<int>(shadowCheckCounts_.size())
            ? shadowCheckCounts_[n]
            : static_cast<int>(std::pow(double(n), shading_.direct.certainty) + 0.5);
    const double threshold = shading_.direct.threshold / ray.rweight;
    int nhits = 0;
    double hwt = 0.0;
    int k = 0;
    for (; k < n; ++k) {
        // Stop once the untested remainder cannot matter (-dt), but only after
        // the minimum number of tests.
        double remaining = k + nshadcheck >= n ? tail[k] : tail[k] - tail[k + nshadcheck];
        if (k >= kMinShadowTests && remaining < threshold * Bright(ray.rcol)) break;
        DirectContribution& c = contribs[k];
        LightSource& src = sources_[c.source];
        src.ntests++;
        ++stats_.shadowRays;
        if (opaqueShadows_ && !traceShadows_) {
            // Nothing in this scene transmits light, so any hit before the
            // source blocks it: an any-hit query is enough.
            // Stop just short of the sample point on the source itself.
            const double reach = src.shape == LightSource::Shape::Distant
                                     ? 0.0
                                     : c.distance - std::max(scene_.distanceTolerance, 1e-7 * c.distance);
            if (!core_.Occluded(ray.rop, c.dir, reach)) {
                ray.rcol += c.value;
                nhits++;
                src.nhits++;
            }
            hwt += double(src.nhits) / double(src.ntests);
            continue;
        }
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
            hit && (hit->instance >= 0 || hit->surface != src.surface || traceShadows_)) {
            sray.SetHit(*hit, scene_.PatternSpace(hit->instance));
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
        const DirectContribution& c = contribs[k];
        const LightSource& src = sources_[c.source];
        double prob = std::min(1.0, hwt * double(src.nhits) / double(src.ntests));
        ray.rcol += c.value * prob;
    }
}

}  // namespace rt
