// SPDX-License-Identifier: MIT
//
// The scene as lazyrad uses it: Radiance's surfaces with their geometry
// resolved, and the materials they refer to (radiance-notes.md §2.3–2.8).
// Plain data; built by LoadScene() (scene/loader.h) from `.rad` files.
//
// Only what lazyrad can shade is represented: materials, the patterns
// brightfunc, colorfunc, brightdata, colordata, colorpict, brighttext and
// colortext, the textures texfunc and texdata, the mixtures mixfunc, mixdata,
// mixpict and mixtext. A scene using any other modifier type is rejected at
// load time with "file:line: unsupported material type 'X'".
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "cal/program.h"
#include "core/affine.h"
#include "core/conventions.h"
#include "core/error.h"
#include "core/rgb.h"
#include "core/vecmath.h"
#include "scene/data_file.h"
#include "scene/font.h"
#include "scene/bsdf_data.h"

namespace rt {

/// One primitive exactly as written in a scene file, before interpretation
/// (Radiance's OBJREC): `modifier type identifier`, string args, real args.
struct SceneObject {
    std::string modifier;               // "void" or a previously defined modifier
    std::string type;                   // "polygon", "plastic", "alias", ...
    std::string name;                   // identifier
    std::vector<std::string> sargs;     // string arguments (alias: the referenced name)
    std::vector<double> rargs;          // real arguments
    FileLoc loc;                        // where the primitive starts
};

/// Shading looks materials up in tables indexed by this (shading/materials.cpp).
enum class MaterialType {
    Plastic, Metal, Trans, Light, Illum, Glow, Spotlight, Mirror, Glass, Dielectric, Interface,
    Plastic2, Metal2, Trans2,
    PlasFunc, MetFunc, TransFunc, PlasData, MetData, TransData, BRTDFunc, Antimatter, Ashik2,
    Bsdf, ABsdf, Mist, Prism1, Prism2
};
inline constexpr std::size_t kMaterialTypeCount = 28;

// Each material's real arguments by name, read once at load time
// (radiance-notes.md §2.6). Colours are reflectances or transmittances in
// [0, 1] per channel, except light colours: radiance in W·sr⁻¹·m⁻².

/// plastic, metal (5 reals) and trans (7 reals), normal.c.
struct NormalParams {
    Rgb color;
    double specularity = 0;          // fraction of light reflected specularly
    double roughness = 0;            // RMS facet slope, 0 = polished
    double transmissivity = 0;       // trans: fraction of the non-specular part transmitted
    double transmittedSpecular = 0;  // trans: fraction of the transmitted part passed unscattered
};
/// light, illum, glow, spotlight.
struct LightParams {
    Rgb color;                       // emitted radiance
    double radius = 0;               // glow: maximum radius of influence (scene units)
    double coneAngleDegrees = 0;     // spotlight: full cone angle
    Vec3 aim;                        // spotlight: focus direction, not unit
};
struct MirrorParams {
    Rgb color;                       // reflectance
};
struct GlassParams {
    Rgb color;                       // transmissivity at normal incidence
    double index = 1.52;             // refractive index
};
/// dielectric (index n + Hartmann constant / 500 nm, outside vacuum) and interface.
struct DielectricParams {
    Rgb insideColor;                 // transmission per unit length inside
    double insideIndex = 1;
    Rgb outsideColor{1, 1, 1};       // interface only
    double outsideIndex = 1;
};
/// plastic2, metal2 (6 reals) and trans2 (8 reals), m_aniso.c: as
/// NormalParams with a facet slope along each of the surface's u and v
/// directions (u from the material's orientation function).
struct AnisoParams {
    Rgb color;
    double specularity = 0;
    double uRoughness = 0, vRoughness = 0;  // RMS facet slopes, both > FTINY
    double transmissivity = 0;              // trans2 only, as NormalParams
    double transmittedSpecular = 0;
};
/// plasfunc, metfunc, plasdata, metdata (4+ reals) and transfunc, transdata
/// (6+ reals), m_brdf.c's m_brdf2(): a diffuse part and a directional part
/// whose BRDF is the material's function; the reals beyond these are the
/// function's arguments (A5…, A7…).
struct BrdfParams {
    Rgb color;
    double specularity = 0;          // share of the reflection given by the function
    double transmissivity = 0;       // trans types only
    double transmittedSpecular = 0;  // share of the transmission given by the function
};
/// BRTDfunc (9+ reals, m_brdf.c's m_brdf()): diffuse reflectances of the
/// front and back and a diffuse transmittance; its specular and directional
/// parts are the material's function (the reals beyond are A10…).
struct BrtdParams {
    Rgb frontDiffuse, backDiffuse, diffuseTransmission;
};
/// ashik2 (8 reals, Radiance's ashikhmin.c): Ashikhmin and Shirley's
/// anisotropic Phong model, u from the material's orientation function.
struct AshikParams {
    Rgb diffuse;                     // diffuse reflectance, not reduced by the specular part
    Rgb specular;                    // specular reflectance at normal incidence (Schlick)
    double uPower = 0, vPower = 0;   // Phong exponents along u and v
};
/// antimatter (m_clip.c, no real arguments): the modifiers whose surfaces a
/// ray no longer sees once it has entered the antimatter's front.
struct ClipParams {
    /// Surface::modifierId of each modifier named, sorted, without repeats;
    /// the names are resolved as the antimatter is read (Radiance's lastmod()).
    std::vector<int> clipped;
};
/// BSDF and aBSDF (0, 3, 6 or 9 reals, m_bsdf.c): the scattering of a
/// BSDF file (scene/bsdf_data.h), plus diffuse parts the reals add.
struct BsdfParams {
    Rgb frontDiffuse, backDiffuse;   // added reflectances, front and back
    Rgb diffuseTransmission;         // added transmittance
    std::shared_ptr<const BsdfData> data;  // set by the scene builder
    /// Radiance's isBSDFproxy(): a BSDF whose thickness is not written "0"
    /// (what -i and the leak test pass, whatever the thickness evaluates to).
    bool proxy = false;
};
/// mist (0 to 7 reals, m_mist.c): the boundary of a volume whose inside
/// adds `extinction` (per unit length, times the mist's pattern colour) to
/// the medium a ray travels through, may set its scattering albedo and
/// Henyey–Greenstein eccentricity, and lists the light sources whose light
/// it scatters into rays (radiance-notes.md §2.5, §2.8). Radiance reads as
/// many of the reals as are given: three or more set the extinction, six or
/// more the albedo, seven the eccentricity.
struct MistParams {
    Rgb extinction;             // zero with fewer than three reals
    std::optional<Rgb> albedo;  // the scattering share of the extinction
    std::optional<double> eccentricity;  // g of the phase function, in (-1, 1)
    /// The source names as written: a source's surface name, or for a
    /// source seen in a mirror `relay>source` (one relay per '>'); resolved
    /// against the scene's light sources when shading is set up.
    std::vector<std::string> sourceNames;
};
/// prism1, prism2 (m_direct.c): light redirected by the material's function
/// (Material::function) into `projections` directions, each with its own
/// coefficient; all the reals are the function's arguments A1….
struct PrismParams {
    int projections = 1;
};
using MaterialParams = std::variant<NormalParams, LightParams, MirrorParams, GlassParams,
                                    DielectricParams, AnisoParams, BrdfParams, BrtdParams,
                                    ClipParams, AshikParams, BsdfParams, MistParams, PrismParams>;

/// The named parameters of a material of `type` from its real arguments, whose
/// count the caller has checked against radiance-notes.md §2.6.
MaterialParams MakeMaterialParams(MaterialType type, const std::vector<double>& args);

/// Solid angle (sr) of a spotlight's cone of full angle `coneAngleDegrees`:
/// 2π(1 − cos(angle/2)), Radiance's spotlight size.
inline double SpotSolidAngle(double coneAngleDegrees) {
    return 2.0 * kPi * (1.0 - std::cos(kPi / 180.0 / 2.0 * coneAngleDegrees));
}

/// Radiance's spotout(): true when light leaving a spotlight against `dir`
/// (unit, the direction from the lit point or ray toward the light) falls
/// outside the cone of `solidAngle` (sr) around `aim` (unit).
inline bool OutsideSpot(double solidAngle, const Vec3& aim, const Vec3& dir) {
    return solidAngle < 2.0 * kPi * (1.0 + Dot(aim, dir));
}

/// A material. Argument counts are validated at load time against
/// radiance-notes.md §2.6.
struct Material {
    std::string name;           // identifier; for an alias with its own modifier, the alias name
    MaterialType type;
    std::vector<double> args;   // real arguments as written
    MaterialParams params;      // the same, named: what shading reads
    int alternate = -1;         // illum/mirror alternate material (index), -1 for none or void
    /// The modifiers of the material's own chain (Radiance's
    /// raytexture(m->omod)), indices into Scene::patterns in chain order.
    /// Mixtures on it never reach a material ("conflicting material").
    std::vector<int> patterns;
    /// The material's own function, an index into Scene::patterns on no
    /// modifier chain; -1 for types without one. plastic2, metal2, trans2:
    /// the u direction (`ux uy uz funcfile [xf]`, PatternType::Orientation);
    /// plasfunc, metfunc, transfunc: the BRDF (`func funcfile [xf]`,
    /// PatternType::Brdf, the function in data.functions); plasdata,
    /// metdata, transdata: the same with data (`func datafile funcfile
    /// x1…xn [xf]`, the coordinates as values). BRTDfunc (PatternType::
    /// Brtd): `rrefl grefl
    /// brefl rtrns gtrns btrns rbrtd gbrtd bbrtd funcfile [xf]`, the six
    /// expressions as values, the three functions in data.functions (slot
    /// -1 for a name starting with '0': zero, as in Radiance). BSDF: `thick
    /// ux uy uz funcfile [xf]` (the file's name left out), aBSDF `ux uy uz
    /// funcfile [xf]` (PatternType::Orientation, four or three values).
    /// prism1 `coef dx dy dz funcfile [xf]`, prism2 the same twice before
    /// the file (PatternType::Redirect, four or eight values).
    int function = -1;
    FileLoc loc;
};

enum class PatternType {
    BrightFunc, ColorFunc, BrightData, ColorData, ColorPict, TexFunc, TexData, MixFunc, MixData,
    MixPict, BrightText, ColorText, MixText,
    Orientation,  // an anisotropic material's u direction: a vector, turned as a texture's
    Brdf,         // a BRDF material's function, with or without data
    Brtd,         // BRTDfunc's six expressions and three functions (one per channel)
    Redirect,     // prism1/prism2: per direction a coefficient and a vector (4 or 8 values)
};

/// What a function modifier does to a ray (radiance-functions.md §11.1).
enum class ModifierKind {
    Pattern,  // multiplies the pattern colour pcol
    Texture,  // adds to the normal perturbation pert
    Mixture,  // shades the ray with two chains and blends them (§11.9)
};

/// A modifier chain from one modifier on, as Radiance's rayshade() walks it:
/// patterns, textures and mixtures in order, then the material ending it.
struct ModifierChain {
    std::vector<int> modifiers;  // indices into Scene::patterns, in chain order
    int material = -1;           // index into Scene::materials; -1: none (void)
};

/// brighttext, colortext and mixtext (radiance-functions.md §11.10): the
/// lines on their plane, in the space of the object they modify (an
/// instance's; they take no transform of their own), and what they
/// multiply the pattern colour by on and off the glyphs (mixtext: none, it
/// shades with its fore or back side).
struct TextPattern {
    TextBlock block;
    Vec3 anchor;                 // the upper left corner of the first character
    Rgb foreground, background;  // brighttext: grey
};

/// A function modifier (radiance-functions.md §11.2, §11.4, §11.8, §11.9):
/// function-language expressions evaluated at each hit in the modifier's own
/// space. A pattern multiplies the ray's pattern colour, a texture adds a
/// displacement to its normal perturbation, a mixture blends two chains; for
/// the *data and *pict patterns (§11.5, §11.7) the expressions are
/// coordinates in data looked up and mapped by named functions.
/// Compiled into Scene::functions at load time.
struct Pattern {
    std::string name;
    PatternType type;
    ModifierKind kind = ModifierKind::Pattern;
    std::string owner;                    // `brightfunc "name"`, for messages
    /// brightfunc: 1, colorfunc: r g b, texfunc: dx dy dz, mixfunc: the
    /// coefficient of `fore`; *data, *pict: the data coordinates.
    std::vector<cal::Expression> values;
    DataLookup data;                      // *data, *pict: the arrays and functions; empty otherwise
    std::vector<double> args;             // real arguments: arg(n), A1, …
    /// World to pattern space (the inverse of the transform arguments, §10.1);
    /// its scale is the positive factor S (mirrors do not make it negative).
    Transform patternFromWorld;
    /// The transform arguments themselves, pattern to world space (textures
    /// turn their displacement with it), scale positive as above.
    Transform worldFromPattern;
    /// mixfunc: the chains from its `fore` and `back` modifiers as defined
    /// before the mixture (empty for void).
    ModifierChain fore, back;
    /// The text patterns' lines and colours; null for the others, which
    /// evaluate `values`.
    std::shared_ptr<const TextPattern> text;
    FileLoc loc;
};

/// Returns Radiance's type name ("plastic", ...).
const char* MaterialTypeName(MaterialType type);
/// Radiance's istransp(): materials a coincident opaque surface wins against,
/// that -i passes, and that shadow rays may pass (trans, trans2, glass,
/// dielectric, interface, aBSDF; trans2 in fact never passes shadow rays).
bool IsTransparentType(MaterialType type);
/// light, illum, glow, spotlight.
bool IsLightType(MaterialType type);

/// Flat polygon, vertices counter-clockwise seen from the front (§2.4).
struct Polygon {
    std::vector<Vec3> vertices;  // n >= 3, a repeated closing vertex removed
    Vec3 normal;                 // unit, normalize(Σ (v[i-1]-v0)×(v[i]-v0))
    double area = 0;             // ½ |Σ ...|
    double offset = 0;           // plane: Dot(normal, p) == offset (mean over vertices)
};

/// sphere (outward normal) or bubble (inward normal).
struct Sphere {
    Vec3 center;
    double radius = 0;  // > 0
    bool inward = false;
};

/// cone/cup (r0 != r1) and cylinder/tube (r0 == r1); the surface between the two
/// end planes, open at both ends.
struct Cone {
    Vec3 p0, p1;        // axis end points, p0 != p1
    double r0 = 0, r1 = 0;  // radii at p0 and p1, >= 0, not both 0
    bool inward = false;    // cup/tube
};

/// Flat disc or annulus through `center` facing `normal`.
struct Ring {
    Vec3 center;
    Vec3 normal;        // unit
    double r0 = 0, r1 = 0;  // inner < outer
};

/// Radiance `source`: a distant disc, not part of the geometry (never in a BVH).
struct DistantSource {
    Vec3 direction;          // unit, towards the source
    double angleDegrees = 0; // full angular diameter
};

/// Instance and Mesh are not geometry: they are the pseudo-surfaces that shade
/// hits inside an instance or mesh whose own modifier replaces the inner
/// materials (and, for Mesh, the per-material surfaces of a mesh file), as
/// Radiance's hit object becomes the instance or the mesh (radiance-functions.md
/// §13.2, §13.4). Their shape is an empty Polygon.
enum class SurfaceType { Polygon, Sphere, Bubble, Cone, Cup, Cylinder, Tube, Ring, Source, Instance, Mesh };

/// Whether a top-level surface of `type` made of `m` is a light source of the
/// direct calculation (Radiance's marksources()): an emitting material, not
/// a glow without radius (except on a distant `source`), not black.
bool IsSourceMaterial(const Material& m, SurfaceType type);

/// Radiance's type name ("polygon", ...), for messages about a surface.
const char* SurfaceTypeName(SurfaceType type);

struct Surface {
    std::string name;
    SurfaceType type;
    std::string modifierName;   // immediate modifier as written ("void" if none) — rtrace -om
    /// The immediate modifier's definition, unique in the scene and its
    /// prototypes (an alias is a definition of its own, as in Radiance); -1
    /// for void. Antimatter clips surfaces by it (ClipParams).
    int modifierId = -1;
    int material = -1;          // index into Scene::materials after aliases; -1 for void
    /// Modifiers between the surface and its material (a chain such as
    /// `m light l; l brightfunc b; b polygon p`), indices into Scene::patterns;
    /// the material's own chain is Material::patterns. A mixture that can
    /// reach a material ends the chain (`material` is then -1).
    std::vector<int> patterns;
    std::variant<Polygon, Sphere, Cone, Ring, DistantSource> shape;
    FileLoc loc;
};

/// Triangles of a Radiance mesh file (`.rtm`, radiance-functions.md §13.3),
/// in mesh coordinates.
struct TriangleMesh {
    std::vector<Vec3> vertices;
    /// Per vertex, unit; (0,0,0) where a vertex has none. Empty: no normals.
    std::vector<Vec3> normals;
    /// Per vertex (u, v); empty when no vertex has them. hasUv per vertex.
    std::vector<std::array<double, 2>> uvs;
    std::vector<std::uint8_t> hasUv;
    struct Triangle {
        std::array<int, 3> v;  // indices into vertices, counter-clockwise seen from the front
        int surface = -1;      // the Prototype's pseudo-surface for the triangle's material
    };
    std::vector<Triangle> triangles;
};

/// Geometry in its own coordinates, placed in the scene by instances: the
/// contents of an octree that `instance` primitives name, or of a mesh file
/// that `mesh` primitives name. Loaded once per file name as written.
struct Prototype {
    std::string file;
    /// Surfaces in object coordinates, their materials indices into
    /// Scene::materials. A light material here never makes a light source
    /// (radiance-functions.md §13.1). For a mesh: one pseudo-surface
    /// (SurfaceType::Mesh) per material its triangles use.
    std::vector<Surface> surfaces;
    std::shared_ptr<const TriangleMesh> mesh;  // null for an octree
    /// The octree's or the mesh's cube: placed, its 8 corners bound the instance.
    Vec3 cubeOrigin;
    double cubeSize = 0;
};

/// One placement of a Prototype in the scene. Instances nested in instanced
/// octrees are flattened: each is placed here with its composed transform.
struct Instance {
    std::string name;             // the instance/mesh primitive's identifier
    int prototype = -1;           // index into Scene::prototypes
    /// Object to world (row vectors, radiance-notes' Ff), its scale the
    /// positive uniform factor (a mirror keeps |scale|, as Radiance does).
    Transform renderFromObject;
    Transform objectFromRender;   // the inverse (Fb)
    /// Set when a modifier other than void replaces every inner material: the
    /// pseudo-surface (SurfaceType::Instance or Mesh) that shades all hits.
    std::optional<Surface> override;
    /// Where the overriding modifier's patterns are evaluated: the space the
    /// overriding placement was made in. Null for world space.
    std::optional<Transform> overrideFromRender;
    FileLoc loc;
};

struct Scene {
    std::vector<Material> materials;
    std::vector<Pattern> patterns;
    /// The function language holding every pattern's files and expressions;
    /// null when the scene has no patterns. Read-only once built: each
    /// shading thread evaluates with its own cal::Context.
    std::shared_ptr<const cal::Program> functions;
    std::vector<Surface> surfaces;   // in file order; includes distant sources
    std::vector<Prototype> prototypes;
    std::vector<Instance> instances;
    /// oconv's cube (§2.2): bounding box of all non-source surfaces grown by
    /// 1e-5 each side; `cubeSize` is its largest extent. Drives -ar and miss distances.
    Vec3 cubeOrigin;
    double cubeSize = 0;
    /// Header lines of the octree the scene came from (between "#?RADIANCE"
    /// and FORMAT): rtrace copies them into its output header. Empty for .rad input.
    std::vector<std::string> headerLines;
    /// Radiance's FTINY used as a length: hits nearer than this are the surface
    /// the ray starts on, and hits this close together coincide. Radiance's
    /// absolute 1e-6 assumes scenes of about unit size; BuildScene scales it
    /// down with scenes smaller than one unit (but keeps it well above the
    /// double-precision spacing of their coordinates), so a model drawn at
    /// 1e-4 behaves as at 1. Scenes of unit size or more keep exactly kFtiny.
    double distanceTolerance = kFtiny;
    /// Every Surface::modifierId some antimatter names (ClipParams), sorted:
    /// surfaces with one of these may be passed by rays, shadow rays included.
    std::vector<int> clippedModifiers;

