// SPDX-License-Identifier: MIT
#include "shading/light_sources.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/conventions.h"
#include "core/error.h"
#include "raycore/shapes.h"

namespace rt {
namespace {

// Partitions are addressed in units where the whole source spans
// [-kMaxParts, kMaxParts] along each size vector (Radiance's MAXSPART).
constexpr int kMaxParts = 64;

/// A cylinder source's samples lie this many radii off its axis (Radiance's
/// cylinder set-up).
constexpr double kCylinderSampleRadius = 0.8559;

using Partition = SourcePartition;

/// getperpendicular() with Radiance's optional randomisation: a random start
/// vector and axis order when `randomize`, else the fixed z, y, x scan.
Vec3 PerpendicularTo(const Vec3& n, bool randomize, Rng& rng) {
    if (!randomize) return Perpendicular(n);
    Vec3 v(0.5 - rng.Uniform(), 0.5 - rng.Uniform(), 0.5 - rng.Uniform());
    static constexpr int kOrders[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                          {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    const int* ord = kOrders[static_cast<int>(6 * rng.Uniform()) % 6];
    for (int i = 2; i >= 0; --i) {
        if (std::fabs(n[ord[i]]) < 0.6) {
            v[ord[i]] = 1.0;
            break;
        }
    }
    return Normalize(Cross(v, n));
}

/// Radiance's setflatss(): a square of the source's area, oriented by a
/// perpendicular of the normal.
void SetFlatSize(LightSource& src, bool randomFrames, Rng& rng) {
    src.size[0] = PerpendicularTo(src.normal, randomFrames, rng) * (0.5 * std::sqrt(src.area));
    src.size[1] = Cross(src.normal, src.size[0]);
    src.size[2] = Vec3();
}

/// The mean of a polygon's vertices (Radiance's centre of a face).
Vec3 VertexMean(const Polygon& poly) {
    Vec3 c;
    for (const Vec3& v : poly.vertices) c += v;
    return c / static_cast<double>(poly.vertices.size());
}

[[noreturn]] void SourceError(const Surface& s, const std::string& what) {
    ThrowUserError(s.loc, what + " for light source \"" + s.name + "\"");
}

void SetUpPolygon(LightSource& src, const Surface& s, bool randomFrames, Rng& rng) {
    const auto& poly = std::get<Polygon>(s.shape);
    if (poly.area <= 0) SourceError(s, "zero source area");
    const Vec3 c = VertexMean(poly);
    if (!PointInPolygon(poly, c)) SourceError(s, "cannot hit source center");
    src.shape = LightSource::Shape::Flat;
    src.location = c;
    src.normal = poly.normal;
    src.area = poly.area;
    double r2 = 0;
    for (const Vec3& v : poly.vertices) r2 = std::fmax(r2, LengthSquared(v - c));
    src.radius = std::sqrt(r2);
    if (poly.vertices.size() == 4) {  // a quad: sample along its own sides
        src.size[0] = (poly.vertices[1] - poly.vertices[0]) * 0.5;
        src.size[1] = (poly.vertices[3] - poly.vertices[0]) * 0.5;
        src.size[2] = Vec3();
        // Only for a true parallelogram do all samples lie on the source.
        const Vec3 skew = poly.vertices[0] + poly.vertices[2] - poly.vertices[1] - poly.vertices[3];
        src.parallelogram = Length(skew) <= 1e-9 * src.radius;
    } else {
        SetFlatSize(src, randomFrames, rng);
    }
}

void SetUpRing(LightSource& src, const Surface& s, bool randomFrames, Rng& rng) {
    const auto& ring = std::get<Ring>(s.shape);
    if (ring.r1 <= kFtiny) SourceError(s, "illegal source radius");
    if (ring.r0 > 0) SourceError(s, "cannot hit source center");
    src.shape = LightSource::Shape::Flat;
    src.circular = true;
    src.location = ring.center;
    src.normal = ring.normal;
    src.radius = ring.r1;
    src.area = kPi * ring.r1 * ring.r1;
    SetFlatSize(src, randomFrames, rng);
}

void SetUpSphere(LightSource& src, const Surface& s) {
    const auto& sphere = std::get<Sphere>(s.shape);
    if (sphere.radius <= kFtiny) SourceError(s, "illegal source radius");
    src.shape = LightSource::Shape::Sphere;
    src.circular = true;
    src.location = sphere.center;
    src.radius = sphere.radius;
    src.area = kPi * sphere.radius * sphere.radius;
    // 0.7236 r: the half-size of the cube whose sample points best cover a ball.
    src.size[0] = Vec3(0.7236 * sphere.radius, 0, 0);
    src.size[1] = Vec3(0, 0.7236 * sphere.radius, 0);
    src.size[2] = Vec3(0, 0, 0.7236 * sphere.radius);
}

void SetUpCylinder(LightSource& src, const Surface& s, const WarningSink& warn,
                   bool randomFrames, Rng& rng) {
    const auto& cyl = std::get<Cone>(s.shape);
    Vec3 axis = cyl.p1 - cyl.p0;
    double length = Length(axis);
    axis = axis / length;
    if (cyl.r0 <= kFtiny) SourceError(s, "illegal source radius");
    if (cyl.r0 > 0.2 * length && warn) {
        warn(s.loc.ToString() + ": source aspect too small for \"" + s.name + "\"");
    }
    src.shape = LightSource::Shape::Cylinder;
    src.location = (cyl.p0 + cyl.p1) * 0.5;
    src.radius = 0.5 * length;
    src.area = 2.0 * cyl.r0 * length;
    src.size[0] = axis * (0.5 * length);
    src.size[2] = PerpendicularTo(axis, randomFrames, rng) * (kCylinderSampleRadius * cyl.r0);
    src.size[1] = Cross(src.size[2], axis);
}

void SetUpDistant(LightSource& src, const Surface& s, bool randomFrames, Rng& rng) {
    const auto& d = std::get<DistantSource>(s.shape);
    double theta = kPi / 180.0 / 2.0 * d.angleDegrees;
    if (theta <= kFtiny) SourceError(s, "zero size");
    src.shape = LightSource::Shape::Distant;
    src.circular = true;
    src.location = d.direction;
    src.normal = d.direction;
    // Radiance keeps a source's solid angle in a float (SRCREC ss2), and its
    // cone test, 2π(1 − D·dir) <= Ω, uses that float: a 180° sky or ground
    // then takes every ray from about 3e-8 below its horizon up, so a level
    // view's horizontal rays see the sky. In double, 2π(1 − cos 90°) is a
    // hair below 2π and they would miss it.
    src.area = static_cast<float>(2.0 * kPi * (1.0 - std::cos(theta)));
    src.radius = std::sqrt(src.area / kPi);
    SetFlatSize(src, randomFrames, rng);
}

/// Radiance's flt_partit(): bisect along the longer (relative) side until the
/// cell looks small from `point`, emitting leaves in lower-then-upper order.
void PartitionFlat(const Vec3& point, int budget, const Vec3& centre, const Vec3& u,
                   const Vec3& v, double du2, double dv2, Partition cell,
                   std::vector<Partition>& out) {
    double d2 = LengthSquared(point - centre);
    if (budget < 2 || (d2 >= du2 && d2 >= dv2)) {
        out.push_back(cell);
        return;
    }
    int axis = du2 > dv2 ? 0 : 1;
    Vec3 half = (axis == 0 ? u : v) * 0.5;
    Vec3 nu = axis == 0 ? half : u;
    Vec3 nv = axis == 1 ? half : v;
    double ndu2 = axis == 0 ? du2 * 0.25 : du2;
    double ndv2 = axis == 1 ? dv2 * 0.25 : dv2;
    cell.size[axis] /= 2;
    Partition lower = cell, upper = cell;
    lower.center[axis] -= cell.size[axis];
    upper.center[axis] += cell.size[axis];
    PartitionFlat(point, budget / 2, centre - half, nu, nv, ndu2, ndv2, lower, out);
    PartitionFlat(point, budget / 2, centre + half, nu, nv, ndu2, ndv2, upper, out);
}

/// Radiance's cyl_partit(): slices along the axis.
void PartitionCylinder(const Vec3& point, int budget, const Vec3& centre, const Vec3& axis,
                       double d2, Partition cell, std::vector<Partition>& out) {
    if (budget < 2 || LengthSquared(point - centre) >= d2) {
        out.push_back(cell);
        return;
    }
    Vec3 half = axis * 0.5;
    cell.size[0] /= 2;
    Partition lower = cell, upper = cell;
    lower.center[0] -= cell.size[0];
    upper.center[0] += cell.size[0];
    PartitionCylinder(point, budget / 2, centre - half, half, d2 * 0.25, lower, out);
    PartitionCylinder(point, budget / 2, centre + half, half, d2 * 0.25, upper, out);
}

/// The partitions of one source seen from `point` (flatpart, cylpart, nopart).
void PartitionSource(const LightSource& src, const Vec3& point, double rayWeight,
                     double ratio, std::vector<Partition>& out) {
    const Partition whole{{0, 0, 0}, {kMaxParts, kMaxParts, kMaxParts}};
    if (ratio <= kFtiny) {
        out.push_back(whole);
        return;
    }
    switch (src.shape) {
        case LightSource::Shape::Sphere:
        case LightSource::Shape::Distant:
            out.push_back(whole);
            return;
        case LightSource::Shape::Flat: {
            if (Dot(point - src.location, src.normal) <= 0) return;  // behind the source
            double k = 2.0 * rayWeight / ratio;
            k *= k;
            PartitionFlat(point, kMaxParts, src.location, src.size[0], src.size[1],
                          k * LengthSquared(src.size[0]), k * LengthSquared(src.size[1]), whole,
                          out);
            return;
        }
        case LightSource::Shape::Cylinder: {
            Vec3 v = point - src.location;
            double axial2 = LengthSquared(src.size[0]);
            double along = Dot(v, src.size[0]);
            double centre2 = LengthSquared(v);
            double radial2 = centre2 - along * along / axial2;
            double rad2 = 1.365 * LengthSquared(src.size[1]);
            if (radial2 <= rad2) return;  // inside the extended cylinder
            double safe2 = axial2 * 4.0 * rayWeight * rayWeight / (ratio * ratio);
            if (radial2 <= 4.0 * rad2 || centre2 >= safe2) {
                out.push_back(whole);
                return;
            }
            PartitionCylinder(point, kMaxParts, src.location, src.size[0], safe2, whole, out);
            return;
        }
    }
}

}  // namespace

std::vector<LightSource> FindLightSources(const Scene& scene, const WarningSink& warn,
                                          bool randomFrames, Rng& rng) {
    std::vector<LightSource> sources;
    bool found = false;
    for (int i = 0; i < static_cast<int>(scene.surfaces.size()); ++i) {
        const Surface& s = scene.surfaces[i];
        if (s.material < 0) continue;
        const Material& m = scene.materials[s.material];
        if (!IsSourceMaterial(m, s.type)) continue;
        const LightParams& params = std::get<LightParams>(m.params);

        LightSource src;
        src.surface = i;
        src.material = s.material;
        src.patterned = !s.patterns.empty() || !m.patterns.empty();
        switch (s.type) {
            case SurfaceType::Polygon: SetUpPolygon(src, s, randomFrames, rng); break;
            case SurfaceType::Ring: SetUpRing(src, s, randomFrames, rng); break;
            case SurfaceType::Sphere: SetUpSphere(src, s); break;
            case SurfaceType::Cylinder: SetUpCylinder(src, s, warn, randomFrames, rng); break;
            case SurfaceType::Source: SetUpDistant(src, s, randomFrames, rng); break;
            default:
                ThrowUserError(s.loc, "illegal material \"" + m.name + "\" for " +
                                          "surface \"" + s.name + "\" (light sources must be " +
                                          "polygon, sphere, ring, cylinder or source)");
        }
        if (m.type == MaterialType::Glow) {
            src.proximity = true;
            src.proximityRadius = params.radius;
            if (src.shape == LightSource::Shape::Distant) src.skip = true;
        } else if (m.type == MaterialType::Spotlight &&
                   src.shape == LightSource::Shape::Distant) {
            // Radiance makes no spot of a distant source: it lights as a
            // plain distant light, after this warning.
            if (warn) {
                warn(s.loc.ToString() + ": distant source is a spotlight for \"" + s.name + "\"");
            }
        } else if (m.type == MaterialType::Spotlight) {
            // The scene builder has refused zero cone angles and zero focus
            // vectors (scene/build.cpp).
            src.spot = true;
            src.spotSolidAngle = SpotSolidAngle(params.coneAngleDegrees);
            Vec3 aim = params.aim;
            src.spotFocal = Length(aim);
            src.spotAim = aim / src.spotFocal;
            if (src.shape == LightSource::Shape::Flat) {
                // checkspot(): the cone must reach in front of the surface.
                double d = Dot(src.spotAim, src.normal);
                double d1 = 1.0 - src.spotSolidAngle / (2.0 * kPi);
                if (!(d > kFtiny || 1.0 - kFtiny - d * d < d1 * d1)) {
                    if (warn) warn(s.loc.ToString() + ": invalid spotlight direction for \"" +
                                   s.name + "\"");
                    src.skip = true;
                }
            }
        }
        if (!src.skip) found = true;
        sources.push_back(src);
    }
    if (!found && warn) warn("no light sources found");
    return sources;
}

namespace {

/// A relay's plane: unit normal n and offset od, Dot(n, p) == od on it.
struct Plane {
    Vec3 n;
    double od = 0;
};

/// The map a relay makes of space (Radiance's MAT4 from mirrorproj() or
/// dir_proj()): p -> p + g·(n·p − od), a shear along g of the points off
/// the plane, which g = −2n makes a reflection in it.
struct Projection {
    Plane plane;
    Vec3 g;
    bool mirror = false;  // g = −2n: lengths and angles kept
    Vec3 Point(const Vec3& p) const { return p + g * (Dot(plane.n, p) - plane.od); }
    Vec3 Vector(const Vec3& v) const { return v + g * Dot(plane.n, v); }
};

/// A relay surface: its plane and Radiance's bounding disc (fgetmaxdisk,
/// rgetmaxdisk: a polygon's vertex mean moved into its plane, and the
/// largest squared distance from it to a vertex; a ring's centre and outer
/// radius).
struct Relay {
    int surface = -1;
    int projections = 1;  // prism2: 2
    bool prism = false;
    Plane plane;
    Vec3 centre;
    double radius2 = 0;
};

bool MakeRelay(const Surface& s, int index, Relay& out) {
    out.surface = index;
    if (s.type == SurfaceType::Polygon) {
        const auto& poly = std::get<Polygon>(s.shape);
        out.plane = {poly.normal, poly.offset};
        const Vec3 c = VertexMean(poly);
        out.centre = c + poly.normal * (poly.offset - Dot(c, poly.normal));
        for (const Vec3& v : poly.vertices) {
            out.radius2 = std::fmax(out.radius2, LengthSquared(v - out.centre));
        }
        return poly.area > 0;
    }
    if (s.type == SurfaceType::Ring) {
        const auto& ring = std::get<Ring>(s.shape);
        out.plane = {ring.normal, Dot(ring.normal, ring.center)};
        out.centre = ring.center;
        out.radius2 = ring.r1 * ring.r1;
        return true;
    }
    return false;
}

/// Radiance's mirrorproj(): a mirror's reflection, for a source in front of it.
bool MirrorProjection(const LightSource& src, const Relay& relay, Projection& out) {
    const Plane& m = relay.plane;
    if (src.shape == LightSource::Shape::Distant ? Dot(src.location, m.n) <= kFtiny
                                                 : Dot(src.location, m.n) <= m.od + kFtiny) {
        return false;
    }
    out.plane = m;
    out.g = m.n * -2.0;
    out.mirror = true;
    return true;
}

/// Radiance's dir_proj(): prism `relay`'s redirection `n` of the light from
/// `src` toward the centre of its disc, as a shear (and a reflection when the
/// light leaves on the side it came from). False when that ray misses the
/// prism, meets its plane at a grazing angle, leaves along it, or the
/// function gives it no weight.
bool PrismProjection(const LightSource& src, const Relay& relay, int n,
                     const RedirectionProbe& probe, Projection& out) {
    Vec3 org, dir;
    if (src.shape == LightSource::Shape::Distant) {
        dir = -src.location;
        org = relay.centre - dir;
    } else {
        org = src.location;
        dir = relay.centre - src.location;
        const double d = Length(dir);
        if (d == 0) return false;  // at the source
        dir *= 1.0 / d;
    }
    const Plane& plane = relay.plane;
    const double oldDot = Dot(dir, plane.n);
    if (std::fabs(oldDot) <= kFtiny) return false;
    const std::optional<Vec3> newDir = probe(relay.surface, n, org, dir);
    if (!newDir) return false;
    const double newDot = Dot(*newDir, plane.n);
    if (std::fabs(newDot) <= kFtiny) return false;
    out.plane = plane;
    out.g = *newDir / newDot - dir / oldDot;
    if ((newDot > 0.0) != (oldDot > 0.0)) out.g -= plane.n * 2.0;  // back the way it came
    out.mirror = false;
    return true;
}

/// Radiance's makevsrc(): the image of `src` under `m`, relayed by `relay`,
/// or false when there is none.
bool MakeImage(const LightSource& src, int sn, const Relay& relay, const Projection& m,
               int projection, LightSource& image) {
    const bool distant = src.shape == LightSource::Shape::Distant;
    if (relay.radius2 <= kFtiny) return false;  // too small
    image = src;
    image.relay = relay.surface;
    image.relayProjection = projection;
    image.next = sn;
    image.surface = relay.surface;
    // A spotlight's image is a spotlight aimed at the projected direction,
    // its focal distance counted from the image. A shear changes lengths:
    // the normal and aim are made unit again, the size vectors keep what it
    // makes of them (the area stays the source's, as in Radiance).
    image.spotAim = m.Vector(src.spotAim);
    image.normal = m.Vector(src.normal);
    if (!m.mirror) {
        if (src.spot) image.spotAim = Normalize(image.spotAim);
        if (src.shape == LightSource::Shape::Flat) image.normal = Normalize(image.normal);
    }
    for (Vec3& v : image.size) v = m.Vector(v);
    if (distant) {
        image.location = Normalize(m.Vector(src.location));
        image.relayCentre = relay.centre;
        image.relayRadius2 = relay.radius2;
        return true;
    }
    image.location = m.Point(src.location);
    const Vec3 toRelay = relay.centre - image.location;
    if (src.proximity && LengthSquared(toRelay) > src.proximityRadius * src.proximityRadius) {
        return false;  // the relay lies beyond the glow's reach
    }
    const double d = Length(toRelay);
    if (d == 0) return false;
    image.relayAim = toRelay / d;
    // Every ray from a point of the image through the relay's disc: the cone
    // around a ball of the disc's radius plus the image's own extent, all
    // directions when the image's centre lies inside it. It only spares the
    // exact test of the relay (RelayValue), which decides.
    double extent = src.radius;
    if (src.shape == LightSource::Shape::Cylinder) {
        extent += Length(src.size[2]) / kCylinderSampleRadius;
    }
    const double reach = std::sqrt(relay.radius2) + extent;
    const double sine2 = reach * reach / (d * d);
    image.relayCone = sine2 >= 1.0 ? 4.0 * kPi : 2.0 * kPi * (1.0 - std::sqrt(1.0 - sine2));
    if (src.shape == LightSource::Shape::Flat) {
        // checkspot(): the relay's disc must reach in front of the image.
        const double c = Dot(image.relayAim, image.normal);
        const double c1 = 1.0 - image.relayCone / (2.0 * kPi);
        if (!(c > kFtiny || 1.0 - kFtiny - c * c < c1 * c1)) return false;
    }
    return true;
}

/// At most this many images in all, and this many reflections deep: facing
/// mirrors make images without end (a mirrored box at -dr 10 would make
/// millions), and each is sampled at every shading point.
constexpr std::size_t kMaxImages = 10000;
constexpr int kMaxRelays = 100;

/// Radiance's addvirtuals() and vproject(): images of source `sn` in every
/// relay but its own, and theirs, `depth` reflections deep. False when
/// `limit` stopped it.
bool AddImages(const std::vector<Relay>& relays, int sn, int depth, std::size_t limit,
               const RedirectionProbe& probe, std::vector<LightSource>& sources) {
    if (depth <= 0 || sources[sn].skip) return true;
    for (const Relay& relay : relays) {
        if (relay.surface == sources[sn].surface) continue;  // cannot image itself
        for (int n = 0; n < relay.projections; ++n) {
            Projection m;
            if (relay.prism ? !PrismProjection(sources[sn], relay, n, probe, m)
                            : !MirrorProjection(sources[sn], relay, m)) {
                continue;
            }
            LightSource image;
            if (!MakeImage(sources[sn], sn, relay, m, n, image)) continue;
            if (sources.size() >= limit) return false;
            sources.push_back(image);
            const int made = static_cast<int>(sources.size()) - 1;
            if (!AddImages(relays, made, depth - 1, limit, probe, sources)) return false;
        }
    }
    return true;
}

}  // namespace

const Material& RelayMaterial(const Scene& scene, const Surface& surface) {
    const Material& m = scene.materials[static_cast<std::size_t>(surface.material)];
    if (m.type == MaterialType::Illum && m.alternate >= 0) {
        return scene.materials[static_cast<std::size_t>(m.alternate)];
    }
    return m;
}

void AddVirtualSources(const Scene& scene, int relays, const WarningSink& warn,
                       const RedirectionProbe& probe, std::vector<LightSource>& sources) {
    if (relays <= 0) return;
    std::vector<Relay> mirrors;
    for (int i = 0; i < static_cast<int>(scene.surfaces.size()); ++i) {
        const Surface& s = scene.surfaces[i];
        if (s.material < 0) continue;
        const Material& material = RelayMaterial(scene, s);
        const bool prism =
            material.type == MaterialType::Prism1 || material.type == MaterialType::Prism2;
        if (material.type != MaterialType::Mirror && !prism) continue;
        Relay relay;
        relay.prism = prism;
        if (prism) relay.projections = std::get<PrismParams>(material.params).projections;
        if (MakeRelay(s, i, relay)) {
            mirrors.push_back(relay);
        } else if (s.type != SurfaceType::Polygon && warn) {
            warn(s.loc.ToString() + ": secondary sources not supported for " +
                 SurfaceTypeName(s.type) + " \"" + s.name + "\"");
        }
    }
    if (mirrors.empty()) return;
    // The deepest relay count up to -dr whose images all fit, so that the
    // answer is that of a smaller -dr rather than of an arbitrary cut. More
    // depth never makes fewer images, so the depth is found by bisection.
    const std::size_t real = sources.size();
    const auto fits = [&](int depth) {
        sources.resize(real);
        for (int sn = static_cast<int>(real) - 1; sn >= 0; --sn) {
            if (!AddImages(mirrors, sn, depth, real + kMaxImages, probe, sources)) return false;
        }
        return true;
    };
    int depth = std::min(relays, kMaxRelays);
    if (!fits(depth)) {
        int low = 0, high = depth;  // fits(low), not fits(high)
        while (high - low > 1) {
            const int mid = (low + high) / 2;
            (fits(mid) ? low : high) = mid;
        }
        depth = low;
        fits(depth);  // leave that depth's images
    }
    if (depth < relays && warn) {
        warn("-dr " + std::to_string(relays) + " makes more than " + std::to_string(kMaxImages) +
             " virtual sources; using -dr " + std::to_string(depth));
    }
}

namespace {

/// Radiance's nextssamp() for one partition `part` of source `sn` seen from
/// `point`: the sample's direction, distance and solid angle, false when
/// there is none (at the source, behind it or grazing, beyond a glow's
/// reach, outside a spotlight's cone or a relay's). `partitioned`: the
/// source has more than one partition. Inlined: as a call it cost 1.5 % of
/// a cached -ab 2 run's instructions (docs/measured-choices.md).
[[gnu::always_inline]] inline bool SamplePartition(const LightSource& src, int sn, const Partition& part, bool partitioned,
                     const Vec3& point, const DirectOptions& options, Rng& rng,
                     SourceSample& sample) {
    const bool flat = src.shape == LightSource::Shape::Flat;
    const bool distant = src.shape == LightSource::Shape::Distant;
    double vpos[3] = {0, 0, 0};
    if (options.jitter > kFtiny) {
        // Radiance draws these from its stratified urand() table; plain
        // uniform numbers have the same distribution.
        for (int i = 0; i < 3; ++i) {
            double x = (flat && i == 2) ? 0.5 : rng.Uniform();
            vpos[i] = options.jitter * (1.0 - 2.0 * x) * part.size[i] / kMaxParts;
        }
    }
    constexpr double kInvParts = 1.0 / kMaxParts;
    for (int i = 0; i < 3; ++i) vpos[i] += part.center[i] * kInvParts;
    if (src.circular && (partitioned || options.jitter > 0.7)) {
        // Squeeze the square's samples into the disc (or the cube's into
        // the ball) so they do not miss a round source.
        double trim[3];
        if (flat || distant) {
            double d = 1.12837917;  // sqrt(4/π): undoes setflatss()'s square
            trim[0] = d * std::sqrt(1.0 - 0.5 * vpos[1] * vpos[1]);
            trim[1] = d * std::sqrt(1.0 - 0.5 * vpos[0] * vpos[0]);
            trim[2] = 0.0;
        } else {
            double sum = 0, big = 0;
            for (double x : vpos) {
                sum += x * x;
                big = std::fmax(big, x * x);
            }
            double t = sum > kFtiny * kFtiny ? (1.0 / 0.7236) * std::sqrt(big / sum) : 0.0;
            trim[0] = trim[1] = trim[2] = t;
        }
        for (int i = 0; i < 3; ++i) vpos[i] *= trim[i];
    }
    Vec3 dir = src.location + src.size[0] * vpos[0] + src.size[1] * vpos[1];
    if (!flat) dir += src.size[2] * vpos[2];
    if (!distant) dir -= point;
    const double d = Length(dir);
    if (d == 0) return false;  // at the source
    dir *= 1.0 / d;

    double omega;
    if (flat) {
        omega = -Dot(dir, src.normal) * part.size[0] * part.size[1] /
                (double(kMaxParts) * kMaxParts);
    } else if (src.shape == LightSource::Shape::Cylinder) {
        double c = Dot(dir, src.size[0]);
        c *= c / LengthSquared(src.size[0]);
        omega = std::sqrt(std::fmax(0.0, 1.0 - c)) * part.size[0] / double(kMaxParts);
    } else {
        omega = double(part.size[0]) * part.size[1] * part.size[2] /
                (double(kMaxParts) * kMaxParts * kMaxParts);
    }
    sample.source = sn;
    sample.dir = dir;
    if (distant) {
        if (src.IsVirtual()) {
            // Only rays passing within the relay's disc (spotout()).
            const Vec3 toRelay = src.relayCentre - point;
            const double along = Dot(dir, toRelay);
            if (LengthSquared(toRelay) - along * along > src.relayRadius2) return false;
        }
        sample.omega = omega * src.area;
        sample.distance = kFhuge;
        return true;
    }
    if (omega <= 1e-4) return false;  // behind the source or grazing
    sample.omega = omega * src.area / (d * d);
    sample.distance = d;
    if (src.proximity && d > src.proximityRadius) return false;
    if (src.IsVirtual() && OutsideSpot(src.relayCone, src.relayAim, dir)) return false;
    if (src.spot) {
        if (OutsideSpot(src.spotSolidAngle, src.spotAim, dir)) return false;
        double df = d + src.spotFocal;
        sample.omega *= d * d / (df * df);
    }
    return true;
}

}  // namespace

void CollectSourceSamples(const std::vector<LightSource>& sources, const Vec3& point,
                          double rayWeight, const DirectOptions& options, Rng& rng,
                          std::vector<SourceSample>& out, std::vector<SourcePartition>& parts) {
    out.clear();
    for (int sn = 0; sn < static_cast<int>(sources.size()); ++sn) {
        const LightSource& src = sources[sn];
        if (src.skip) continue;
        parts.clear();
        PartitionSource(src, point, rayWeight, options.sampling, parts);
        const bool partitioned = parts.size() > 1;
        const std::size_t first = out.size();
        for (const Partition& part : parts) {
            SourceSample sample;
            if (SamplePartition(src, sn, part, partitioned, point, options, rng, sample)) {
                sample.whole = !partitioned;
                out.push_back(sample);
            }
        }
        if (out.size() == first + 1) out.back().alone = true;
    }
}

bool SampleWholeSource(const std::vector<LightSource>& sources, int source, const Vec3& point,
                       const DirectOptions& options, Rng& rng, SourceSample& sample) {
    const LightSource& src = sources[static_cast<std::size_t>(source)];
    if (src.skip) return false;
    const Partition whole{{0, 0, 0}, {kMaxParts, kMaxParts, kMaxParts}};
    if (!SamplePartition(src, source, whole, false, point, options, rng, sample)) return false;
    sample.whole = sample.alone = true;
    return true;
}

}  // namespace rt
