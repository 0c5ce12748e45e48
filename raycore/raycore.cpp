// SPDX-License-Identifier: MIT
//
// Embree 3 back end of RayCore. Embree traverses in single precision; the
// exact answer comes from raycore/shapes.h in double. The two meet in
// callbacks that receive a Query (our RTCIntersectContext extension) carrying
// the caller's double ray and the best hit so far:
//   - polygons, as an Embree quad mesh (pairs of their triangles sharing an
//     edge; a lone triangle repeats its last vertex): an intersection/
//     occlusion filter recomputes t on the polygon's plane and accepts or
//     rejects the candidate;
//   - spheres, cones, rings: user geometry whose intersect callback runs the
//     exact shape test directly.
// Candidates with exact t <= tolerance (Scene::distanceTolerance, Radiance's
// FTINY for scenes of unit size and up) or t >= tmax are rejected, so traversal
// simply continues past the surface a ray starts on, except surfaces that cross
// the one it leaves (RayCore::Intersect's `leaving`; ExactRay::tcross).
//
// Embree's contracts relied on here:
//   - The context pointer given to rtcIntersect1/rtcOccluded1 is handed back
//     unchanged to filters and user callbacks (so the Query can extend it).
//   - A filter sees ray.tfar set to the candidate's float distance; if it
//     keeps the hit it may lower or raise tfar, and Embree culls later
//     candidates against that value; if it rejects, tfar is restored.
//   - Geometry must be committed before the scene, the scene before tracing;
//     after rtcCommitScene the scene is read-only and safe to trace from any
//     number of threads.
//   - rtcAttachGeometry takes its own reference: we release ours at once, and
//     the scene keeps the geometry alive until rtcReleaseScene.
#include "raycore/raycore.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <mutex>
#include <optional>
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

#include "core/check.h"
#include "core/conventions.h"
#include "core/huge_pages.h"
#include "raycore/hull.h"
#include "raycore/shapes.h"
#include "raycore/source_plane.h"
#include "scene/mesh_file.h"

namespace rt {

std::ostream& operator<<(std::ostream& os, const Hit& hit) {
    return os << "Hit{t=" << hit.t << ", point=" << hit.point << ", normal=" << hit.normal
              << ", surface=" << hit.surface << "}";
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// TransmitsShadowRays for a material: `depth` counts the alternates followed,
/// and a chain too long to follow is taken to transmit (the safe answer).
bool MaterialTransmits(const Scene& scene, int material, int depth) {
    if (material < 0) return false;  // black, as a void surface
    if (depth > 8) return true;
    const Material& m = scene.materials[static_cast<size_t>(material)];
    switch (m.type) {
        case MaterialType::Trans: {
            // Only a trans without roughness passes shadow rays: its straight
            // specular transmission (normal.c; the rough lobe is part of the
            // trans surface's own direct light).
            const auto& p = std::get<NormalParams>(m.params);
            return p.roughness * p.roughness <= kFtiny && p.transmissivity != 0 &&
                   p.transmittedSpecular != 0;
        }
        case MaterialType::Glass:
        case MaterialType::Dielectric:
        case MaterialType::Interface:
        case MaterialType::Illum:
        case MaterialType::BRTDFunc:  // its transmission expressions (m_brdf())
        case MaterialType::Antimatter:  // passed, the ray's clipped modifiers changed
        case MaterialType::Bsdf:        // a proxy passes them (its thickness may vary)
        case MaterialType::ABsdf:       // its straight-through part passes them
        case MaterialType::Mist:        // passed, the medium beyond changed
            return true;
        case MaterialType::Mirror:
            // A shadow ray meeting its front is shaded with the alternate.
            return MaterialTransmits(scene, m.alternate, depth + 1);
        case MaterialType::Plastic:
        case MaterialType::Metal:
        case MaterialType::Plastic2:
        case MaterialType::Metal2:
        case MaterialType::Trans2:  // m_aniso.c stops every shadow ray
        case MaterialType::Ashik2:
        case MaterialType::PlasFunc:
        case MaterialType::MetFunc:
        case MaterialType::TransFunc:  // so does m_brdf2()
        case MaterialType::PlasData:
        case MaterialType::MetData:
        case MaterialType::TransData:
        case MaterialType::Light:
        case MaterialType::Glow:
        case MaterialType::Spotlight:
        // A shadow ray meeting a prism is black unless it aims at the
        // prism's own image of a source, which shading/ follows from the
        // prism on (m_direct.c).
        case MaterialType::Prism1:
        case MaterialType::Prism2:
            return false;
    }
    return true;
}

/// Float error allowance of Embree's distances, relative to the size of the
/// coordinates involved (~84 float ulps: covers rounding of the origin, the
/// direction and the triangle test with room to spare).
constexpr double kFloatSlack = 1e-5;

/// A ray that leaves a surface (RayCore::Intersect's `leaving`) hits another
/// surface within the tolerance if that one meets it at an angle: normals
/// more than ~1e-3 rad apart (cos² below this), and farther than the
/// rounding of the scene's coordinates (kCoordinateUlps of them). A
/// coincident surface, or the ray's own surface found again by rounding,
/// stays discarded as Radiance discards it.
constexpr double kCoincidentCos2 = 1.0 - 1e-6;

/// What the coincidence rule needs to know about a surface's material.
struct Priority {
    int material = -1;         // -1: void
    bool transparent = false;  // istransp() of the material
};

/// Plane of the polygon a quad primitive came from, or of a mesh triangle
/// (exact t for the filter), in the coordinates of the Embree scene's surfaces.
struct PolygonPlane {
    Vec3 normal;
    double offset = 0;
    int surface = -1;
};

/// Geometry IDs in the scenes that hold instances: the scene's own kinds
/// first, then one instance geometry per Scene::instances entry.
constexpr unsigned kPolygonGeometry = 0, kSphereGeometry = 1, kConeGeometry = 2,
                   kRingGeometry = 3, kMeshGeometry = 4, kFirstInstanceGeometry = 5;

float RoundDown(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
}
float RoundUp(double x) {
    float f = static_cast<float>(x);
    if (static_cast<double>(f) < x) {
        // The next float up. Not std::nextafter: glibc's saves and restores
        // the floating-point environment, too slow here, as every query calls
        // this (docs/measured-choices.md). f is finite and below x.
        if (f == 0.0f) return std::numeric_limits<float>::denorm_min();
        auto bits = std::bit_cast<std::uint32_t>(f);
        bits += f > 0.0f ? 1 : -1;
        f = std::bit_cast<float>(bits);
    }
    return f;
}

/// True unless the segment from `org` to `end` = org + dir·tmax certainly
/// misses `box` (slab test; NaNs and rounding err toward "meets").
[[gnu::always_inline]] inline bool SegmentMeetsBox(const Vec3& org, const Vec3& end,
                                                   const Vec3& dir, double tmax,
                                                   const Bounds3& box) {
    // The segment's own box first: no divisions, and enough for most misses.
    if (std::min(org.x, end.x) > box.hi.x || std::max(org.x, end.x) < box.lo.x ||
        std::min(org.y, end.y) > box.hi.y || std::max(org.y, end.y) < box.lo.y ||
        std::min(org.z, end.z) > box.hi.z || std::max(org.z, end.z) < box.lo.z) {
        return false;
    }
    double t0 = 0, t1 = tmax;
    for (int axis = 0; axis < 3; ++axis) {
        // A zero component: the segment's box already lies within the slab.
        if (dir[axis] == 0) continue;
        const double inv = 1.0 / dir[axis];
        double a = (box.lo[axis] - org[axis]) * inv, b = (box.hi[axis] - org[axis]) * inv;
        if (a > b) std::swap(a, b);
        if (a > t0) t0 = a;
        if (b < t1) t1 = b;
        if (t0 > t1) return false;
    }
    return true;
}

/// First Embree error reported through the device callback. The callback may
/// run on Embree's build threads, hence the mutex.
struct EmbreeErrors {
    std::mutex mutex;
    RTCError code = RTC_ERROR_NONE;
    std::string message;

    static void Callback(void* userPtr, RTCError code, const char* str) {
        auto* self = static_cast<EmbreeErrors*>(userPtr);
        std::lock_guard lock(self->mutex);
        if (self->code != RTC_ERROR_NONE) return;
        self->code = code;
        self->message = str ? str : "";
    }
};

const char* ErrorName(RTCError code) {
    switch (code) {
        case RTC_ERROR_NONE:
            return "no error";
        case RTC_ERROR_UNKNOWN:
            return "unknown error";
        case RTC_ERROR_INVALID_ARGUMENT:
            return "invalid argument";
        case RTC_ERROR_INVALID_OPERATION:
            return "invalid operation";
        case RTC_ERROR_OUT_OF_MEMORY:
            return "out of memory";
        case RTC_ERROR_UNSUPPORTED_CPU:
            return "unsupported CPU";
        case RTC_ERROR_CANCELLED:
            return "cancelled";
    }
    return "unknown error";
}

[[noreturn]] void ThrowEmbreeError(RTCError code, const std::string& message, const char* call) {
    const auto kind = code == RTC_ERROR_OUT_OF_MEMORY ? Error::Kind::System : Error::Kind::Internal;
    std::string text = std::string("Embree ") + call + ": " + ErrorName(code);
    if (!message.empty()) text += " (" + message + ")";
    throw Error(kind, text);
}

/// The Embree quad (v0, v1, v2, v3) made of triangles a and b if they share an
/// edge; Embree splits a quad into (v0, v1, v3) and (v2, v3, v1), which are
/// then exactly a and b with their own orientation, so the union need not be
/// convex.
std::optional<std::array<int, 4>> JoinTriangles(const std::array<int, 3>& a,
                                                const std::array<int, 3>& b) {
    for (int k = 0; k < 3; ++k) {
        const int x = a[k], y = a[(k + 1) % 3], opposite = a[(k + 2) % 3];
        for (int m = 0; m < 3; ++m) {
            // b runs along the shared edge the other way: (other, y, x).
            if (b[m] == y && b[(m + 1) % 3] == x) return std::array{opposite, x, b[(m + 2) % 3], y};
        }
    }
    return std::nullopt;
}

/// A polygon's triangles as Embree quads: consecutive triangles sharing an
/// edge are paired (a quad test costs about as much as one triangle test, and
/// most polygons are quadrilaterals); a triangle left over repeats its last
/// vertex, Embree's way of putting a triangle in a quad mesh.
std::vector<std::array<int, 4>> PairTriangles(const std::vector<std::array<int, 3>>& triangles) {
    std::vector<std::array<int, 4>> quads;
    for (size_t i = 0; i < triangles.size(); ++i) {
        const auto& a = triangles[i];
        if (i + 1 < triangles.size()) {
            if (auto quad = JoinTriangles(a, triangles[i + 1])) {
                quads.push_back(*quad);
                ++i;
                continue;
            }
        }
        quads.push_back({a[0], a[1], a[2], a[2]});
    }
    return quads;
}

}  // namespace

bool TransmitsShadowRays(const Scene& scene, const Surface& surface) {
    // Passed by a ray that has entered an antimatter naming its modifier.
    if (scene.MayBeClipped(surface.modifierId)) return true;
    for (int p : surface.patterns) {
        if (scene.patterns[static_cast<size_t>(p)].kind == ModifierKind::Mixture) return true;
    }
    if (surface.material < 0) return !surface.patterns.empty();  // a hole, or black
    return MaterialTransmits(scene, surface.material, 0);
}

struct RayCore::Impl {
    /// Per-kind user geometry: primID -> surface, and float bounds relative
    /// to the Embree scene's centre, precomputed so the bounds callback only copies.
    struct UserKind {
        const std::vector<Surface>* surfaceList = nullptr;  // what `surfaces` index
        std::vector<int> surfaces;
        std::vector<RTCBounds> bounds;
        std::vector<ConeFrame> coneFrames;  // per primitive, for the cone kind only
    };

