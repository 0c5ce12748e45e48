// SPDX-License-Identifier: MIT
//
// Radiance's direct calculation (source.c direct(), srcvalue(), raycont() for
// shadow rays); radiance-notes.md §3.3–3.4.
#include "shading/direct.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "shading/ray_tree.h"

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

/// What a medium between the point and each source (the whole way to a
/// distant one) lets through of its light (srcvalue()'s rayparticipate()):
/// scales the contributions, and drops those it extinguishes.
void AttenuateByMedium(const Medium& medium, const std::vector<LightSource>& sources,
                       std::vector<DirectContribution>& contribs) {
    for (DirectContribution& c : contribs) {
        const LightSource& src = sources[static_cast<std::size_t>(c.source)];
        const bool distant = src.shape == LightSource::Shape::Distant && !src.IsVirtual();
        c.value *= RayTree::ShadowTransmittance(medium, distant ? kFhuge : c.distance);
        c.bright = Bright(c.value);
    }
    contribs.erase(std::remove_if(contribs.begin(), contribs.end(),
                                  [](const DirectContribution& c) { return c.bright <= 0.0; }),
                   contribs.end());
}

}  // namespace

void DirectLight::CountAim(ThreadState& ts, int source, bool hit) const {
    SourceTally& aimed = ts.sourceTallies[source];
    if (hit) {
        if (aimed.aimSuccess >= 0) ++aimed.aimSuccess;
        return;
    }
    // The sample missed the source (a partition of a non-parallelogram
    // polygon reaching past its edge, a ray into a cylinder's open end, or
    // rounding at grazing angles). Radiance warns once, when the misses
    // have used up the credit (srcvalue()).
    if (aimed.aimSuccess < 0) return;
    aimed.aimSuccess -= SourceTally::kAimRequired;
    if (aimed.aimSuccess < 0) {
        const Surface& surface = s_.scene.surfaces[s_.sources[source].surface];
        ts.Warn("aiming failure for light source \"" + surface.name + "\"");
    }
}

Rgb DirectLight::RelayValue(ThreadState& ts, TracedRay& sray, int source) const {
    // The ray must meet the relay itself; the relay (ShadeMirror, ShadePrism)
    // reflects or redirects it toward the source it images and follows it
    // there, past whatever transmits and stopped by anything opaque.
    auto hit = s_.core.IntersectSurface(s_.sources[source].relay, sray.org, sray.dir);
    if (!hit) return Rgb();
    sray.SetHit(*hit, s_.scene.PatternSpace(hit->instance));
    sray.rot = hit->t;
    sray.rcol = Rgb();
    tree_.Shade(ts, sray);
    return sray.rcol;
}

std::vector<int>& DirectLight::Obstructors(ThreadState& ts, int source) const {
    std::vector<int>& table = ts.obstructors[static_cast<std::size_t>(source)];
    if (table.empty()) {
        const ObstructorLayout& layout = s_.obstructorLayouts[static_cast<std::size_t>(source)];
        table.assign(static_cast<std::size_t>(layout.CellCount()), kUnfilled);
    }
    return table;
}

int DirectLight::CachedSurface(std::vector<int>& table, int source, int cell) const {
    int& entry = table[static_cast<std::size_t>(cell)];
    if (entry != kUnfilled) return entry;
    // castshadow(): the first surface that qualifies along the cell's fill
    // ray, as if it had blocked a ray aimed back at the source. Radiance 5.4
    // starts that pretended ray one unit from the hit on the source's side
    // (it subtracts the unnegated direction), so for a distant source a
    // surface within one unit of the plane the rays start from falls outside
    // every cell and is not recorded; lazyrad does the same, to test the same
    // samples. Surfaces that do not qualify are stepped past (a bounded
    // number, so that no scene can make the fill loop).
    entry = -1;
    const ObstructorLayout& layout = s_.obstructorLayouts[static_cast<std::size_t>(source)];
    const ObstructorFillRay fill =
        MakeObstructorFillRay(layout, s_.sources[static_cast<std::size_t>(source)], cell);
    constexpr int kMaxSteps = 1024;
    Vec3 org = fill.org;
    for (int n = 0; n < kMaxSteps; ++n) {
        const auto hit = s_.core.Intersect(org, fill.dir, 0.0);
        if (!hit) break;
        if (IsRecordable(source, hit->instance, hit->surface)) {
            // The pretended ray lands in this cell or, for a distant source,
            // in none (Obstructors.EachCellHasAFillRayOfItsOwn).
            if (layout.Cell(hit->point - fill.dir, -fill.dir) == cell) entry = hit->surface;
            break;
        }
        org = hit->point + fill.dir * s_.scene.distanceTolerance;
    }
    return entry;
}