    /// Whether some antimatter clips surfaces modified by `modifierId`.
    bool MayBeClipped(int modifierId) const {
        return modifierId >= 0 && std::binary_search(clippedModifiers.begin(),
                                                     clippedModifiers.end(), modifierId);
    }

    /// distanceTolerance / kFtiny, in (0, 1]: the factor applied to Radiance's
    /// other absolute lengths (the -I offsets, the ambient "behind" margin).
    double ToleranceScale() const { return distanceTolerance / kFtiny; }

    /// The surface that shades a hit on `surface` of `instance` (-1: a
    /// surface of the scene itself): the instance's override if it has one.
    const Surface& HitSurface(int instance, int surface) const {
        if (instance < 0) return surfaces[static_cast<std::size_t>(surface)];
        const Instance& in = instances[static_cast<std::size_t>(instance)];
        if (in.override) return *in.override;
        return prototypes[static_cast<std::size_t>(in.prototype)]
            .surfaces[static_cast<std::size_t>(surface)];
    }

    /// The space a hit's patterns are evaluated in, before their own
    /// transforms: the instance's object space when the inner materials
    /// shade it, the overriding placement's space otherwise. Null for world.
    const Transform* PatternSpace(int instance) const {
        if (instance < 0) return nullptr;
        const Instance& in = instances[static_cast<std::size_t>(instance)];
        if (in.override) return in.overrideFromRender ? &*in.overrideFromRender : nullptr;
        return &in.objectFromRender;
    }
};

/// World bounds of an instance: its prototype's cube, placed (the 8 corners
/// transformed, as oconv bounds instances).
Bounds3 InstanceBounds(const Scene& scene, const Instance& instance);

/// Axis-aligned bounds of a surface's geometry (empty for a distant source).
Bounds3 SurfaceBounds(const Surface& surface);

}  // namespace rt