    /// The shape a user-geometry callback tests for primitive `primID`.
    template <typename Shape>
    static const Shape& ShapeOf(const UserKind& kind, unsigned primID) {
        if constexpr (std::is_same_v<Shape, ConeFrame>) {
            return kind.coneFrames[primID];
        } else {
            const int surface = kind.surfaces[primID];
            return std::get<Shape>((*kind.surfaceList)[static_cast<size_t>(surface)].shape);
        }
    }

    /// A ray in the coordinates of the surfaces it is tested against: the
    /// caller's world ray, or that ray mapped into an instance's object space
    /// (unit direction; object distances times `scale` are world distances).
    struct ExactRay {
        Vec3 org, dir;
        double tmin = 0;   // tolerance in these units
        double tmax = kInf;
        double scale = 1;  // world length of one unit here
        /// Unit normal (either way round) of the surface the ray leaves, and
        /// the distance beyond which a surface crossing that one is a hit
        /// although nearer than tmin (kInf: the ray leaves no known surface).
        Vec3 leaving;
        double tcross = kInf;

        /// Whether a candidate at t in (tcross, tmin] with unit `normal`
        /// meets the surface the ray leaves at an angle.
        bool Crosses(const Vec3& normal) const {
            const double c = Dot(normal, leaving);
            return c * c < kCoincidentCos2;
        }
    };

    /// Our RTCIntersectContext extension; see the file comment. Lives on the
    /// caller's stack for one query, so queries share no mutable state.
    struct Query {
        RTCIntersectContext rtc;  // must stay first: Embree returns &rtc to callbacks
        const Impl* impl;
        Vec3 org, dir;  // the caller's exact ray
        double tmax;    // exclusive upper bound on exact t (kInf: none)
        double shift;   // the float ray starts this far behind org
        double slack;   // allowance for Embree's float error in t
        // Best candidate so far (Intersect only); the normal in the
        // coordinates of its instance.
        double bestT = kInf;
        int best = -1;
        int bestInstance = -1;
        int bestTriangle = -1;
        Vec3 bestNormal;
        int ignored = -1;  // Occluded only: a world surface whose exact test is skipped
        ExactRay world;  // the caller's ray as an ExactRay
        // The ray in the object space of the instance last asked for: callbacks
        // for one instance come in runs, so it is mapped once per run.
        mutable int mappedInstance = -1;
        mutable ExactRay mapped;

        /// The exact ray for a callback: the world's, or (kInstanced) the ray
        /// in the object space of Embree instance `instID`. Callbacks are
        /// instantiated per kind of Embree scene, so the world's, the hot path,
        /// pays nothing for instancing.
        template <bool kInstanced>
        const ExactRay& RayIn(unsigned instID) const {
            if constexpr (!kInstanced) {
                return world;
            }
            RT_DCHECK(instID != RTC_INVALID_GEOMETRY_ID);
            const int instance = static_cast<int>(instID - kFirstInstanceGeometry);
            if (instance != mappedInstance) {
                const InstanceData& in = impl->instances[static_cast<size_t>(instance)];
                mapped.org = in.objectFromRender.Point(org);
                mapped.dir = in.objectFromRender.Vector(dir) * in.scale;
                mapped.tmin = impl->tolerance / in.scale;
                mapped.tmax = tmax / in.scale;
                mapped.scale = in.scale;
                mapped.tcross = world.tcross / in.scale;
                if (world.tcross < kInf) mapped.leaving = Normalize(in.objectFromRender.Vector(world.leaving));
                mappedInstance = instance;
            }
            return mapped;
        }
        template <bool kInstanced>
        static int InstanceOf(unsigned instID) {
            if constexpr (!kInstanced) return -1;
            return static_cast<int>(instID - kFirstInstanceGeometry);
        }

        /// Radiance's rule for a new candidate: nearer by more than the
        /// tolerance wins; within it, material beats void, opaque beats transparent,
        /// the larger material index wins, and a tie goes to the nearer surface,
        /// then the lower (instance, surface) (where Radiance keeps "the first
        /// found"). Nearer first: a ray that took the farther of two walls
        /// 1e-7 apart would start its reflections behind the nearer one and
        /// hit its back at grazing angles (acne). Always inline: it runs for
        /// every candidate, and GCC's choice flips with unrelated code in this
        /// file (out of line it cost the fast floor 0.5 % of its instructions).
        [[gnu::always_inline]] bool Offer(double t, int instance, int surface, int triangle,
                                          const Vec3& normal) {
            bool take;
            const double tolerance = impl->tolerance;
            if (best < 0 || t < bestT - tolerance) {
                take = true;
            } else if (t > bestT + tolerance) {
                take = false;
            } else if (surface == best && instance == bestInstance) {
                take = t < bestT;
            } else {
                const int order = impl->Compare(instance, surface, bestInstance, best);
                take = order != 0 ? order > 0
                                  : (t != bestT ? t < bestT
                                                : std::pair(instance, surface) <
                                                      std::pair(bestInstance, best));
            }
            if (take) {
                bestT = t;
                best = surface;
                bestInstance = instance;
                bestTriangle = triangle;
                bestNormal = normal;
            }
            return take;
        }

        /// Float tfar that still admits every candidate that could matter:
        /// anything within the tolerance of the best, plus Embree's float error.
        float FarBound() const { return RoundUp(bestT + impl->tolerance + shift + slack); }
    };
    static_assert(std::is_standard_layout_v<Query>, "Query must extend RTCIntersectContext");

    /// The surfaces of one coordinate space as Embree geometry: the scene's
    /// own (world), or a prototype's (object space).
    struct Geometry {
        const std::vector<Surface>* surfaces = nullptr;
        Vec3 centre;  // Embree coordinates are relative to this point
        /// Size of the coordinates in this space that Embree's float error
        /// scales with (user-geometry padding).
        double coordinateScale = 1;
        UserKind spheres, cones, rings;
        /// Per surface: its primitive in `cones`, or -1.
        std::vector<int> conePrimitive;
        const TriangleMesh* mesh = nullptr;
        std::vector<PolygonPlane> meshPlanes;  // per triangle