bool DirectLight::CachedBlocked(ThreadState& ts, int source, const Vec3& org, const Vec3& dir,
                                double distance) const {
    if (!HasObstructors(source)) return false;
    const ObstructorLayout& layout = s_.obstructorLayouts[static_cast<std::size_t>(source)];
    const int cell = layout.Cell(org, dir);
    if (cell < 0) return false;
    const int blocker = CachedSurface(Obstructors(ts, source), source, cell);
    if (blocker < 0) return false;
    // Either side: the materials recorded stop shadow rays from behind too,
    // -bv- or not (normal.c's "easy shadow test" comes first).
    const auto hit = s_.core.IntersectSurfaceSide(blocker, org, dir);
    if (!hit) return false;
    // A blocker beyond a local source does not shade it (Radiance checks
    // that the source is not in front).
    return layout.kind == ObstructorLayout::Kind::Distant || hit->t < distance;
}

bool DirectLight::IsRecordable(int source, int instance, int surface) const {
    if (instance >= 0 || surface < 0) return false;  // inside an instance or mesh, or nothing
    if (surface == s_.sources[static_cast<std::size_t>(source)].surface) return false;
    return s_.reliableBlockers[static_cast<std::size_t>(surface)] != 0;
}

void DirectLight::RecordBlocker(ThreadState& ts, int source, const Vec3& org, const Vec3& dir,
                                int instance, int surface) const {
    if (!IsRecordable(source, instance, surface)) return;
    const int cell = s_.obstructorLayouts[static_cast<std::size_t>(source)].Cell(org, dir);
    // Whether or not the cell was filled, the blocker replaces what it held.
    if (cell >= 0) Obstructors(ts, source)[static_cast<std::size_t>(cell)] = surface;
}

void DirectLight::RecordShadowBlocker(ThreadState& ts, int source, const Vec3& org,
                                      const Vec3& dir, double reach, const Vec3* leaving) const {
    if (!HasObstructors(source)) return;
    if (const auto hit = s_.core.Intersect(org, dir, reach, leaving)) {
        RecordBlocker(ts, source, org, dir, hit->instance, hit->surface);
    }
}

void DirectLight::RecordBlockerOf(ThreadState& ts, const TracedRay& sray) const {
    if (!HasObstructors(sray.rsrc)) return;
    RecordBlocker(ts, sray.rsrc, sray.org, sray.dir, sray.instance, sray.surface);
}

Rgb DirectLight::SourceValue(ThreadState& ts, TracedRay& sray, int source,
                             double distance) const {
    const LightSource& src = s_.sources[source];
    const Surface& surface = s_.scene.surfaces[src.surface];
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
        auto hit = s_.core.IntersectSurface(src.surface, sray.org, sray.dir);
        CountAim(ts, source, hit.has_value());
        if (!hit) return Rgb();
        sray.SetHit(*hit, s_.scene.PatternSpace(hit->instance));
    }
    sray.rcol = Rgb();
    if (!tree_.ApplyModifiers(ts, sray, surface.patterns)) {
        tree_.ShadeMaterial(ts, sray, s_.scene.materials[surface.material]);
    }
    return sray.rcol;
}

void DirectLight::Add(ThreadState& ts, TracedRay& ray,
                      FunctionRef<Rgb(const Vec3&, double)> coef) const {
    if (s_.sources.empty()) return;
    if (!ts.timing) {
        AddUntimed(ts, ray, coef);
        return;
    }
    // Reading the clock twice around each of a run's millions of calls would
    // slow the run measurably (README, "Options", -t), so every
    // kDirectTimingStride-th call is timed and stands for the others.
    ts.timing = false;  // calls nested in this one are part of it
    if (++ts.directCalls % ThreadState::kDirectTimingStride == 0) {
        const auto start = std::chrono::steady_clock::now();
        AddUntimed(ts, ray, coef);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ts.stats.secondsDirect +=
            ThreadState::kDirectTimingStride * std::max(0.0, seconds - ts.clockReadSeconds);
    } else {
        AddUntimed(ts, ray, coef);
    }
    ts.timing = true;
}

