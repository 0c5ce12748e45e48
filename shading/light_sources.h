// SPDX-License-Identifier: MIT
//
// Light sources and their sampling, after Radiance's source.c (marksources),
// srcsupp.c (the per-shape set-up) and srcsamp.c (partitioning with -ds and
// jitter with -dj); radiance-notes.md §3.1–3.2.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "core/diagnostics.h"
#include "core/random.h"
#include "core/vecmath.h"
#include "scene/scene.h"
#include "shading/shading_options.h"

namespace rt {

struct LightSource {
    enum class Shape { Flat, Sphere, Cylinder, Distant };

    int surface = -1;          // index into Scene::surfaces
    int material = -1;         // index into Scene::materials (light, illum, glow, spotlight)
    Shape shape = Shape::Flat;
    bool circular = false;     // ring, sphere, distant (Radiance's SCIR)
    Vec3 location;             // centre; for a distant source the unit direction to it
    Vec3 normal;               // flat sources: surface normal (sources emit along it)
    Vec3 size[3];              // half-size vectors U, V, W spanning the source
    double area = 0;           // area (flat, sphere: projected disc, cylinder: 2rL)
                               // or solid angle (distant)
    double radius = 0;         // largest distance from the centre (approximate for distant)
    bool skip = false;         // never sampled directly (a distant glow = sky)
    bool proximity = false;    // glow with radius: a source only within proximityRadius
    double proximityRadius = 0;
    bool spot = false;
    double spotSolidAngle = 0; // 2π(1 - cos(angle/2))
    Vec3 spotAim;              // unit
    double spotFocal = 0;      // focal length behind the source centre
    bool parallelogram = false;  // flat quad whose samples always land on it
    bool patterned = false;      // its radiance comes through patterns, per sample ray

    // Virtual sources (-dr, Radiance's SVIRTUAL): the image of source `next`
    // in the planar mirror or prism `relay`. Its geometry above is the
    // geometry of `next` mirrored (or, by a prism, sheared and maybe
    // mirrored); its light reaches a point only along rays through the relay
    // surface, which reflects or redirects them toward `next`. For a local image
    // those rays leave it within the cone `relayCone` (sr) around `relayAim`
    // (unit, from the image toward the relay's bounding disc); for a distant
    // image they pass within √relayRadius2 of `relayCentre`.
    int relay = -1;              // surface index of the mirror; -1 for a real source
    int relayProjection = 0;     // which of a prism2's two redirections (Radiance's pn)
    int next = -1;               // the source this one images (Radiance's sa.sv.sn)
    Vec3 relayAim;
    double relayCone = 0;
    Vec3 relayCentre;
    double relayRadius2 = 0;
    bool IsVirtual() const { return relay >= 0; }
};

/// One sample direction toward a light source (one per source partition).
struct SourceSample {
    int source = -1;
    Vec3 dir;               // unit, from the shading point
    double distance = 0;    // to the sample point on the source (kFhuge for distant)
    double omega = 0;       // solid angle this sample stands for (sr)
    /// The source was not divided (one partition): Radiance checks only such
    /// samples against its obstructor cache.
    bool whole = false;
    /// The only sample its source gave here: Radiance records the blocker of
    /// only such a sample's shadow ray in the cache.
    bool alone = false;
};

/// Radiance's marksources(): every surface whose material emits and whose
/// shape can be a source. Throws rt::Error for shapes that cannot carry a
/// light material ("illegal material") and Radiance's other fatal cases;
/// warns "no light sources found" when none is usable. `randomFrames`
/// (-u+) orients the sampling frames of non-quad flat sources randomly.
std::vector<LightSource> FindLightSources(const Scene& scene, const WarningSink& warn,
                                          bool randomFrames, Rng& rng);

/// Radiance's vsmaterial(): the material `surface` (which has one) relays
/// light sources with, its own or, for an illum, its alternate.
const Material& RelayMaterial(const Scene& scene, const Surface& surface);

/// For a prism's images (Radiance's dir_proj()): the new direction (render
/// space, not unit) that prism surface `surface`'s redirection `n` gives the
/// ray from `org` along unit `dir`, if the ray meets the surface and the
/// coefficient there is above FTINY. shading/ answers it with the ray core
/// and the prism's function.
using RedirectionProbe =
    std::function<std::optional<Vec3>(int surface, int n, const Vec3& org, const Vec3& dir)>;

/// Radiance's markvirtuals() for -dr `relays` > 0: appends the images of
/// `sources` in every top-level planar mirror and prism (polygon or ring):
/// a mirror's reflections, a prism's redirections as `probe` finds them
/// toward the centre of its disc, one image per redirection; and their
/// images in turn up to `relays` reflections deep, depth first from the last
/// source as Radiance orders them. A mirror never images the source it
/// relays itself; a source behind a mirror's plane, a relay disc behind a
/// flat source's image, or outside a glow's reach makes no image. Warns
/// "secondary sources not supported" for mirrors of any other shape. Makes at
/// most 10 000 images: when -dr would make more, it goes as many reflections
/// deep as fit (at most 100), with a warning. A spotlight's image is a
/// spotlight aimed at the mirrored direction. Radiance's visibility pretest
/// (-dp) is not needed: an image whose relay cannot see its source
/// contributes nothing, as there.
void AddVirtualSources(const Scene& scene, int relays, const WarningSink& warn,
                       const RedirectionProbe& probe, std::vector<LightSource>& sources);

/// Radiance's nextssamp() + srcray() over all sources: the samples seen from
/// `point` by a ray of weight `rayWeight`, in source order then partition order.
/// `out` is cleared first; both vectors are the caller's scratch space, kept
/// between calls so that shading allocates nothing per point.
struct SourcePartition {
    int center[3];
    int size[3];
};
void CollectSourceSamples(const std::vector<LightSource>& sources, const Vec3& point,
                          double rayWeight, const DirectOptions& options, Rng& rng,
                          std::vector<SourceSample>& out, std::vector<SourcePartition>& scratch);

/// One sample of the whole of source `source` (Radiance's nopart() then
/// nextssamp(), as srcscatter() samples the sources mist scatters): its
/// centre, or with -dj a point jittered over it. False when it gives none.
bool SampleWholeSource(const std::vector<LightSource>& sources, int source, const Vec3& point,
                       const DirectOptions& options, Rng& rng, SourceSample& sample);

}  // namespace rt