        /// The polygons as Embree quads, made once (MakePolygonQuads) for all
        /// the layers built over this geometry: every polygon's vertices in
        /// float relative to `centre` (Embree's shared vertex buffer, padded
        /// for its 16-byte reads), every quad's vertex indices and plane, and
        /// per surface its run of quads [quadStart[i], quadStart[i + 1]).
        std::vector<float> polygonVertices;
        std::vector<std::array<unsigned, 4>> polygonQuads;
        std::vector<PolygonPlane> polygonPlanes;
        std::vector<unsigned> quadStart;
    };

    /// One Embree scene over some of the surfaces.
    struct Layer {
        RTCScene rtc = nullptr;
        /// Per quad primitive (primID) when the layer leaves some polygons
        /// out; the polygon filters' geometry user data (else the Geometry's).
        std::vector<PolygonPlane> quads;
        /// Box around every hit the layer can report (scene coordinates),
        /// widened by Embree's float error; empty when the layer holds nothing.
        Bounds3 bounds;
        /// The user geometry of a layer that leaves some of it out (the
        /// callbacks' user data); a layer with all of a kind uses the
        /// Geometry's own. Never moved once the layer is built.
        UserKind spheres, cones, rings;
    };

    struct PrototypeData {
        Geometry geometry;
        Layer layer;
        std::vector<Priority> priority;  // per prototype surface
    };

    struct InstanceData {
        Transform objectFromRender, renderFromObject;
        double scale = 1;  // positive uniform scale of renderFromObject
        int prototype = -1;
        std::optional<Priority> override;
    };

    const Scene* scene = nullptr;
    Vec3 centre;                           // Embree coordinates are relative to this point
    double extent = 1;                     // size of the geometry around the centre (scene units)
    /// Size of the scene's coordinates: the extent, or the largest coordinate
    /// of the geometry if larger (far from the origin). Sets rounding allowances.
    double coordinateScale = 1;
    double tolerance = kFtiny;             // Scene::distanceTolerance
    double crossTolerance = 0;             // ExactRay::tcross of a ray leaving a surface
    std::vector<Priority> priority;        // per surface
    Geometry world;
    std::vector<PrototypeData> prototypes;
    std::vector<InstanceData> instances;

    EmbreeErrors errors;
    RTCDevice device = nullptr;
    /// The layers an occlusion query chooses among, for one set of surfaces.
    struct LayerSet {
        Layer whole;  // every surface of the set
        /// Without the bounding polygons, for occlusion tests between points
        /// inside the bounding planes (see raycore/hull.h). Built only when
        /// the scene has bounding polygons and local light sources (whose
        /// shadow rays are such tests); otherwise interior.rtc stays null.
        Layer interior;
        /// The interior without the polygons in the plane of the light-source
        /// polygons, for occlusion tests that also stay on one side of that
        /// plane (see raycore/source_plane.h). Built with the interior when
        /// the scene has such a plane; otherwise besideSources.rtc stays null.
        Layer besideSources;
    };
    /// All surfaces: `allLayers.whole` answers Intersect and, with the
    /// others, Occluded(All) when nothing transmits; when something does,
    /// only `whole` is built.
    LayerSet allLayers;
    /// The surfaces and instances that stop shadow rays (Occluders::Opaque),
    /// built only when something transmits (`transmittingLayer.rtc` not
    /// null); otherwise `allLayers` is that set.
    LayerSet opaqueLayers;
    /// The surfaces that transmit shadow rays and every instance with one
    /// (Occluders::Transmitting); rtc stays null when there are none.
    Layer transmittingLayer;
    BoundingPolygons bounding;
    std::optional<SourcePlane> sourcePlane;

    ~Impl() {
        for (LayerSet* set : {&opaqueLayers, &allLayers}) {
            for (Layer* layer : {&set->besideSources, &set->interior, &set->whole}) {
                if (layer->rtc) rtcReleaseScene(layer->rtc);
            }
        }
        if (transmittingLayer.rtc) rtcReleaseScene(transmittingLayer.rtc);
        for (PrototypeData& p : prototypes) {
            if (p.layer.rtc) rtcReleaseScene(p.layer.rtc);
        }
        if (device) rtcReleaseDevice(device);
    }

    /// Throws the first error the callback recorded during `call`.
    void Check(const char* call) {
        std::lock_guard lock(errors.mutex);
        if (errors.code != RTC_ERROR_NONE) ThrowEmbreeError(errors.code, errors.message, call);
    }

    const Priority& PriorityOf(int instance, int surface) const {
        if (instance < 0) return priority[static_cast<size_t>(surface)];
        const InstanceData& in = instances[static_cast<size_t>(instance)];
        if (in.override) return *in.override;
        return prototypes[static_cast<size_t>(in.prototype)].priority[static_cast<size_t>(surface)];
    }

    /// +1 if the candidate's material outranks the incumbent's in Radiance's
    /// coincidence rule, -1 if it ranks below, 0 if they rank the same.
    int Compare(int candidateInstance, int candidate, int incumbentInstance, int incumbent) const {
        const Priority& c = PriorityOf(candidateInstance, candidate);
        const Priority& b = PriorityOf(incumbentInstance, incumbent);
        const bool cVoid = c.material < 0, bVoid = b.material < 0;
        if (cVoid != bVoid) return cVoid ? -1 : 1;
        if (c.transparent != b.transparent) return c.transparent ? -1 : 1;
        if (c.material != b.material) return c.material > b.material ? 1 : -1;
        return 0;
    }

    Priority PriorityOfSurface(const Surface& surface) const {
        Priority p;
        p.material = surface.material;
        if (p.material >= 0) {
            RT_CHECK(static_cast<size_t>(p.material) < scene->materials.size());
            p.transparent = IsTransparentType(scene->materials[static_cast<size_t>(p.material)].type);
        }
        return p;
    }

    void Build(const Scene& s);
    /// Sorts a space's surfaces into the user kinds and sets up its mesh planes.
    void Classify(Geometry& geometry, const std::vector<Surface>& surfaces,
                  const TriangleMesh* mesh);
    void BuildPrototype(PrototypeData& data, const Prototype& prototype);
    /// An Embree scene over `geometry`'s surfaces except `leftOut`, and, for
    /// the world (`instanceLeftOut` not null), every instance not left out.
    void BuildLayer(Layer& layer, Geometry& geometry, const std::vector<bool>& leftOut,
                    const std::vector<bool>* instanceLeftOut);
    void BuildPolygons(Layer& layer, Geometry& geometry, const std::vector<bool>& leftOut);
    /// Geometry::polygonVertices and the rest, unless made already.
    static void MakePolygonQuads(Geometry& geometry);
    void BuildMesh(Layer& layer, Geometry& geometry);
    void BuildInstances(Layer& layer, const std::vector<bool>& leftOut);
    /// Float boxes of user-geometry surfaces, relative to the centre.
    std::vector<RTCBounds> UserBoundsOf(const Geometry& geometry, const std::vector<int>& surfaces) const;
    void BuildUserKind(UserKind& kind, const Geometry& geometry, Layer& layer, unsigned id,
                       RTCIntersectFunctionN intersect, RTCOccludedFunctionN occluded);
    void AttachGeometry(Layer& layer, RTCGeometry geometry, unsigned id);
    // Both run once per query: inlined into Intersect and Occluded, which
    // share their work on the origin (as calls they cost measurable time,
    // docs/measured-choices.md).
    [[gnu::always_inline]] inline Query MakeQuery(const Vec3& org, const Vec3& dir, double tmax,
                                                  const Vec3* leaving, RTCRay& ray) const;

    /// How far a ray must be advanced before Embree sees it (0 near the
    /// scene), or kUnreachable when it cannot reach the scene at all. A
    /// plain double, not std::optional: GCC builds an optional<double> in
    /// memory and reloads it whole, a store-forwarding stall on every query.
    [[gnu::always_inline]] inline double DistanceToScene(const Vec3& org, const Vec3& dir) const;
    /// DistanceToScene for an origin far from the scene.
    double DistanceFromAfar(const Vec3& org, const Vec3& dir) const;
    static constexpr double kUnreachable = -1;
    /// Shading normal and (u, v) of a hit on a mesh triangle.
    void SetMeshAttributes(Hit& hit) const;

