// SPDX-License-Identifier: MIT
//
// Closest-hit and occlusion queries on a Scene, backed by Embree 3 (the only
// module that includes Embree; its types never appear in this header).
// Polygons become triangles, spheres/cones/cylinders/rings are Embree user
// geometry with exact analytic intersection. Each instanced octree and mesh
// file is one Embree scene, shared by all its instances through Embree
// instancing; hits in it are recomputed in its own (object) space. Embree finds the candidate in
// single precision; every reported hit is then recomputed in double precision
// against the original ray, so hit points are accurate at any scale and far
// from the origin. Distant sources are not geometry and are never reported.
//
//   RayCore core(scene);
//   if (auto hit = core.Intersect(org, dir, 0.0)) { ... hit->surface ... }
#pragma once

#include <iosfwd>
#include <memory>
#include <optional>
#include <vector>

#include "core/vecmath.h"
#include "scene/scene.h"

namespace rt {

struct Hit {
    double t = 0;      // distance along the unit ray direction
    Vec3 point;        // org + t·dir, computed in double
    Vec3 normal;       // unit geometric normal as the surface defines it (outward for a
                       // sphere, inward for a bubble, the polygon's normal, ...), not flipped
    /// Unit normal to shade with: `normal`, except on a mesh triangle whose
    /// three vertices have normals (their interpolation, radiance-functions.md §13.4).
    Vec3 shadingNormal;
    /// The hit surface: Scene::HitSurface(instance, surface) shades it.
    int instance = -1;   // index into Scene::instances; -1 for the scene's own surfaces
    int surface = -1;    // index into Scene::surfaces, or the instance prototype's surfaces
    int triangle = -1;   // mesh triangle (index into the prototype's mesh), -1 otherwise
    /// Mesh (u, v) interpolated at the hit when all three vertices have them; else 0.
    double u = 0, v = 0;

    /// Same surface (for tests such as "did the ray hit the floor again").
    bool SameSurface(const Hit& other) const {
        return instance == other.instance && surface == other.surface;
    }
};

/// For test failure messages.
std::ostream& operator<<(std::ostream& os, const Hit& hit);

/// True if a shadow ray that meets `surface` (one of `scene`'s surfaces, of
/// its prototypes' or an instance's override) may go on past it as shading/
/// follows shadow rays, whichever side it meets: its material is glass,
/// dielectric, interface, an illum (passed, or shown as its alternate) or a
/// trans with a specular transmission and no roughness, it is a mirror whose
/// alternate material transmits, it has no material but modifiers (a hole),
/// a mixture is among its modifiers, it is antimatter, or antimatter clips
/// its modifier (passed by rays inside the antimatter). A shadow ray that
/// meets any other surface returns black (back faces visible).
bool TransmitsShadowRays(const Scene& scene, const Surface& surface);

/// The surfaces an occlusion query looks at. shading/ follows a shadow ray
/// through the surfaces when a Transmitting one is in its way; otherwise an
/// Opaque one blocks it, and with neither it reaches its source.
enum class Occluders {
    All,
    Opaque,        // surfaces that do not transmit shadow rays, and instances with none
    Transmitting,  // surfaces that do, and every instance that has one
};

class RayCore {
public:
    /// Builds acceleration structures for the scene's surfaces (only the kinds
    /// present are created). The scene must outlive the RayCore. Throws rt::Error
    /// if Embree fails.
    explicit RayCore(const Scene& scene);
    ~RayCore();
    RayCore(const RayCore&) = delete;
    RayCore& operator=(const RayCore&) = delete;

    /// Nearest hit with tol < t and, when tmax > 0, t < tmax, where tol is the
    /// scene's Scene::distanceTolerance (Radiance's rule: distances <= FTINY
    /// are discarded). `dir` must be unit. Among hits within tol of each other, Radiance's coincidence rule picks the winner
    /// (material beats void, opaque beats transparent, later modifier wins).
    ///
    /// `leaving`, if given, is the unit normal (either way round) of the
    /// surface `org` lies on. Then a surface that meets that one at an angle
    /// (not coincident with it) is a hit also nearer than tol, down to the
    /// rounding of the scene's coordinates: a ray from a floor point within
    /// tol of a wall, towards the wall, hits the wall instead of passing
    /// through it and out of the room (Radiance's FTINY rule lets it through).
    /// Thread-safe.
    std::optional<Hit> Intersect(const Vec3& org, const Vec3& dir, double tmax,
                                 const Vec3* leaving = nullptr) const;

    /// Intersection with one of Scene::surfaces only (source rays aim at their source).
    std::optional<Hit> IntersectSurface(int surface, const Vec3& org, const Vec3& dir) const;

    /// IntersectSurface's distance, and whether the ray meets the surface's
    /// back (-Dot(dir, hit.normal) < 0, bit for bit), without the normal's
    /// cost when the side is certain without it.
    struct SurfaceSide {
        double t = 0;
        bool back = false;
    };
    std::optional<SurfaceSide> IntersectSurfaceSide(int surface, const Vec3& org,
                                                    const Vec3& dir) const;

    /// True if any of the surfaces `which` selects lies in (tol, tmax) along
    /// the ray (tmax <= 0: no limit). `ignored` (one of Scene::surfaces, or
    /// -1) is a surface the caller knows is not there, such as the light
    /// source a shadow ray stops short of: its test is skipped, which saves
    /// time and changes no answer. Thread-safe.
    /// `leaving` as for Intersect.
    bool Occluded(const Vec3& org, const Vec3& dir, double tmax,
                  Occluders which = Occluders::All, int ignored = -1,
                  const Vec3* leaving = nullptr) const;

    /// True if some surface or instance transmits shadow rays
    /// (TransmitsShadowRays); otherwise Occluders::Transmitting selects nothing.
    bool HasTransmitting() const;

    /// One query as the caller asked it (Intersect: occlusion false; each
    /// occlusion test Occluded makes: true), tmax as given (<= 0: none).
    struct LoggedQuery {
        Vec3 org, dir;
        double tmax = 0;
        bool occlusion = false;
    };
    /// Appends every later Intersect and occlusion query to `log` (null: stop).
    /// For lazyrad_bench, which replays the full calculation's own rays through
    /// raw Embree; not thread-safe, so for one thread only. Costs a query one
    /// predictable branch when off.
    void SetQueryLog(std::vector<LoggedQuery>* log) { log_ = log; }

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::vector<LoggedQuery>* log_ = nullptr;
};

}  // namespace rt