void DirectLight::AddUntimed(ThreadState& ts, TracedRay& ray,
                             FunctionRef<Rgb(const Vec3&, double)> coef) const {
    // Direct() is not re-entered while it runs, but keep one scratch set per
    // depth so that a future material that shades inside a shadow path
    // cannot clobber a caller's buffers.
    if (ts.directScratch.size() <= static_cast<size_t>(ts.directDepth)) {
        ts.directScratch.resize(ts.directDepth + 1);
    }
    DirectScratch& scratch = ts.directScratch[ts.directDepth];
    ++ts.directDepth;
    struct DepthGuard {
        int& depth;
        ~DepthGuard() { --depth; }
    } guard{ts.directDepth};

    // Radiance's deterministic partition centres (-dj 0), also for rays of
    // the indirect calculation: jittering them there converges to the exact
    // integral, which differs from Radiance's own converged answers in
    // penumbrae (README, "Differences"); lazyrad's contract is Radiance's
    // answer.
    // Sources are divided for the shadow rays' weight, which the shading
    // ray's path through a medium lowers (Radiance's srcray() partitions for
    // the shadow ray rayorigin() made); a path that extinguished it has none.
    const double partitionWeight = ray.sourceWeight * RayTree::MediumImportance(ray);
    if (partitionWeight <= 0) return;
    CollectSourceSamples(s_.sources, ray.rop, partitionWeight, s_.shading.direct, ts.rng,
                         scratch.samples, scratch.partitions);
    if (scratch.samples.empty()) return;

    auto& contribs = scratch.contributions;
    contribs.clear();
    for (const SourceSample& s : scratch.samples) {
        const Rgb coefficient = coef(s.dir, s.omega);
        if (Bright(coefficient) <= 0.0) continue;
        // Radiance drops a whole source's sample that its obstructor cache
        // finds blocked before anything else: no shadow ray, no statistics.
        if (s.whole && CachedBlocked(ts, s.source, ray.rop, s.dir, s.distance)) {
            ++ts.stats.samplesObstructed;
            continue;
        }
        const LightSource& src = s_.sources[s.source];
        const Rgb& color = std::get<LightParams>(s_.scene.materials[src.material].params).color;
        Rgb value;
        double distance = s.distance;
        if (src.IsVirtual()) {
            // An image in a mirror or prism: its light comes through the relay (srcvalue()).
            TracedRay sray;
            tree_.StartChild(ts, sray, ray, kShadowRay, nullptr);
            sray.dir = s.dir;
            sray.rsrc = s.source;
            value = RelayValue(ts, sray, s.source) * coefficient;
            // The shadow test below asks only about the way to the relay:
            // the way on from it is in the value already (Radiance's
            // virtual sources without SFOLLOW, which its pretest clears
            // when nothing obstructs the relay's view of its source).
            distance = sray.rot;
        } else if ((src.shape == LightSource::Shape::Distant || src.parallelogram) &&
                   !src.patterned) {
            // The sample lands on the source: its radiance is the material's
            // colour from the front (spot cones and proximity were checked
            // when sampling), black from behind.
            const bool front = src.shape == LightSource::Shape::Distant ||
                               Dot(s.dir, src.normal) < 0.0;
            if (!front) continue;
            value = color * coefficient;
        } else if (!src.patterned) {
            // SourceValue() without a ray tree: the sample ray must meet the
            // source, and the material's colour shows from the front only
            // (what its light material gives a shadow ray aimed at it).
            const auto hit = s_.core.IntersectSurfaceSide(src.surface, ray.rop, s.dir);
            CountAim(ts, s.source, hit.has_value());
            if (!hit || hit->back) continue;
            // The shadow ray must stop where it enters the source's surface,
            // not at the sample point: a sphere's or cylinder's sample points
            // lie inside it, behind its own surface, which an any-hit query
            // would count as the source blocking itself.
            distance = hit->t;
            value = color * coefficient;
        } else {
            TracedRay sray;
            tree_.StartChild(ts, sray, ray, kShadowRay, nullptr);
            sray.dir = s.dir;
            sray.rsrc = s.source;
            value = SourceValue(ts, sray, s.source, s.distance) * coefficient;
            distance = sray.rot;  // where it enters the source, as above
        }
        const double bright = Bright(value);
        // Built in place: a copy of a DirectContribution assembled on the
        // stack stalls on store forwarding.
        if (bright > 0.0) {
            contribs.emplace_back(s.source, s.dir, distance, coefficient, value, bright, s.alone);
        }
    }
    if (ray.medium) AttenuateByMedium(*ray.medium, s_.sources, contribs);
    if (contribs.empty()) return;
    SortBrightestFirst(contribs, scratch.sortBuffer);
    const int n = static_cast<int>(contribs.size());
    // Tail sums: tail[k] = Σ_{m >= k} bright_m.
    auto& tail = scratch.tail;
    tail.resize(n + 1);  // every entry is written below: no need to clear
    tail[n] = 0.0;
    for (int k = n - 1; k >= 0; --k) tail[k] = tail[k + 1] + contribs[k].bright;

    const int nshadcheck =
        n < static_cast<int>(s_.shadowCheckCounts.size())
            ? s_.shadowCheckCounts[n]
            : static_cast<int>(std::pow(double(n), s_.shading.direct.certainty) + 0.5);
    const double threshold = s_.shading.direct.threshold / ray.rweight;
    int nhits = 0;
    double hwt = 0.0;
    int k = 0;
    for (; k < n; ++k) {
        // Stop once the untested remainder cannot matter (-dt), but only after
        // the minimum number of tests.
        double remaining = k + nshadcheck >= n ? tail[k] : tail[k] - tail[k + nshadcheck];
        if (k >= kMinShadowTests && remaining < threshold * Bright(ray.rcol)) break;
        DirectContribution& c = contribs[k];
        const LightSource& src = s_.sources[c.source];
        SourceTally& tally = ts.sourceTallies[c.source];
        tally.ntests++;
        ++ts.stats.shadowRays;
        // With trace output every shadow ray takes the path below, which
        // finds what blocks it and reports it as Radiance does.
        if (s_.queryShadows && !ts.trace) {
            // Stop just short of the sample point on the source itself (for
            // an image: of the relay).
            const double reach =
                src.shape == LightSource::Shape::Distant && !src.IsVirtual()
                    ? 0.0
                    : c.distance - std::max(s_.scene.distanceTolerance, 1e-7 * c.distance);
            // Transmitting surfaces are asked about first: a shadow ray that
            // meets one is followed (below) exactly as without the queries,
            // random numbers drawn by Russian roulette included. With none in
            // the way, any hit before the source blocks it. The source itself
            // is not in the way (the ray stops short of its first hit on it,
            // or of its plane), so its test is skipped.
            if (!s_.transmitting ||
                !s_.core.Occluded(ray.rop, c.dir, reach, Occluders::Transmitting, src.surface,
                                  &ray.ron)) {
                if (!s_.core.Occluded(ray.rop, c.dir, reach, Occluders::Opaque, src.surface,
                                      &ray.ron)) {
                    ray.rcol += c.value;
                    nhits++;
                    tally.nhits++;
                } else if (c.alone) {
                    RecordShadowBlocker(ts, c.source, ray.rop, c.dir, reach, &ray.ron);
                }
                hwt += double(tally.nhits) / double(tally.ntests);
                continue;
            }
        }
        TracedRay sray;
        tree_.StartChild(ts, sray, ray, kShadowRay, nullptr);
        sray.dir = c.dir;
        sray.rsrc = c.source;
        sray.rcoef = c.coef;
        bool blocked = false;
        // Something in between is followed through (opaque materials return
        // black, transparent ones transmit); with -oT every shadow ray is
        // followed so that it can be reported, as Radiance's SFOLLOW flag does.
        if (auto hit = s_.core.Intersect(sray.org, sray.dir, 0.0, sray.Leaving());
            hit && (src.IsVirtual() || hit->instance >= 0 || hit->surface != src.surface ||
                    ts.traceShadows)) {
            sray.SetHit(*hit, s_.scene.PatternSpace(hit->instance));
            // Shaded past the surface in between (Radiance's raycont()).
            // Reported and tested before the medium between the point and
            // the surface acts on it, in Radiance's order.
            sray.rcol = Rgb();
            tree_.Shade(ts, sray);
            tree_.ReportFollowedShadow(ts, sray);
            if (Bright(sray.rcol) <= kFtiny) {
                blocked = true;
                if (c.alone) RecordBlockerOf(ts, sray);
            } else {
                tree_.Participate(ts, sray);
                c.value = sray.rcol * c.coef;
            }
        } else if (ts.traceShadows && !hit && src.shape == LightSource::Shape::Distant &&
                   !src.IsVirtual()) {
            tree_.ReportShadowAtDistantSource(ts, sray);
        }
        if (!blocked) {
            ray.rcol += c.value;
            nhits++;
            tally.nhits++;
        }
        hwt += double(tally.nhits) / double(tally.ntests);
    }
    hwt = hwt > kFtiny ? nhits / hwt : 0.5;
    for (; k < n; ++k) {
        const DirectContribution& c = contribs[k];
        const SourceTally& tally = ts.sourceTallies[c.source];
        double prob = std::min(1.0, hwt * double(tally.nhits) / double(tally.ntests));
        ray.rcol += c.value * prob;
    }
}

}  // namespace rt