    // kInstanced: the callback runs inside an instance (a prototype's Embree
    // scene), so its exact ray is mapped into the instance's object space.
    // kMesh: the primitives are mesh triangles, whose index the hit keeps.
    template <bool kInstanced, bool kMesh = false>
    static void PolygonIntersectFilter(const RTCFilterFunctionNArguments* args);
    template <bool kInstanced>
    static void PolygonOccludedFilter(const RTCFilterFunctionNArguments* args);
    static void UserBounds(const RTCBoundsFunctionArguments* args);
    template <bool kInstanced, typename Shape,
              std::optional<ShapeHit> (*Fn)(const Shape&, const Vec3&, const Vec3&, double)>
    static void UserIntersect(const RTCIntersectFunctionNArguments* args);
    template <bool kInstanced, typename Shape,
              std::optional<ShapeHit> (*Fn)(const Shape&, const Vec3&, const Vec3&, double)>
    static void UserOccluded(const RTCOccludedFunctionNArguments* args);
    template <bool kInstanced>
    void BuildUserKinds(Geometry& geometry, Layer& layer, const std::vector<bool>& leftOut);
    /// `all`'s primitives whose surfaces are not left out: `all` itself if
    /// that is every one, else a copy of them in `own`.
    static UserKind& ChooseUserKind(UserKind& all, UserKind& own, const std::vector<bool>& leftOut);

    /// Whether polygon plane p is a valid candidate for ray r: exact t =
    /// num/denom in (r.tmin, r.tmax), or in (r.tcross, r.tmin] if p crosses
    /// the surface the ray leaves. Compared without dividing, because a
    /// division's latency stalls Embree's traversal in every filter call, and
    /// most calls reject (the surface the ray starts on).
    static bool PlaneCandidate(const ExactRay& r, const PolygonPlane& p, double& num,
                               double& denom) {
        denom = Dot(p.normal, r.dir);
        if (std::fabs(denom) <= kFtiny) return false;  // parallel, as o_face.c
        num = p.offset - Dot(p.normal, r.org);
        // tmax = kInf: inf·denom keeps the sign, so the far test passes;
        // tcross = kInf fails the near one.
        if (denom > 0 ? !(num < r.tmax * denom) : !(num > r.tmax * denom)) return false;
        if (denom > 0 ? num > r.tmin * denom : num < r.tmin * denom) return true;
        return (denom > 0 ? num > r.tcross * denom : num < r.tcross * denom) &&
               r.Crosses(p.normal);
    }

