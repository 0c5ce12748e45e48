// SPDX-License-Identifier: MIT
//
// Hand-built scenes for the raycore tests (the .rad loader is not used here):
// surfaces with geometry derived the way the loader derives it (§2.4).
#pragma once

#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/vecmath.h"
#include "scene/scene.h"

namespace rt::testing {

/// A direction uniformly distributed over the sphere.
inline Vec3 RandomDirection(std::mt19937& rng) {
    std::normal_distribution<double> g;
    for (;;) {
        const Vec3 v{g(rng), g(rng), g(rng)};
        if (LengthSquared(v) > 1e-6) return Normalize(v);
    }
}

/// Radiance's polygon set-up (face.c getface): normal from the fan of cross
/// products, area, and plane offset as the mean of Dot(normal, v).
inline Polygon MakePolygon(std::vector<Vec3> vertices) {
    Polygon p;
    p.vertices = std::move(vertices);
    Vec3 sum;
    for (size_t i = 2; i < p.vertices.size(); ++i) {
        sum += Cross(p.vertices[i - 1] - p.vertices[0], p.vertices[i] - p.vertices[0]);
    }
    p.area = Length(sum) / 2;
    p.normal = Normalize(sum);
    double offset = 0;
    for (const Vec3& v : p.vertices) offset += Dot(p.normal, v);
    p.offset = offset / static_cast<double>(p.vertices.size());
    return p;
}

/// Builder: each Add* returns the surface index.
class SceneBuilder {
  public:
    int AddMaterial(MaterialType type, const std::string& name = "m") {
        Material m;
        // Appending (not operator+ on a temporary) avoids GCC 12's false
        // -Wrestrict on std::string concatenation (GCC bug 105329).
        m.name = name;
        m.name.append(std::to_string(scene_.materials.size()));
        m.type = type;
        scene_.materials.push_back(m);
        return static_cast<int>(scene_.materials.size()) - 1;
    }
    int AddPolygon(std::vector<Vec3> vertices, int material = -1) {
        return Add(SurfaceType::Polygon, MakePolygon(std::move(vertices)), material);
    }
    int AddSphere(const Vec3& c, double r, bool bubble = false, int material = -1) {
        return Add(bubble ? SurfaceType::Bubble : SurfaceType::Sphere, Sphere{c, r, bubble},
                   material);
    }
    int AddCone(const Vec3& p0, const Vec3& p1, double r0, double r1, bool cup = false,
                int material = -1) {
        Cone c{p0, p1, r0, r1, cup};
        SurfaceType type = r0 == r1 ? (cup ? SurfaceType::Tube : SurfaceType::Cylinder)
                                    : (cup ? SurfaceType::Cup : SurfaceType::Cone);
        return Add(type, c, material);
    }
    int AddRing(const Vec3& c, const Vec3& n, double r0, double r1, int material = -1) {
        return Add(SurfaceType::Ring, Ring{c, Normalize(n), r0, r1}, material);
    }
    int AddSource(const Vec3& dir, double angleDegrees, int material = -1) {
        return Add(SurfaceType::Source, DistantSource{Normalize(dir), angleDegrees}, material);
    }
    /// Axis-aligned box [lo, hi] as six outward-facing quads.
    void AddBox(const Vec3& lo, const Vec3& hi, int material = -1) {
        auto v = [&](int i) {
            return Vec3{(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z};
        };
        AddPolygon({v(0), v(2), v(3), v(1)}, material);  // -z
        AddPolygon({v(4), v(5), v(7), v(6)}, material);  // +z
        AddPolygon({v(0), v(1), v(5), v(4)}, material);  // -y
        AddPolygon({v(2), v(6), v(7), v(3)}, material);  // +y
        AddPolygon({v(0), v(4), v(6), v(2)}, material);  // -x
        AddPolygon({v(1), v(3), v(7), v(5)}, material);  // +x
    }
    Scene& scene() { return scene_; }

  private:
    template <typename Shape>
    int Add(SurfaceType type, const Shape& shape, int material) {
        Surface s;
        s.name = "s";
        s.name.append(std::to_string(scene_.surfaces.size()));
        s.type = type;
        s.material = material;
        s.modifierName =
            material < 0 ? "void" : scene_.materials[static_cast<size_t>(material)].name;
        s.shape = shape;
        scene_.surfaces.push_back(std::move(s));
        return static_cast<int>(scene_.surfaces.size()) - 1;
    }
    Scene scene_;
};

}  // namespace rt::testing
