// SPDX-License-Identifier: MIT
//
// Builds small Scenes by hand for tests of modules above scene/, so they do
// not depend on the parser.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace rt::testing {

class SceneBuilder {
public:
    /// Adds a material and returns its index.
    int AddMaterial(const std::string& name, MaterialType type, std::vector<double> args) {
        Material m;
        m.name = name;
        m.type = type;
        m.args = std::move(args);
        m.params = MakeMaterialParams(type, m.args);
        scene_.materials.push_back(m);
        return static_cast<int>(scene_.materials.size()) - 1;
    }

    /// Adds a polygon (vertices counter-clockwise seen from the front).
    int AddPolygon(const std::string& name, int material, std::vector<Vec3> vertices) {
        Polygon p;
        Vec3 sum;
        for (size_t i = 2; i < vertices.size(); ++i) {
            sum += Cross(vertices[i - 1] - vertices[0], vertices[i] - vertices[0]);
        }
        p.area = 0.5 * Length(sum);
        p.normal = Normalize(sum);
        double off = 0;
        for (const Vec3& v : vertices) off += Dot(p.normal, v);
        p.offset = off / static_cast<double>(vertices.size());
        p.vertices = std::move(vertices);
        return AddSurface(name, SurfaceType::Polygon, material, p);
    }

    int AddSphere(const std::string& name, int material, Vec3 center, double radius,
                  bool inward = false) {
        return AddSurface(name, inward ? SurfaceType::Bubble : SurfaceType::Sphere, material,
                          Sphere{center, radius, inward});
    }

    int AddRing(const std::string& name, int material, Vec3 center, Vec3 normal, double r0,
                double r1) {
        return AddSurface(name, SurfaceType::Ring, material,
                          Ring{center, Normalize(normal), r0, r1});
    }

    int AddDistant(const std::string& name, int material, Vec3 direction, double angleDegrees) {
        return AddSurface(name, SurfaceType::Source, material,
                          DistantSource{Normalize(direction), angleDegrees});
    }

    /// The scene with oconv's cube computed from the surfaces.
    Scene Build() const {
        Scene s = scene_;
        Bounds3 b;
        for (const Surface& surf : s.surfaces) {
            if (surf.type != SurfaceType::Source) b.Extend(SurfaceBounds(surf));
        }
        if (b.Empty()) {
            s.cubeOrigin = Vec3(-0.5, -0.5, -0.5);
            s.cubeSize = 1;
            return s;
        }
        b.lo -= Vec3(1e-5, 1e-5, 1e-5);
        b.hi += Vec3(1e-5, 1e-5, 1e-5);
        Vec3 ext = b.hi - b.lo;
        s.cubeSize = std::max({ext.x, ext.y, ext.z});
        s.cubeOrigin = (b.lo + b.hi - Vec3(s.cubeSize, s.cubeSize, s.cubeSize)) * 0.5;
        return s;
    }

private:
    template <typename Shape>
    int AddSurface(const std::string& name, SurfaceType type, int material, const Shape& shape) {
        Surface s;
        s.name = name;
        s.type = type;
        s.material = material;
        s.modifierName = material >= 0 ? scene_.materials[material].name : "void";
        s.shape = shape;
        scene_.surfaces.push_back(s);
        return static_cast<int>(scene_.surfaces.size()) - 1;
    }

    Scene scene_;
};

}  // namespace rt::testing