    /// Fn's nearest hit of `shape` for ray r under the same rule as
    /// PlaneCandidate (no tmax).
    template <typename Shape,
              std::optional<ShapeHit> (*Fn)(const Shape&, const Vec3&, const Vec3&, double)>
    static std::optional<ShapeHit> ShapeCandidate(const Shape& shape, const ExactRay& r) {
        if (r.tcross < r.tmin) {
            auto h = Fn(shape, r.org, r.dir, r.tcross);
            if (!h || h->t > r.tmin || r.Crosses(h->normal)) return h;
        }
        return Fn(shape, r.org, r.dir, r.tmin);
    }
};

// ---------------------------------------------------------------------------
// Callbacks. Only rtcIntersect1/rtcOccluded1 are used, so every callback sees
// N == 1 and the ray/hit pointers are plain RTCRay/RTCRayHit. The instance a
// callback runs in is the context's instID[0] (invalid in the world).

template <bool kInstanced, bool kMesh>
void RayCore::Impl::PolygonIntersectFilter(const RTCFilterFunctionNArguments* args) {
    RT_DCHECK(args->N == 1);
    auto& q = *reinterpret_cast<Query*>(args->context);
    const auto* hit = reinterpret_cast<const RTCHit*>(args->hit);
    const auto& quads = *static_cast<const std::vector<PolygonPlane>*>(args->geometryUserPtr);
    const PolygonPlane& plane = quads[hit->primID];
    const unsigned instID = args->context->instID[0];
    const ExactRay& r = q.RayIn<kInstanced>(instID);
    double num, denom;
    if (!PlaneCandidate(r, plane, num, denom) ||
        !q.Offer(kInstanced ? num / denom * r.scale : num / denom, Query::InstanceOf<kInstanced>(instID),
                 plane.surface, kMesh ? static_cast<int>(hit->primID) : -1, plane.normal)) {
        args->valid[0] = 0;  // Embree restores tfar and keeps traversing
        return;
    }
    reinterpret_cast<RTCRay*>(args->ray)->tfar = q.FarBound();
}

template <bool kInstanced>
void RayCore::Impl::PolygonOccludedFilter(const RTCFilterFunctionNArguments* args) {
    RT_DCHECK(args->N == 1);
    const auto& q = *reinterpret_cast<const Query*>(args->context);
    const auto* hit = reinterpret_cast<const RTCHit*>(args->hit);
    const auto& quads = *static_cast<const std::vector<PolygonPlane>*>(args->geometryUserPtr);
    const PolygonPlane& plane = quads[hit->primID];
    double num, denom;
    if ((!kInstanced && plane.surface == q.ignored) ||
        !PlaneCandidate(q.RayIn<kInstanced>(args->context->instID[0]), plane, num, denom)) {
        args->valid[0] = 0;
    }
}

void RayCore::Impl::UserBounds(const RTCBoundsFunctionArguments* args) {
    const auto* kind = static_cast<const UserKind*>(args->geometryUserPtr);
    *args->bounds_o = kind->bounds[args->primID];
}

template <bool kInstanced, typename Shape,
          std::optional<ShapeHit> (*Fn)(const Shape&, const Vec3&, const Vec3&, double)>
void RayCore::Impl::UserIntersect(const RTCIntersectFunctionNArguments* args) {
    RT_DCHECK(args->N == 1);
    if (!args->valid[0]) return;
    const auto* kind = static_cast<const UserKind*>(args->geometryUserPtr);
    auto& q = *reinterpret_cast<Query*>(args->context);
    const int surface = kind->surfaces[args->primID];
    const Shape& shape = ShapeOf<Shape>(*kind, args->primID);
    const unsigned instID = args->context->instID[0];
    const ExactRay& r = q.RayIn<kInstanced>(instID);
    const auto h = ShapeCandidate<Shape, Fn>(shape, r);
    if (!h || !(h->t < r.tmax) ||
        !q.Offer(kInstanced ? h->t * r.scale : h->t, Query::InstanceOf<kInstanced>(instID), surface,
                 -1, h->normal)) {
        return;
    }
    auto* rayhit = reinterpret_cast<RTCRayHit*>(args->rayhit);
    rayhit->ray.tfar = q.FarBound();
    rayhit->hit.Ng_x = static_cast<float>(h->normal.x);
    rayhit->hit.Ng_y = static_cast<float>(h->normal.y);
    rayhit->hit.Ng_z = static_cast<float>(h->normal.z);
    rayhit->hit.u = rayhit->hit.v = 0;
    rayhit->hit.primID = args->primID;
    rayhit->hit.geomID = args->geomID;
    rayhit->hit.instID[0] = instID;
}

template <bool kInstanced, typename Shape,
          std::optional<ShapeHit> (*Fn)(const Shape&, const Vec3&, const Vec3&, double)>
void RayCore::Impl::UserOccluded(const RTCOccludedFunctionNArguments* args) {
    RT_DCHECK(args->N == 1);
    if (!args->valid[0]) return;
    const auto* kind = static_cast<const UserKind*>(args->geometryUserPtr);
    const auto& q = *reinterpret_cast<const Query*>(args->context);
    if (!kInstanced && kind->surfaces[args->primID] == q.ignored) return;
    const Shape& shape = ShapeOf<Shape>(*kind, args->primID);
    const ExactRay& r = q.RayIn<kInstanced>(args->context->instID[0]);
    const auto h = ShapeCandidate<Shape, Fn>(shape, r);
    if (h && h->t < r.tmax) {
        // Embree's convention for "occluded": tfar = -inf.
        reinterpret_cast<RTCRay*>(args->ray)->tfar = -std::numeric_limits<float>::infinity();
    }
}

// ---------------------------------------------------------------------------
// Construction.

void RayCore::Impl::Classify(Geometry& geometry, const std::vector<Surface>& surfaces,
                             const TriangleMesh* mesh) {
    geometry.surfaces = &surfaces;
    geometry.spheres.surfaceList = geometry.cones.surfaceList = geometry.rings.surfaceList = &surfaces;
    geometry.conePrimitive.assign(surfaces.size(), -1);
    for (size_t i = 0; i < surfaces.size(); ++i) {
        const Surface& surface = surfaces[i];
        const int index = static_cast<int>(i);
        switch (surface.type) {
            case SurfaceType::Polygon:
                break;  // BuildPolygons
            case SurfaceType::Sphere:
            case SurfaceType::Bubble:
                RT_CHECK(std::get<Sphere>(surface.shape).inward ==
                         (surface.type == SurfaceType::Bubble));
                geometry.spheres.surfaces.push_back(index);
                break;
            case SurfaceType::Cone:
            case SurfaceType::Cup:
            case SurfaceType::Cylinder:
            case SurfaceType::Tube:
                RT_CHECK(std::get<Cone>(surface.shape).inward ==
                         (surface.type == SurfaceType::Cup || surface.type == SurfaceType::Tube));
                geometry.conePrimitive[i] = static_cast<int>(geometry.cones.surfaces.size());
                geometry.cones.surfaces.push_back(index);
                geometry.cones.coneFrames.push_back(MakeConeFrame(std::get<Cone>(surface.shape)));
                break;
            case SurfaceType::Ring:
                geometry.rings.surfaces.push_back(index);
                break;
            case SurfaceType::Source:
            case SurfaceType::Instance:
            case SurfaceType::Mesh:
                break;  // not geometry
        }
    }
    geometry.mesh = mesh;
    if (!mesh) return;
    // Radiance's mesh normal (o_mesh.c): (V0 − V2) × (V1 − V0), so that
    // counter-clockwise vertices face the viewer.
    geometry.meshPlanes.reserve(mesh->triangles.size());
    for (const TriangleMesh::Triangle& tri : mesh->triangles) {
        const Vec3& a = mesh->vertices[static_cast<size_t>(tri.v[0])];
        const Vec3& b = mesh->vertices[static_cast<size_t>(tri.v[1])];
        const Vec3& c = mesh->vertices[static_cast<size_t>(tri.v[2])];
        Vec3 n = Cross(a - c, b - a);
        const double length = Length(n);
        n = length > 0 ? n / length : Vec3{};
        // A degenerate triangle gets a zero normal: PlaneCandidate finds it parallel.
        geometry.meshPlanes.push_back({n, Dot(n, a), tri.surface});
    }
}

void RayCore::Impl::Build(const Scene& s) {
    scene = &s;
    tolerance = s.distanceTolerance;
    // Centre of the geometry: oconv's cube when the loader filled it in,
    // otherwise (hand-built scenes) the bounds of the surfaces.
    Bounds3 bounds;
    for (const Surface& surface : s.surfaces) bounds.Extend(ShapeBounds(surface));
    for (const Instance& instance : s.instances) bounds.Extend(InstanceBounds(s, instance));
    if (s.cubeSize > 0) {
        centre = s.cubeOrigin + Vec3{1, 1, 1} * (s.cubeSize / 2);
        extent = s.cubeSize;
    } else if (!bounds.Empty()) {
        centre = (bounds.lo + bounds.hi) / 2;
        extent = MaxAbs(bounds.hi - bounds.lo);
    }
    if (!(extent > 0)) extent = 1;
    coordinateScale = std::max(extent, MaxAbs(centre) + extent);
    crossTolerance = kCoordinateUlps * std::numeric_limits<double>::epsilon() * coordinateScale;

    priority.resize(s.surfaces.size());
    for (size_t i = 0; i < s.surfaces.size(); ++i) priority[i] = PriorityOfSurface(s.surfaces[i]);
    Classify(world, s.surfaces, nullptr);
    world.centre = centre;
    world.coordinateScale = coordinateScale;

    device = rtcNewDevice(nullptr);
    if (!device) ThrowEmbreeError(rtcGetDeviceError(nullptr), "", "rtcNewDevice");
    rtcSetDeviceErrorFunction(device, &EmbreeErrors::Callback, &errors);
    // Without filter support Embree would silently report self-intersections;
    // with back-face culling it would lose the inside of closed rooms.
    if (!rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_FILTER_FUNCTION_SUPPORTED) ||
        rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_BACKFACE_CULLING_ENABLED)) {
        throw Error(Error::Kind::Internal,
                    "Embree build lacks filter functions or culls back faces");
    }

    instances.resize(s.instances.size());
    // Embree's float error in an instance's object space is the world's,
    // divided by the instance's scale: the smallest placement sets the padding.
    std::vector<double> smallestScale(s.prototypes.size(), kInf);
    for (size_t i = 0; i < s.instances.size(); ++i) {
        const Instance& in = s.instances[i];
        InstanceData& data = instances[i];
        data.renderFromObject = in.renderFromObject;
        data.objectFromRender = in.objectFromRender;
        data.scale = std::fabs(in.renderFromObject.scale);
        data.prototype = in.prototype;
        if (in.override) data.override = PriorityOfSurface(*in.override);
        double& smallest = smallestScale[static_cast<size_t>(in.prototype)];
        smallest = std::min(smallest, data.scale);
    }
    prototypes.resize(s.prototypes.size());
    for (size_t p = 0; p < s.prototypes.size(); ++p) {
        const Prototype& prototype = s.prototypes[p];
        PrototypeData& data = prototypes[p];
        Geometry& g = data.geometry;
        g.centre = prototype.cubeOrigin + Vec3{1, 1, 1} * (prototype.cubeSize / 2);
        const double own = std::max(prototype.cubeSize, MaxAbs(g.centre) + prototype.cubeSize);
        g.coordinateScale =
            std::isfinite(smallestScale[p]) ? std::max(own, coordinateScale / smallestScale[p]) : own;
        BuildPrototype(data, prototype);
    }

    // Which surfaces and instances stop shadow rays (Occluders::Opaque) and
    // which may let them pass (Occluders::Transmitting); an instance goes
    // wholly to one side.
    std::vector<bool> transmits(s.surfaces.size(), false);
    for (size_t i = 0; i < s.surfaces.size(); ++i) {
        transmits[i] = TransmitsShadowRays(s, s.surfaces[i]);
    }
    std::vector<bool> instanceTransmits(s.instances.size(), false);
    for (size_t i = 0; i < s.instances.size(); ++i) {
        const Instance& in = s.instances[i];
        if (in.override) {
            instanceTransmits[i] = TransmitsShadowRays(s, *in.override);
        } else {
            const auto& inner = s.prototypes[static_cast<size_t>(in.prototype)].surfaces;
            instanceTransmits[i] = std::any_of(inner.begin(), inner.end(), [&](const Surface& f) {
                return TransmitsShadowRays(s, f);
            });
        }
    }
    const bool anyTransmits =
        std::find(transmits.begin(), transmits.end(), true) != transmits.end() ||
        std::find(instanceTransmits.begin(), instanceTransmits.end(), true) !=
            instanceTransmits.end();
    const std::vector<bool> none(s.surfaces.size(), false),
        noInstance(s.instances.size(), false);
    // `leftOut` with the transmitting (opaque) surfaces left out as well.
    const auto without = [](std::vector<bool> leftOut, const std::vector<bool>& more) {
        for (size_t i = 0; i < leftOut.size(); ++i) leftOut[i] = leftOut[i] || more[i];
        return leftOut;
    };
    const auto negated = [](std::vector<bool> v) {
        v.flip();
        return v;
    };

    BuildLayer(allLayers.whole, world, none, &noInstance);
    if (anyTransmits) {
        BuildLayer(opaqueLayers.whole, world, transmits, &instanceTransmits);
        const std::vector<bool> opaqueInstances = negated(instanceTransmits);
        BuildLayer(transmittingLayer, world, negated(transmits), &opaqueInstances);
    }

    const bool localSources =
        std::any_of(s.surfaces.begin(), s.surfaces.end(), [&](const Surface& f) {
            return f.type != SurfaceType::Source && f.material >= 0 &&
                   IsLightType(s.materials[static_cast<size_t>(f.material)].type);
        });
    if (!localSources) return;
    // Hit points carry rounding errors of a few ulps of the coordinates,
    // which the tolerance exceeds a thousandfold; 1 % of it keeps them inside.
    bounding = FindBoundingPolygons(s, 0.01 * tolerance);
    if (bounding.surfaces.empty()) return;
    std::vector<bool> leftOut(s.surfaces.size(), false);
    for (int i : bounding.surfaces) leftOut[static_cast<size_t>(i)] = true;
    // With something that transmits, Occluded(All) asks the two sets in
    // turn, so the shortcut layers of all surfaces are not needed.
    if (anyTransmits) {
        BuildLayer(opaqueLayers.interior, world, without(leftOut, transmits), &instanceTransmits);
    } else {
        BuildLayer(allLayers.interior, world, leftOut, &noInstance);
    }

    sourcePlane = FindSourcePlane(s, leftOut, coordinateScale);
    if (!sourcePlane) return;
    for (int i : sourcePlane->surfaces) leftOut[static_cast<size_t>(i)] = true;
    if (anyTransmits) {
        BuildLayer(opaqueLayers.besideSources, world, without(leftOut, transmits),
                   &instanceTransmits);
    } else {
        BuildLayer(allLayers.besideSources, world, leftOut, &noInstance);
    }
}

void RayCore::Impl::BuildPrototype(PrototypeData& data, const Prototype& prototype) {
    data.priority.reserve(prototype.surfaces.size());
    for (const Surface& surface : prototype.surfaces) data.priority.push_back(PriorityOfSurface(surface));
    Classify(data.geometry, prototype.surfaces, prototype.mesh.get());
    BuildLayer(data.layer, data.geometry, std::vector<bool>(prototype.surfaces.size(), false),
               nullptr);
}

