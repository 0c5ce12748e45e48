// SPDX-License-Identifier: MIT
//
// Light sources and their sampling, after Radiance's source.c (marksources),
// srcsupp.c (the per-shape set-up) and srcsamp.c (partitioning with -ds and
// jitter with -dj); radiance-notes.md §3.1–3.2.
#pragma once

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
};

/// One sample direction toward a light source (one per source partition).
struct SourceSample {
    int source = -1;
    Vec3 dir;               // unit, from the shading point
    double distance = 0;    // to the sample point on the source (kFhuge for distant)
    double omega = 0;       // solid angle this sample stands for (sr)
};

/// Radiance's marksources(): every surface whose material emits and whose
/// shape can be a source. Throws rt::Error for shapes that cannot carry a
/// light material ("illegal material") and Radiance's other fatal cases;
/// warns "no light sources found" when none is usable. `randomFrames`
/// (-u+) orients the sampling frames of non-quad flat sources randomly.
std::vector<LightSource> FindLightSources(const Scene& scene, const WarningSink& warn,
                                          bool randomFrames, Rng& rng);

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

}  // namespace rt