void RayCore::Impl::AttachGeometry(Layer& layer, RTCGeometry geometry, unsigned id) {
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(layer.rtc, geometry, id);
    rtcReleaseGeometry(geometry);
}

void RayCore::Impl::BuildLayer(Layer& layer, Geometry& geometry, const std::vector<bool>& leftOut,
                               const std::vector<bool>* instanceLeftOut) {
    layer.rtc = rtcNewScene(device);
    Check("rtcNewScene");
    // ROBUST: watertight triangle tests, so rays through shared edges and
    // vertices never slip between triangles. It costs traversal time, but
    // without it rays from inside a closed genbox room aimed at its edges and
    // corners escape (README, "Measured"; raycore_test's CheckClosedBox).
    rtcSetSceneFlags(layer.rtc, RTC_SCENE_FLAG_ROBUST);
    // The scene never changes after loading and is traced millions of times:
    // spend more on the build for faster traversal.
    rtcSetSceneBuildQuality(layer.rtc, RTC_BUILD_QUALITY_HIGH);

    // Embree's candidates lie within its float error of their surface, and
    // the exact tests accept them there.
    const double pad = 2 * kFloatSlack * geometry.coordinateScale + tolerance;
    const Vec3 padding{pad, pad, pad};
    const auto& surfaces = *geometry.surfaces;
    for (size_t i = 0; i < surfaces.size(); ++i) {
        if (leftOut[i]) continue;
        const Bounds3 b = ShapeBounds(surfaces[i]);
        if (!b.Empty()) layer.bounds.Extend(Bounds3{b.lo - padding, b.hi + padding});
    }
    if (geometry.mesh) {
        for (const Vec3& v : geometry.mesh->vertices) layer.bounds.Extend(Bounds3{v - padding, v + padding});
    }
    BuildPolygons(layer, geometry, leftOut);
    if (&geometry == &world) {
        BuildUserKinds<false>(geometry, layer, leftOut);
    } else {
        BuildUserKinds<true>(geometry, layer, leftOut);
    }
    if (geometry.mesh) BuildMesh(layer, geometry);
    if (instanceLeftOut) BuildInstances(layer, *instanceLeftOut);

    rtcCommitScene(layer.rtc);
    Check("rtcCommitScene");
}

template <bool kInstanced>
void RayCore::Impl::BuildUserKinds(Geometry& geometry, Layer& layer,
                                   const std::vector<bool>& leftOut) {
    BuildUserKind(ChooseUserKind(geometry.spheres, layer.spheres, leftOut), geometry, layer,
                  kSphereGeometry, &UserIntersect<kInstanced, Sphere, IntersectSphere>,
                  &UserOccluded<kInstanced, Sphere, IntersectSphere>);
    BuildUserKind(ChooseUserKind(geometry.cones, layer.cones, leftOut), geometry, layer,
                  kConeGeometry, &UserIntersect<kInstanced, ConeFrame, IntersectCone>,
                  &UserOccluded<kInstanced, ConeFrame, IntersectCone>);
    BuildUserKind(ChooseUserKind(geometry.rings, layer.rings, leftOut), geometry, layer,
                  kRingGeometry, &UserIntersect<kInstanced, Ring, IntersectRing>,
                  &UserOccluded<kInstanced, Ring, IntersectRing>);
}

RayCore::Impl::UserKind& RayCore::Impl::ChooseUserKind(UserKind& all, UserKind& own,
                                                       const std::vector<bool>& leftOut) {
    const auto out = [&](int surface) { return leftOut[static_cast<size_t>(surface)]; };
    if (std::none_of(all.surfaces.begin(), all.surfaces.end(), out)) return all;
    own.surfaceList = all.surfaceList;
    for (size_t p = 0; p < all.surfaces.size(); ++p) {
        if (out(all.surfaces[p])) continue;
        own.surfaces.push_back(all.surfaces[p]);
        if (!all.coneFrames.empty()) own.coneFrames.push_back(all.coneFrames[p]);
    }
    return own;
}

void RayCore::Impl::MakePolygonQuads(Geometry& geometry) {
    if (!geometry.quadStart.empty()) return;
    const auto& surfaces = *geometry.surfaces;
    // Sized once: growing them would touch twice the memory, and a large
    // scene's start-up is mostly first touches of memory. A polygon of n
    // vertices makes at most n - 2 quads.
    std::size_t vertexCount = 0, quadBound = 0;
    for (const Surface& surface : surfaces) {
        if (surface.type == SurfaceType::Polygon) {
            const std::size_t n = std::get<Polygon>(surface.shape).vertices.size();
            vertexCount += n;
            quadBound += n - 2;
        }
    }
    geometry.polygonVertices.reserve(3 * vertexCount + 1);
    geometry.polygonQuads.reserve(quadBound);
    geometry.polygonPlanes.reserve(quadBound);
    AdviseHugePages(geometry.polygonVertices);
    AdviseHugePages(geometry.polygonQuads);
    AdviseHugePages(geometry.polygonPlanes);
    geometry.quadStart.reserve(surfaces.size() + 1);
    for (size_t i = 0; i < surfaces.size(); ++i) {
        geometry.quadStart.push_back(static_cast<unsigned>(geometry.polygonQuads.size()));
        const Surface& surface = surfaces[i];
        if (surface.type != SurfaceType::Polygon) continue;
        const auto& polygon = std::get<Polygon>(surface.shape);
        const auto base = static_cast<unsigned>(geometry.polygonVertices.size() / 3);
        // Same double -> same float: polygons sharing a vertex share it
        // bit-exactly, which Embree's watertight test needs.
        for (const Vec3& v : polygon.vertices) {
            const Vec3 r = v - geometry.centre;
            geometry.polygonVertices.insert(geometry.polygonVertices.end(),
                                            {static_cast<float>(r.x), static_cast<float>(r.y),
                                             static_cast<float>(r.z)});
        }
        for (const auto& quad : PairTriangles(TriangulatePolygon(polygon))) {
            geometry.polygonQuads.push_back(
                {base + static_cast<unsigned>(quad[0]), base + static_cast<unsigned>(quad[1]),
                 base + static_cast<unsigned>(quad[2]), base + static_cast<unsigned>(quad[3])});
            geometry.polygonPlanes.push_back({polygon.normal, polygon.offset, static_cast<int>(i)});
        }
    }
    geometry.quadStart.push_back(static_cast<unsigned>(geometry.polygonQuads.size()));
    geometry.polygonVertices.push_back(0.0f);  // Embree reads 16 bytes at the last vertex
}

void RayCore::Impl::BuildPolygons(Layer& layer, Geometry& geometry,
                                  const std::vector<bool>& leftOut) {
    MakePolygonQuads(geometry);
    const auto& start = geometry.quadStart;
    std::size_t count = 0;
    for (size_t i = 0; i + 1 < start.size(); ++i) {
        if (!leftOut[i]) count += start[i + 1] - start[i];
    }
    if (count == 0) return;
    // A layer with every polygon uses the geometry's planes; one that
    // leaves some out numbers its quads afresh and keeps its own.
    const bool all = count == geometry.polygonQuads.size();
    if (!all) {
        layer.quads.reserve(count);
        AdviseHugePages(layer.quads);
    }

    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_QUAD);
    Check("rtcNewGeometry");
    const std::size_t vertexCount = (geometry.polygonVertices.size() - 1) / 3;
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                               geometry.polygonVertices.data(), 0, 3 * sizeof(float), vertexCount);
    if (all) {
        // Every quad: Embree reads the geometry's own index array, which
        // outlives the layer, rather than a copy in fresh pages (a large
        // model's start-up is mostly first touches of memory).
        rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4,
                                   geometry.polygonQuads.data(), 0, 4 * sizeof(unsigned), count);
    } else {
        auto* ib = static_cast<std::array<unsigned, 4>*>(rtcSetNewGeometryBuffer(
            geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT4, 4 * sizeof(unsigned), count));
        if (!ib) {
            rtcReleaseGeometry(geom);
            Check("rtcSetNewGeometryBuffer");
            throw Error(Error::Kind::System, "Embree rtcSetNewGeometryBuffer failed");
        }
        for (size_t i = 0; i + 1 < start.size(); ++i) {
            if (leftOut[i]) continue;
            for (unsigned q = start[i]; q < start[i + 1]; ++q) {
                *ib++ = geometry.polygonQuads[q];
                layer.quads.push_back(geometry.polygonPlanes[q]);
            }
        }
    }
    rtcSetGeometryUserData(geom, all ? &geometry.polygonPlanes : &layer.quads);
    const bool instanced = &geometry != &world;
    rtcSetGeometryIntersectFilterFunction(
        geom, instanced ? &PolygonIntersectFilter<true> : &PolygonIntersectFilter<false>);
    rtcSetGeometryOccludedFilterFunction(
        geom, instanced ? &PolygonOccludedFilter<true> : &PolygonOccludedFilter<false>);
    AttachGeometry(layer, geom, kPolygonGeometry);
    Check("polygon mesh");
}

void RayCore::Impl::BuildMesh(Layer& layer, Geometry& geometry) {
    const TriangleMesh& mesh = *geometry.mesh;
    if (mesh.triangles.empty()) return;
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    Check("rtcNewGeometry");
    auto* vb = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0,
                                                           RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                           mesh.vertices.size()));
    auto* ib = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(unsigned), mesh.triangles.size()));
    if (!vb || !ib) {
        rtcReleaseGeometry(geom);
        Check("rtcSetNewGeometryBuffer");
        throw Error(Error::Kind::System, "Embree rtcSetNewGeometryBuffer failed");
    }
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        const Vec3 r = mesh.vertices[i] - geometry.centre;
        vb[3 * i] = static_cast<float>(r.x);
        vb[3 * i + 1] = static_cast<float>(r.y);
        vb[3 * i + 2] = static_cast<float>(r.z);
    }
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        for (int k = 0; k < 3; ++k) ib[3 * i + k] = static_cast<unsigned>(mesh.triangles[i].v[k]);
    }
    rtcSetGeometryUserData(geom, &geometry.meshPlanes);
    rtcSetGeometryIntersectFilterFunction(geom, &PolygonIntersectFilter<true, true>);
    rtcSetGeometryOccludedFilterFunction(geom, &PolygonOccludedFilter<true>);
    AttachGeometry(layer, geom, kMeshGeometry);
    Check("triangle mesh");
}

void RayCore::Impl::BuildInstances(Layer& layer, const std::vector<bool>& leftOut) {
    for (size_t i = 0; i < instances.size(); ++i) {
        if (leftOut[i]) continue;
        const InstanceData& in = instances[i];
        PrototypeData& proto = prototypes[static_cast<size_t>(in.prototype)];
        if (proto.layer.bounds.Empty()) continue;  // nothing to hit
        // Embree's instance transform takes the prototype's Embree coordinates
        // (relative to its centre) to the world's (relative to ours):
        // x ↦ (x + c_p)·R + T − c, column-major 3×4.
        const Transform& f = in.renderFromObject;
        const Vec3 translation = f.Point(proto.geometry.centre) - centre;
        float xfm[12];
        for (int row = 0; row < 3; ++row) {
            for (int k = 0; k < 3; ++k) xfm[3 * row + k] = static_cast<float>(f.m[row][k]);
        }
        xfm[9] = static_cast<float>(translation.x);
        xfm[10] = static_cast<float>(translation.y);
        xfm[11] = static_cast<float>(translation.z);
        RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
        Check("rtcNewGeometry");
        rtcSetGeometryInstancedScene(geom, proto.layer.rtc);
        rtcSetGeometryTimeStepCount(geom, 1);
        rtcSetGeometryTransform(geom, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
        AttachGeometry(layer, geom, kFirstInstanceGeometry + static_cast<unsigned>(i));
        // The layer's box (for SegmentMeetsBox) in world coordinates: the
        // prototype's box placed, widened by the world's float error.
        const Bounds3& b = proto.layer.bounds;
        const double pad = 2 * kFloatSlack * coordinateScale;
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3 c{corner & 1 ? b.hi.x : b.lo.x, corner & 2 ? b.hi.y : b.lo.y,
                         corner & 4 ? b.hi.z : b.lo.z};
            const Vec3 w = f.Point(c);
            layer.bounds.Extend(Bounds3{w - Vec3{pad, pad, pad}, w + Vec3{pad, pad, pad}});
        }
    }
    Check("instances");
}

void RayCore::Impl::BuildUserKind(UserKind& kind, const Geometry& geometry, Layer& layer,
                                  unsigned id, RTCIntersectFunctionN intersect,
                                  RTCOccludedFunctionN occluded) {
    if (kind.surfaces.empty()) return;
    if (kind.bounds.empty()) kind.bounds = UserBoundsOf(geometry, kind.surfaces);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    Check("rtcNewGeometry");
    rtcSetGeometryUserPrimitiveCount(geom, static_cast<unsigned>(kind.surfaces.size()));
    rtcSetGeometryUserData(geom, &kind);
    rtcSetGeometryBoundsFunction(geom, &UserBounds, nullptr);
    rtcSetGeometryIntersectFunction(geom, intersect);
    rtcSetGeometryOccludedFunction(geom, occluded);
    AttachGeometry(layer, geom, id);
    Check("user geometry");
}

std::vector<RTCBounds> RayCore::Impl::UserBoundsOf(const Geometry& geometry,
                                                   const std::vector<int>& surfaces) const {
    std::vector<RTCBounds> bounds;
    bounds.reserve(surfaces.size());
    for (int surface : surfaces) {
        const Bounds3 b = ShapeBounds((*geometry.surfaces)[static_cast<size_t>(surface)]);
        const Vec3 lo = b.lo - geometry.centre, hi = b.hi - geometry.centre;
        // Padding covers the float ray's deviation from the exact ray, so a
        // grazing exact hit is still offered to the exact test.
        // In a prototype the float ray comes from the world's through the
        // instance transform, so its error follows the world's coordinates.
        const double scaleTerm = &geometry == &world ? 0.0 : geometry.coordinateScale;
        const double pad = kFloatSlack * (std::max({MaxAbs(lo), MaxAbs(hi), scaleTerm}) +
                                          MaxAbs(hi - lo));
        RTCBounds rb;
        rb.lower_x = RoundDown(lo.x - pad);
        rb.lower_y = RoundDown(lo.y - pad);
        rb.lower_z = RoundDown(lo.z - pad);
        rb.upper_x = RoundUp(hi.x + pad);
        rb.upper_y = RoundUp(hi.y + pad);
        rb.upper_z = RoundUp(hi.z + pad);
        rb.align0 = rb.align1 = 0;
        bounds.push_back(rb);
    }
    return bounds;
}

// ---------------------------------------------------------------------------
// Queries.

RayCore::Impl::Query RayCore::Impl::MakeQuery(const Vec3& org, const Vec3& dir, double tmax,
                                              const Vec3* leaving, RTCRay& ray) const {
    Query q;
    rtcInitIntersectContext(&q.rtc);
    q.impl = this;
    q.org = org;
    q.dir = dir;
    q.tmax = tmax > 0 ? tmax : kInf;
    q.world = ExactRay{org, dir, tolerance, q.tmax, 1.0, Vec3{}, kInf};
    if (leaving) {
        q.world.leaving = *leaving;
        q.world.tcross = crossTolerance;
    }
    q.mappedInstance = -1;
    // Embree's float distances are off by a few ulps of the largest
    // coordinate in play. The float ray starts `shift` behind the origin so
    // that every exact t > tolerance has a float t > 0 (tnear = 0), and the
    // exact test, not Embree, decides what is too close.
    const Vec3 rel = org - centre;
    q.slack = kFloatSlack * std::max(MaxAbs(rel), extent);
    q.shift = q.slack;
    const Vec3 start = rel - dir * q.shift;
    ray.org_x = static_cast<float>(start.x);
    ray.org_y = static_cast<float>(start.y);
    ray.org_z = static_cast<float>(start.z);
    ray.dir_x = static_cast<float>(dir.x);
    ray.dir_y = static_cast<float>(dir.y);
    ray.dir_z = static_cast<float>(dir.z);
    ray.tnear = 0;
    ray.tfar =
        tmax > 0 ? RoundUp(tmax + q.shift + q.slack) : std::numeric_limits<float>::infinity();
    ray.time = 0;
    ray.mask = 0xFFFFFFFFu;
    ray.id = 0;
    ray.flags = 0;
    return q;
}

RayCore::RayCore(const Scene& scene) : impl_(std::make_unique<Impl>()) { impl_->Build(scene); }

RayCore::~RayCore() = default;

double RayCore::Impl::DistanceToScene(const Vec3& org, const Vec3& dir) const {
    // One finiteness test each: a sum is NaN or infinite if any term is.
    if (!std::isfinite(dir.x + dir.y + dir.z)) return kUnreachable;
    // Generous: the geometry lies within 0.87·extent of the centre.
    if (LengthSquared(org - centre) <= 16.0 * extent * extent) return 0.0;
    return DistanceFromAfar(org, dir);
}

double RayCore::Impl::DistanceFromAfar(const Vec3& org, const Vec3& dir) const {
    const Vec3 rel = org - centre;
    const double radius = extent;
    const double dist2 = LengthSquared(rel);
    if (!std::isfinite(dist2)) return kUnreachable;
    // Closest approach from the perpendicular part (no b² - c cancellation).
    const double b = Dot(rel, dir);
    const double perp2 = LengthSquared(rel - dir * b);
    if (perp2 > radius * radius || b > 0) return kUnreachable;  // misses the scene
    const double entry = -b - std::sqrt(radius * radius - perp2);
    // The advanced origin is only known to an ulp of the original distance:
    // stop that far (and a scene radius) short of the scene.
    const double margin = radius + 8.0 * std::sqrt(dist2) * std::numeric_limits<double>::epsilon();
    const double advance = std::max(0.0, entry - margin);
    // Beyond ~1e15 scene sizes the origin cannot be placed near the scene in
    // double at all; such a ray cannot meaningfully hit anything.
    if (MaxAbs(org + dir * advance - centre) > 1e15 * radius) return kUnreachable;
    return advance;
}

std::optional<Hit> RayCore::Intersect(const Vec3& orgIn, const Vec3& dir, double tmaxIn,
                                      const Vec3* leaving) const {
    if (log_) [[unlikely]] log_->push_back({orgIn, dir, tmaxIn, false});
    // A ray from far outside the scene is first advanced, in double, to near
    // the scene: Embree's float rays lose precision with distance and must
    // stay within about 1.8e19 of the origin.
    const double advance = impl_->DistanceToScene(orgIn, dir);
    if (advance < 0) return std::nullopt;
    if (tmaxIn > 0 && tmaxIn <= advance) return std::nullopt;
    const Vec3 org = orgIn + dir * advance;
    const double tmax = tmaxIn > 0 ? tmaxIn - advance : 0.0;
    RTCRayHit rayhit;
    // An advanced origin is on no surface.
    Impl::Query q = impl_->MakeQuery(org, dir, tmax, advance == 0 ? leaving : nullptr, rayhit.ray);
    rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.primID = RTC_INVALID_GEOMETRY_ID;
    rayhit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(impl_->allLayers.whole.rtc, &q.rtc, &rayhit);
    // The answer is the Query's best, not rayhit.hit: the callbacks may have
    // accepted later coincident candidates that lost the priority rule.
    if (q.best < 0) return std::nullopt;
    Hit hit;
    hit.t = q.bestT + advance;
    hit.point = org + dir * q.bestT;
    hit.surface = q.best;
    hit.instance = q.bestInstance;
    hit.triangle = q.bestTriangle;
    if (q.bestInstance < 0) {
        hit.normal = q.bestNormal;
    } else {
        const Impl::InstanceData& in = impl_->instances[static_cast<size_t>(q.bestInstance)];
        hit.normal = Normalize(in.renderFromObject.Vector(q.bestNormal));
    }
    hit.shadingNormal = hit.normal;
    if (hit.triangle >= 0) impl_->SetMeshAttributes(hit);
    return hit;
}

void RayCore::Impl::SetMeshAttributes(Hit& hit) const {
    const InstanceData& in = instances[static_cast<size_t>(hit.instance)];
    const TriangleMesh& mesh = *prototypes[static_cast<size_t>(in.prototype)].geometry.mesh;
    const TriangleMesh::Triangle& tri = mesh.triangles[static_cast<size_t>(hit.triangle)];
    const Vec3 p = in.objectFromRender.Point(hit.point);
    const auto w = BarycentricWeights(mesh.vertices[static_cast<size_t>(tri.v[0])],
                                      mesh.vertices[static_cast<size_t>(tri.v[1])],
                                      mesh.vertices[static_cast<size_t>(tri.v[2])], p);
    if (!w) return;  // degenerate: no interpolation (Radiance warns "bad triangle")
    const auto vertex = [&](int k) { return static_cast<size_t>(tri.v[k]); };
    if (!mesh.normals.empty()) {
        Vec3 n;
        bool every = true;
        for (int k = 0; k < 3 && every; ++k) {
            const Vec3& nk = mesh.normals[vertex(k)];
            every = LengthSquared(nk) > 0;
            n += nk * (*w)[k];
        }
        if (every && LengthSquared(n) > 0) hit.shadingNormal = Normalize(in.renderFromObject.Vector(n));
    }
    if (!mesh.uvs.empty() && mesh.hasUv[vertex(0)] && mesh.hasUv[vertex(1)] &&
        mesh.hasUv[vertex(2)]) {
        for (int k = 0; k < 3; ++k) {
            hit.u += (*w)[k] * mesh.uvs[vertex(k)][0];
            hit.v += (*w)[k] * mesh.uvs[vertex(k)][1];
        }
    }
}

std::optional<Hit> RayCore::IntersectSurface(int surface, const Vec3& org, const Vec3& dir) const {
    RT_CHECK(surface >= 0 && static_cast<size_t>(surface) < impl_->scene->surfaces.size());
    const Impl::Geometry& world = impl_->world;
    const int cone = world.conePrimitive[static_cast<size_t>(surface)];
    const auto h = cone >= 0 ? IntersectCone(world.cones.coneFrames[static_cast<size_t>(cone)], org,
                                             dir, impl_->tolerance)
                             : IntersectShape(impl_->scene->surfaces[static_cast<size_t>(surface)],
                                              org, dir, impl_->tolerance);
    if (!h) return std::nullopt;
    Hit hit;
    hit.t = h->t;
    hit.point = org + dir * h->t;
    hit.normal = hit.shadingNormal = h->normal;
    hit.surface = surface;
    return hit;
}

std::optional<RayCore::SurfaceSide> RayCore::IntersectSurfaceSide(int surface, const Vec3& org,
                                                                  const Vec3& dir) const {
    RT_CHECK(surface >= 0 && static_cast<size_t>(surface) < impl_->scene->surfaces.size());
    const Impl::Geometry& world = impl_->world;
    const int cone = world.conePrimitive[static_cast<size_t>(surface)];
    const auto h =
        cone >= 0
            ? IntersectConeSide(world.cones.coneFrames[static_cast<size_t>(cone)], org, dir,
                                impl_->tolerance)
            : IntersectShapeSide(impl_->scene->surfaces[static_cast<size_t>(surface)], org, dir,
                                 impl_->tolerance);
    if (!h) return std::nullopt;
    return SurfaceSide{h->t, h->back};
}

bool RayCore::HasTransmitting() const { return impl_->transmittingLayer.rtc != nullptr; }

bool RayCore::Occluded(const Vec3& orgIn, const Vec3& dir, double tmaxIn, Occluders which,
                       int ignored, const Vec3* leaving) const {
    if (impl_->transmittingLayer.rtc && which == Occluders::All) {
        return Occluded(orgIn, dir, tmaxIn, Occluders::Transmitting, ignored, leaving) ||
               Occluded(orgIn, dir, tmaxIn, Occluders::Opaque, ignored, leaving);
    }
    if (which == Occluders::Transmitting && !impl_->transmittingLayer.rtc) return false;
    if (log_) [[unlikely]] log_->push_back({orgIn, dir, tmaxIn, true});
    const double advance = impl_->DistanceToScene(orgIn, dir);
    if (advance < 0) return false;
    if (tmaxIn > 0 && tmaxIn <= advance) return false;
    const Impl::LayerSet& set = which == Occluders::Opaque && impl_->transmittingLayer.rtc
                                    ? impl_->opaqueLayers
                                    : impl_->allLayers;
    const Impl::Layer* layer = &set.whole;
    if (which == Occluders::Transmitting) {
        layer = &impl_->transmittingLayer;
        // Few surfaces, usually away from the segment: no need to ask Embree.
        // Without tmax, the segment to beyond the geometry (which lies within
        // 0.87 extents of the centre) stands for the ray.
        if (advance == 0) {
            const double reach =
                tmaxIn > 0 ? tmaxIn : Length(orgIn - impl_->centre) + impl_->extent;
            if (!SegmentMeetsBox(orgIn, orgIn + dir * reach, dir, reach, layer->bounds)) {
                return false;
            }
        }
    } else if (set.interior.rtc && tmaxIn > 0) {
        // Between two points inside every bounding plane the bounding
        // polygons cannot be in the way (raycore/hull.h), nor, if the points
        // are on one side of it, the polygons in the light sources' plane
        // (raycore/source_plane.h).
        const Vec3 end = orgIn + dir * tmaxIn;
        if (impl_->bounding.Inside(orgIn) && impl_->bounding.Inside(end)) {
            layer = set.besideSources.rtc && impl_->sourcePlane->Clears(orgIn, end)
                        ? &set.besideSources
                        : &set.interior;
            // Most shadow rays in a room pass by its furniture: no need to
            // ask Embree.
            if (!SegmentMeetsBox(orgIn, end, dir, tmaxIn, layer->bounds)) return false;
        }
    }
    const Vec3 org = orgIn + dir * advance;
    const double tmax = tmaxIn > 0 ? tmaxIn - advance : 0.0;
    RTCRay ray;
    Impl::Query q = impl_->MakeQuery(org, dir, tmax, advance == 0 ? leaving : nullptr, ray);
    q.ignored = ignored;
    rtcOccluded1(layer->rtc, &q.rtc, &ray);
    return ray.tfar == -std::numeric_limits<float>::infinity();
}

}  // namespace rt
