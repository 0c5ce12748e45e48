// SPDX-License-Identifier: MIT
//
// BuildScene(): what oconv and rtrace do with the objects readobj() returns —
// modifier and alias resolution (readobj.c, modobject.c), material argument
// checks (m_*.c), surface set-up (face.c, cone.c, o_sphere, srcsupp.c) and
// oconv's bounding cube (oconv.c, bbox.c).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>

#include "cal/ray_variables.h"
#include "core/conventions.h"
#include "core/huge_pages.h"
#include "scene/loader.h"
#include "scene/object_types.h"
#include "scene/mesh_file.h"
#include "scene/octree.h"
#include "scene/reader.h"
#include "scene/transform.h"
#include "cal/search.h"

namespace rt {
namespace {

/// oconv's OMARGIN: the cube is grown by this (times the tolerance scale) on
/// every side.
constexpr double kCubeMargin = 10 * kFtiny;

/// Scene::distanceTolerance for geometry of extent `size` whose coordinates
/// reach `maxCoordinate` in magnitude.
double DistanceTolerance(double size, double maxCoordinate) {
    const double floor = kCoordinateUlps * std::numeric_limits<double>::epsilon() * maxCoordinate;
    return std::max(std::min(kFtiny, kFtiny * size), floor);
}
/// Radiance's VERTEPS (double build): tolerated relative distance of a vertex
/// from the polygon's plane before "non-planar vertex" is reported.
constexpr double kVertexEpsilon = 1e-5;
/// A polygon whose doubled area is below this times its squared size is
/// degenerate (the triangulator's collinearity threshold too).
constexpr double kDegenerateArea = 1e-14;

/// The kinds of function a material carries of its own (Material::function).
enum class MaterialFunction {
    None,
    Orientation,  // plastic2, metal2, trans2: `ux uy uz funcfile [xf]`
    Brdf,         // plasfunc, metfunc, transfunc: `func funcfile [xf]`
    BrdfData,     // plasdata, metdata, transdata: `func datafile funcfile x1…xn [xf]`
    Brtd,         // BRTDfunc: six expressions, three functions, `funcfile [xf]`
    Bsdf,         // BSDF: `thick xmlfile ux uy uz funcfile [xf]`; aBSDF without thick
    Redirect,     // prism1: `coef dx dy dz funcfile [xf]`; prism2: two such quadruples
};

struct MaterialSpec {
    const char* name;
    MaterialType type;
    int minReals, maxReals;
    int maxStrings;  // illum/mirror take an optional alternate material
    MaterialFunction function = MaterialFunction::None;
};

/// Real arguments beyond the named ones are the BRDF function's (A5…).
constexpr int kAnyCount = std::numeric_limits<int>::max();

constexpr MaterialSpec kMaterialSpecs[] = {
    {"plastic", MaterialType::Plastic, 5, 5, 0},
    {"metal", MaterialType::Metal, 5, 5, 0},
    {"trans", MaterialType::Trans, 7, 7, 0},
    {"light", MaterialType::Light, 3, 3, 0},
    {"illum", MaterialType::Illum, 3, 3, 1},
    {"glow", MaterialType::Glow, 4, 4, 0},
    {"spotlight", MaterialType::Spotlight, 7, 7, 0},
    {"mirror", MaterialType::Mirror, 3, 3, 1},
    {"glass", MaterialType::Glass, 3, 4, 0},
    {"dielectric", MaterialType::Dielectric, 5, 5, 0},
    {"interface", MaterialType::Interface, 8, 8, 0},
    {"plastic2", MaterialType::Plastic2, 6, 6, 0, MaterialFunction::Orientation},
    {"metal2", MaterialType::Metal2, 6, 6, 0, MaterialFunction::Orientation},
    {"trans2", MaterialType::Trans2, 8, 8, 0, MaterialFunction::Orientation},
    {"ashik2", MaterialType::Ashik2, 8, 8, 0, MaterialFunction::Orientation},
    {"plasfunc", MaterialType::PlasFunc, 4, kAnyCount, 0, MaterialFunction::Brdf},
    {"metfunc", MaterialType::MetFunc, 4, kAnyCount, 0, MaterialFunction::Brdf},
    {"transfunc", MaterialType::TransFunc, 6, kAnyCount, 0, MaterialFunction::Brdf},
    {"plasdata", MaterialType::PlasData, 4, kAnyCount, 0, MaterialFunction::BrdfData},
    {"metdata", MaterialType::MetData, 4, kAnyCount, 0, MaterialFunction::BrdfData},
    {"transdata", MaterialType::TransData, 6, kAnyCount, 0, MaterialFunction::BrdfData},
    {"BRTDfunc", MaterialType::BRTDFunc, 9, kAnyCount, 0, MaterialFunction::Brtd},
    {"BSDF", MaterialType::Bsdf, 0, 9, 0, MaterialFunction::Bsdf},
    {"aBSDF", MaterialType::ABsdf, 0, 9, 0, MaterialFunction::Bsdf},
    // Its strings are modifier names (checked in SetClipped); m_clip.c reads
    // no real arguments and ignores any.
    {"antimatter", MaterialType::Antimatter, 0, kAnyCount, kAnyCount},
    // Its strings are light source names (resolved in shading/); m_mist.c
    // reads up to seven reals, as many as there are.
    {"mist", MaterialType::Mist, 0, 7, kAnyCount},
    // All their reals are the function's arguments.
    {"prism1", MaterialType::Prism1, 0, kAnyCount, 0, MaterialFunction::Redirect},
    {"prism2", MaterialType::Prism2, 0, kAnyCount, 0, MaterialFunction::Redirect},
};

/// Radiance's MAXSLIST: the most light sources one mist may name.
constexpr std::size_t kMaxMistSources = 32;

/// Radiance's MAXSET: the most modifiers one antimatter may name.
constexpr std::size_t kMaxClipped = 511;

const MaterialSpec* FindMaterialSpec(const std::string& type) {
    for (const MaterialSpec& spec : kMaterialSpecs) {
        if (type == spec.name) return &spec;
    }
    return nullptr;
}

std::string Describe(const SceneObject& object) {
    return object.type + " \"" + PrintableWord(object.name) + "\"";
}

/// One modifier definition, in file order. Mirrors Radiance's OBJREC enough to
/// walk modifier chains and to tell a pure alias synonym from an alias that
/// re-modifies its reference. Exactly one of material and pattern is set.
struct ModifierDef {
    int material = -1;  // index into Scene::materials
    int pattern = -1;   // index into Scene::patterns
    int modifier = -1;  // the definition's own modifier (index into defs), -1 = void
    int id = -1;        // Surface::modifierId of surfaces it modifies; set by Define()
};

/// The function modifiers lazyrad evaluates and the layout of their string
/// arguments (radiance-functions.md §11.2): `names` modifier names (mixfunc's
/// fore and back), `functions` function names, then `dataFiles` data files or
/// a picture, then the function file, then the expressions (-1: as many as the
/// first data file has dimensions), then an optional transform.
/// brightfunc `v file`, colorfunc `r g b file`, texfunc `dx dy dz file`,
/// mixfunc `fore back c file`, brightdata `f data file x1…xn`, colordata
/// `fr fg fb dr dg db file x1…xn`, colorpict `fr fg fb pict file u v`,
/// texdata `fx fy fz dx dy dz file x1…xn`, mixdata `fore back f data file
/// x1…xn`, mixpict `fore back f pict file u v`.
struct PatternSpec {
    const char* name;
    PatternType type;
    ModifierKind kind;
    int names;
    int expressions;
    int functions = 0;
    int dataFiles = 0;
    bool picture = false;
    /// The coordinates are names of functions of the light's direction
    /// (plasdata…), kept after the spec's own functions, not expressions.
    bool coordinateFunctions = false;
    /// A function name starting with '0' means none, the value 0 (BRTDfunc).
    bool zeroFunctions = false;
};
constexpr PatternSpec kPatternSpecs[] = {
    {"brightfunc", PatternType::BrightFunc, ModifierKind::Pattern, 0, 1},
    {"colorfunc", PatternType::ColorFunc, ModifierKind::Pattern, 0, 3},
    {"texfunc", PatternType::TexFunc, ModifierKind::Texture, 0, 3},
    {"mixfunc", PatternType::MixFunc, ModifierKind::Mixture, 2, 1},
    {"brightdata", PatternType::BrightData, ModifierKind::Pattern, 0, -1, 1, 1},
    {"colordata", PatternType::ColorData, ModifierKind::Pattern, 0, -1, 3, 3},
    {"colorpict", PatternType::ColorPict, ModifierKind::Pattern, 0, 2, 3, 1, true},
    {"texdata", PatternType::TexData, ModifierKind::Texture, 0, -1, 3, 3},
    {"mixdata", PatternType::MixData, ModifierKind::Mixture, 2, -1, 1, 1},
    {"mixpict", PatternType::MixPict, ModifierKind::Mixture, 2, 2, 1, 1, true},
};

/// A material's own function (MaterialFunction), its strings read as a
/// pattern's: an anisotropic material's as a texfunc's (three expressions,
/// the file, a transform); a BRDF function's as a brightdata's without data
/// (function, file, transform) or with it (function, data, file,
/// coordinates, transform).
constexpr PatternSpec kOrientationSpec = {"orientation", PatternType::Orientation,
                                          ModifierKind::Texture, 0, 3};
/// BSDF's thickness and up vector (aBSDF: kOrientationSpec), the strings
/// without the BSDF file's name.
constexpr PatternSpec kBsdfFrameSpec = {"bsdf", PatternType::Orientation, ModifierKind::Texture,
                                        0, 4};
constexpr PatternSpec kBrdfSpec = {"brdf", PatternType::Brdf, ModifierKind::Pattern, 0, 0, 1, 0};
constexpr PatternSpec kBrdfDataSpec = {"brdfdata", PatternType::Brdf, ModifierKind::Pattern,
                                       0, -1, 1, 1, false, true};
constexpr PatternSpec kBrtdSpec = {"brtd", PatternType::Brtd, ModifierKind::Pattern, 0, 6, 3,
                                   0, false, false, true};

/// prism1's coefficient and direction, prism2's two of each.
constexpr PatternSpec kRedirect1Spec = {"prism1", PatternType::Redirect, ModifierKind::Texture,
                                        0, 4};
constexpr PatternSpec kRedirect2Spec = {"prism2", PatternType::Redirect, ModifierKind::Texture,
                                        0, 8};

const PatternSpec* FindPatternSpec(const std::string& type) {
    for (const PatternSpec& spec : kPatternSpecs) {
        if (type == spec.name) return &spec;
    }
    return nullptr;
}

const char* PatternTypeName(PatternType type) {
    for (const PatternSpec& spec : kPatternSpecs) {
        if (spec.type == type) return spec.name;
    }
    switch (type) {
        case PatternType::BrightText: return "brighttext";
        case PatternType::ColorText: return "colortext";
        case PatternType::MixText: return "mixtext";
        default: return "unknown";
    }
}

/// An `instance` or `mesh` primitive as written, in the space of the scene
/// or of the instanced octree that holds it; flattened into Scene::instances
/// when the scene is finished.
struct Placement {
    std::string name;
    int prototype = -1;
    Transform outerFromObject;       // to the space the primitive is written in
    std::optional<Surface> override; // the primitive's own modifier, unless void
    FileLoc loc;
};

/// Nested placements beyond this many in all are refused: flattening
/// multiplies the counts of each level, and a few lines of scene can ask for
/// more instances than memory holds.
constexpr std::size_t kMaxInstances = 10'000'000;

/// Heap reserved in huge pages for a large scene (ReserveHeapInHugePages):
/// per object a scene announces (an octree's count), and per byte of scene
/// text where the count is unknown (an exported model's object takes some
/// 150 bytes of text). About 1 KiB of heap per object was measured to cover
/// the office of bench/big_scene.sh, lists and Embree's input included
/// (docs/measured-choices.md).
constexpr std::size_t kHeapPerObject = 1024;
constexpr std::uintmax_t kHeapPerTextByte = 8;

class SceneBuilder {
public:
    SceneBuilder(const WarningSink& warn, const SceneLoadOptions& options)
        : warn_(warn), options_(options) {}

    /// Room for `n` more surfaces: most objects of a large scene are.
    void ReserveSurfaces(std::size_t n) {
        const bool fresh = surfaces_->capacity() == 0;
        surfaces_->reserve(surfaces_->size() + n);
        if (fresh) {
            AdviseHugePages(*surfaces_);
            // A large scene's other blocks in huge pages too.
            ReserveHeapInHugePages(n * kHeapPerObject);
        }
    }

    /// A surface takes the object's strings; other objects are left as they were.
    void Add(SceneObject& object) {
        if (object.type == "alias") {
            AddAlias(object);
        } else if (FindPatternSpec(object.type) != nullptr) {
            AddPattern(object);
        } else if (IsTextType(object.type)) {
            AddTextPattern(object);
        } else if (!IsSurfaceObjectType(object.type)) {
            AddMaterial(object);
        } else {
            AddSurface(object);
        }
    }

    Scene Finish() {
        ResolvePendingClips();
        for (const Placement& p : topPlacements_) Flatten(p, Transform{}, nullptr, std::nullopt);
        SetCube();
        if (functions_) scene_.functions = std::move(functions_);
        return std::move(scene_);
    }

private:
    void Warn(const SceneObject& object, const std::string& what) const {
        if (warn_) warn_(object.loc.ToString() + ": " + Describe(object) + ": " + what);
    }
    [[noreturn]] void Fail(const SceneObject& object, const std::string& what) const {
        ThrowUserError(object.loc, Describe(object) + ": " + what);
    }
    [[noreturn]] void BadArgs(const SceneObject& object) const {
        ThrowUserError(object.loc, "bad number of arguments for " + Describe(object));
    }

    std::optional<int> Lookup(const std::string& name) const {
        const auto it = byName_.find(name);
        if (it == byName_.end()) return std::nullopt;
        return it->second;
    }

    /// Index of the modifier definition `name` refers to now; -1 for void.
    int ResolveModifier(const SceneObject& object) const {
        if (object.modifier == "void") return -1;
        const auto def = Lookup(object.modifier);
        if (!def) {
            ThrowUserError(object.loc,
                           "undefined modifier \"" + PrintableWord(object.modifier) + "\"");
        }
        return *def;
    }

    void Define(const std::string& name, ModifierDef def) {
        // Unique across the prototypes too, whose names are their own.
        def.id = nextModifierId_++;
        defs_.push_back(def);
        byName_[name] = static_cast<int>(defs_.size()) - 1;
    }

    void AddAlias(const SceneObject& object) {
        // The text reader always gives an alias its reference; a frozen
        // octree's objects come with whatever argument counts it holds.
        if (object.sargs.size() != 1 || !object.rargs.empty()) BadArgs(object);
        const std::string& reference = object.sargs[0];
        const auto ref = Lookup(reference);
        if (!ref) {
            ThrowUserError(object.loc, "undefined alias reference \"" + PrintableWord(reference) +
                                           "\" in alias \"" + PrintableWord(object.name) + "\"");
        }
        const ModifierDef target = defs_[static_cast<std::size_t>(*ref)];
        const int modifier = object.modifier == "inherit" ? target.modifier : ResolveModifier(object);
        if (modifier == target.modifier) {
            // Pure synonym (readobj.c): shading goes straight to the reference.
            Define(object.name, target);
            return;
        }
        // Same type and arguments as the reference, under the alias's own name,
        // with its own modifier (radiance-functions.md §11.12).
        if (target.pattern >= 0) {
            Pattern copy = scene_.patterns[static_cast<std::size_t>(target.pattern)];
            copy.name = object.name;
            copy.loc = object.loc;
            CheckMixtureModifier(object, copy, modifier);
            scene_.patterns.push_back(std::move(copy));
            Define(object.name,
                   ModifierDef{-1, static_cast<int>(scene_.patterns.size()) - 1, modifier});
            return;
        }
        Material copy = scene_.materials[static_cast<std::size_t>(target.material)];
        copy.name = object.name;
        copy.loc = object.loc;
        copy.patterns = MaterialChain(object, modifier);
        scene_.materials.push_back(std::move(copy));
        Define(object.name,
               ModifierDef{static_cast<int>(scene_.materials.size()) - 1, -1, modifier});
    }

    /// The patterns of a material's own modifier chain from definition `def`
    /// on, in chain order. A material on that chain is Radiance's fatal
    /// "conflicting material".
    std::vector<int> MaterialChain(const SceneObject& object, int def) const {
        std::vector<int> patterns;
        for (int d = def; d != -1; d = defs_[static_cast<std::size_t>(d)].modifier) {
            const ModifierDef& m = defs_[static_cast<std::size_t>(d)];
            if (m.material >= 0) {
                ThrowUserError(object.loc,
                               "conflicting material \"" +
                                   PrintableWord(scene_.materials[static_cast<std::size_t>(m.material)].name) +
                                   "\" in the modifiers of " + Describe(object));
            }
            // A mixture that shades with a material is one too (raytexture()).
            const Pattern& p = scene_.patterns[static_cast<std::size_t>(m.pattern)];
            if (p.kind == ModifierKind::Mixture && ReachesMaterial(p)) {
                ThrowUserError(object.loc, "conflicting material \"" + PrintableWord(p.name) +
                                               "\" in the modifiers of " + Describe(object));
            }
            patterns.push_back(m.pattern);
        }
        return patterns;
    }

    /// The chain rayshade() walks from definition `def` on (-1: void, an
    /// empty chain): modifiers until the first material.
    ModifierChain ChainFrom(int def) const {
        ModifierChain chain;
        for (int d = def; d != -1; d = defs_[static_cast<std::size_t>(d)].modifier) {
            const ModifierDef& m = defs_[static_cast<std::size_t>(d)];
            if (m.material >= 0) {
                chain.material = m.material;
                break;
            }
            chain.modifiers.push_back(m.pattern);
        }
        return chain;
    }

    /// Whether shading `mixture` can end at a material on either side (else
    /// it only ever acts as a pattern/texture, §11.9).
    bool ReachesMaterial(const Pattern& mixture) const {
        for (const ModifierChain* chain : {&mixture.fore, &mixture.back}) {
            if (chain->material >= 0) return true;
            for (const int index : chain->modifiers) {
                const Pattern& p = scene_.patterns[static_cast<std::size_t>(index)];
                if (p.kind == ModifierKind::Mixture && ReachesMaterial(p)) return true;
            }
        }
        return false;
    }

    /// A mixture that shades with materials ends the chain, so it must have
    /// no modifier of its own (Radiance checks when it first reaches one;
    /// here at load).
    void CheckMixtureModifier(const SceneObject& object, const Pattern& pattern,
                              int modifier) const {
        if (pattern.kind == ModifierKind::Mixture && modifier != -1 && ReachesMaterial(pattern)) {
            // Named by its type even when it is an alias's copy, as Radiance does.
            ThrowUserError(object.loc, std::string("inappropriate modifier for ") +
                                           PatternTypeName(pattern.type) + " \"" +
                                           PrintableWord(object.name) + "\"");
        }
    }

    /// The function language, set up at the first pattern: rtrace's ray
    /// variables and rayinit.cal (RAYPATH, else lazyrad's own).
    cal::Program& Functions() {
        if (!functions_) {
            cal::Options options;
            // $28… for BRDF materials, $35… for prisms
            options.channelCount = cal::kRedirectChannelCount;
            functions_ = std::make_shared<cal::Program>(options, warn_);
            functions_->DefineRayVariables();
            functions_->LoadRayinit(searchPath_);
        }
        return *functions_;
    }

    void AddPattern(const SceneObject& object) {
        Pattern pattern = MakePattern(object, *FindPatternSpec(object.type));
        const int modifier = ResolveModifier(object);
        CheckMixtureModifier(object, pattern, modifier);
        scene_.patterns.push_back(std::move(pattern));
        Define(object.name, ModifierDef{-1, static_cast<int>(scene_.patterns.size()) - 1, modifier});
    }

    /// A modifier of `type` named and located as `object`, with its reals.
    static Pattern NewPattern(const SceneObject& object, PatternType type, ModifierKind kind) {
        Pattern pattern;
        pattern.name = object.name;
        pattern.type = type;
        pattern.kind = kind;
        pattern.owner = Describe(object);
        pattern.args = object.rargs;
        pattern.loc = object.loc;
        return pattern;
    }

    /// The function modifier `object` describes by the layout of `spec`: its
    /// data, transform and mixture sides, its expressions compiled.
    Pattern MakePattern(const SceneObject& object, const PatternSpec& spec) {
        const auto& words = object.sargs;
        const std::string where = object.loc.ToString();
        Pattern pattern = NewPattern(object, spec.type, spec.kind);
        std::size_t expressions = static_cast<std::size_t>(std::max(spec.expressions, 0));
        const bool hasData = spec.dataFiles > 0 || spec.picture;
        const std::size_t names = static_cast<std::size_t>(spec.names);
        // Names, function names and data files come before the file; so do
        // the expressions of a modifier without data.
        const std::size_t fileAt = names + static_cast<std::size_t>(spec.functions + spec.dataFiles) +
                                   (hasData ? 0 : expressions);
        std::size_t exprAt = names;
        if (!hasData) {
            if (words.size() < fileAt + 1) BadArgs(object);
        } else {
            // Radiance loads the data before anything else: its dimensions
            // are the number of coordinate expressions.
            exprAt = fileAt + 1;
            if (words.size() < exprAt + (spec.picture ? 2 : 1)) BadArgs(object);
            LoadData(spec, object, pattern.data);
            if (!spec.picture) {
                expressions = static_cast<std::size_t>(pattern.data.arrays[0]->dimensions());
            }
            if (words.size() < exprAt + expressions) {
                Fail(object, "too few string arguments (" + std::to_string(expressions) +
                                 " coordinates for the data's dimensions)");
            }
        }
        // The transform: the first word after the expressions and the file
        // that starts with '-', and everything after it (words in between are
        // ignored, §10.2).
        std::size_t xfAt = hasData ? exprAt + expressions : fileAt + 1;
        while (xfAt < words.size() && words[xfAt].rfind('-', 0) != 0) ++xfAt;
        if (xfAt < words.size()) {
            const ParsedTransform xf = ParseTransformArgs(words, xfAt);
            if (xf.next != words.size()) {
                ThrowUserError(object.loc, "bad transform for " + Describe(object));
            }
            pattern.worldFromPattern = xf.transform;
            pattern.worldFromPattern.scale = std::fabs(pattern.worldFromPattern.scale);
            pattern.patternFromWorld = Inverse(xf.transform);
            pattern.patternFromWorld.scale = std::fabs(pattern.patternFromWorld.scale);
        }
        if (spec.kind == ModifierKind::Mixture) ResolveMixtureSides(object, pattern);
        cal::Program& functions = Functions();
        const std::string context = functions.LoadFile(words[fileAt], searchPath_, where);
        if (!spec.coordinateFunctions) {
            for (std::size_t k = 0; k < expressions; ++k) {
                pattern.values.push_back(functions.CompileExpression(
                    words[exprAt + k], where + ": " + pattern.owner, context));
            }
        }
        const std::size_t functionCount = static_cast<std::size_t>(spec.functions) +
                                          (spec.coordinateFunctions ? expressions : 0);
        for (std::size_t k = 0; k < functionCount; ++k) {
            // The function names follow the names (with data) or the
            // expressions (without); a *data BRDF's coordinates follow them.
            const std::size_t at = k < static_cast<std::size_t>(spec.functions)
                                       ? names + (hasData ? 0 : expressions) + k
                                       : exprAt + k - static_cast<std::size_t>(spec.functions);
            const std::string& name = words[at];
            if (spec.zeroFunctions && name[0] == '0') {
                pattern.data.functions.push_back(cal::Function{});
                pattern.data.argCounts.push_back(1);
                continue;
            }
            const std::optional<cal::Function> f = functions.FindFunction(name, context);
            if (!f) {
                ThrowUserError(object.loc, pattern.owner + ": " + PrintableWord(name) +
                                               ": undefined function");
            }
            pattern.data.functions.push_back(*f);
            // texdata and mixpict always give their functions all three
            // values; colordata and colorpict a function of three or more
            // parameters all three, others their own channel's (§11.2).
            const bool allThree = spec.type == PatternType::TexData ||
                                  spec.type == PatternType::MixPict ||
                                  (spec.functions == 3 && functions.Arity(*f) >= 3);
            pattern.data.argCounts.push_back(allThree ? 3 : 1);
        }
        return pattern;
    }

    /// A mixture's `fore` and `back` chains from its first two strings: each
    /// the last definition of its name before the mixture (lastmod()), or
    /// void.
    void ResolveMixtureSides(const SceneObject& object, Pattern& pattern) const {
        const auto& words = object.sargs;
        ModifierChain* sides[2] = {&pattern.fore, &pattern.back};
        for (std::size_t k = 0; k < 2; ++k) {
            if (words[k] == "void") continue;
            const auto def = Lookup(words[k]);
            if (!def) {
                ThrowUserError(object.loc, "undefined modifier \"" + PrintableWord(words[k]) +
                                               "\" for " + Describe(object));
            }
            *sides[k] = ChainFrom(*def);
        }
    }

    /// brighttext `font textfile` or `font . words…` with 11 reals (anchor,
    /// right, down, foreground and background factors) and an optional
    /// spacing; colortext the same with colours (15 reals); mixtext `fore
    /// back font …` with 9 (text.c). Radiance reads the text and the font at
    /// the first ray that meets the pattern; here when the scene loads.
    void AddTextPattern(const SceneObject& object) {
        const bool mix = object.type == "mixtext";
        const bool colour = object.type == "colortext";
        const std::size_t fontAt = mix ? 2 : 0;
        const std::size_t textAt = fontAt + 1;
        const std::size_t reals = mix ? 9 : colour ? 15 : 11;
        const auto& words = object.sargs;
        const auto& a = object.rargs;
        if (words.size() < textAt + 1 || a.size() < reals) BadArgs(object);
        Pattern pattern = NewPattern(object,
                                     mix      ? PatternType::MixText
                                     : colour ? PatternType::ColorText
                                              : PatternType::BrightText,
                                     mix ? ModifierKind::Mixture : ModifierKind::Pattern);
        if (mix) ResolveMixtureSides(object, pattern);
        const Vec3 right(a[3], a[4], a[5]), down(a[6], a[7], a[8]);
        if (!TextBlock::SpansPlane(right, down)) Fail(object, "illegal motion vector");
        std::vector<std::string> lines;
        if (words.size() > textAt + 1) {
            // One line: the words after the (ignored) file name, joined by spaces.
            std::string line;
            for (std::size_t k = textAt + 1; k < words.size(); ++k) {
                if (k > textAt + 1) line += ' ';
                line += words[k];
            }
            lines.push_back(std::move(line));
        } else {
            const auto file = cal::FindFunctionFile(words[textAt], searchPath_);
            if (!file) {
                throw Error(Error::Kind::System, object.loc,
                            Describe(object) + ": cannot find text file \"" +
                                PrintableWord(words[textAt]) + "\"");
            }
            lines = SplitTextLines(file->text);
        }
        std::shared_ptr<const Font> font;
        try {
            font = fonts_.Get(words[fontAt]);
        } catch (const Error& e) {
            Fail(object, std::string("font load error: ") + e.what());
        }
        std::optional<double> spacing;
        if (a.size() > reals) spacing = a[reals];
        const Rgb fore = colour ? Rgb(a[9], a[10], a[11]) : Rgb::Grey(mix ? 1.0 : a[9]);
        const Rgb back = colour ? Rgb(a[12], a[13], a[14]) : Rgb::Grey(mix ? 1.0 : a[10]);
        pattern.text = std::make_shared<const TextPattern>(TextPattern{
            TextBlock(font, lines, right, down, spacing), Vec3(a[0], a[1], a[2]), fore, back});
        const int modifier = ResolveModifier(object);
        CheckMixtureModifier(object, pattern, modifier);
        scene_.patterns.push_back(std::move(pattern));
        Define(object.name, ModifierDef{-1, static_cast<int>(scene_.patterns.size()) - 1, modifier});
    }

    /// The data files (sargs after the function names) or the picture of a
    /// *data / *pict pattern, each file loaded once per scene.
    void LoadData(const PatternSpec& spec, const SceneObject& object, DataLookup& data) {
        const std::string requestedBy = object.loc.ToString() + ": " + Describe(object);
        const std::size_t first = static_cast<std::size_t>(spec.names + spec.functions);
        if (spec.picture) {
            const auto channels = dataFiles_.Picture(object.sargs[first], requestedBy);
            data.arrays.assign(channels.begin(), channels.end());
            data.picture = true;
            return;
        }
        for (std::size_t k = first; k < first + static_cast<std::size_t>(spec.dataFiles); ++k) {
            data.arrays.push_back(dataFiles_.Data(object.sargs[k], requestedBy));
            if (data.arrays.back()->dimensions() != data.arrays.front()->dimensions()) {
                Fail(object, "dimension error (data files of different dimensions)");
            }
        }
    }

    void AddMaterial(const SceneObject& object) {
        const MaterialSpec* spec = FindMaterialSpec(object.type);
        if (spec == nullptr) {
            ThrowUserError(object.loc, "unsupported material type '" + object.type + "'");
        }
        const int modifier = ResolveModifier(object);
        const int nreals = static_cast<int>(object.rargs.size());
        if (spec->function == MaterialFunction::Bsdf) {
            // m_bsdf.c's check, at the first ray there; here when loading.
            const std::size_t strings = spec->type == MaterialType::Bsdf ? 6 : 5;
            if (object.sargs.size() < strings || nreals > 9 || nreals % 3 != 0) BadArgs(object);
        } else if (spec->function == MaterialFunction::Redirect) {
            // getfunc()'s check (Radiance makes it at the first ray or
            // virtual source; here when loading).
            const std::size_t strings = spec->type == MaterialType::Prism1 ? 5 : 9;
            if (object.sargs.size() < strings) Fail(object, "too few string arguments");
        } else if (spec->function == MaterialFunction::Orientation) {
            // Radiance's own words for these (m_aniso.c, getfunc()).
            if (nreals < spec->minReals || nreals > spec->maxReals) {
                Fail(object, "bad number of real arguments");
            }
            if (object.sargs.size() < 4) Fail(object, "too few string arguments");
        } else if (spec->type == MaterialType::Mist) {
            // m_mist.c's words and kinds, at the first ray there; here when
            // loading (README, Differences).
            if (nreals > spec->maxReals) {
                ThrowUserError(object.loc, "bad arguments for " + Describe(object));
            }
            if (object.sargs.size() > kMaxMistSources) {
                throw Error::InternalByInput(object.loc,
                                             "too many sources in list for " + Describe(object));
            }
        } else if (spec->function != MaterialFunction::None) {
            const std::size_t strings = spec->function == MaterialFunction::Brdf   ? 2
                                        : spec->function == MaterialFunction::Brtd ? 10
                                                                                   : 4;
            if (object.sargs.size() < strings || nreals < spec->minReals) BadArgs(object);
        } else if (static_cast<int>(object.sargs.size()) > spec->maxStrings ||
                   nreals < spec->minReals || nreals > spec->maxReals) {
            BadArgs(object);
        }
        Material material;
        material.name = object.name;
        material.type = spec->type;
        material.args = object.rargs;
        material.params = MakeMaterialParams(spec->type, material.args);
        material.loc = object.loc;
        if (spec->function == MaterialFunction::Orientation) {
            // Radiance stops at the first ray that meets such a surface
            // ("roughness too small"); here when the scene loads.
            const auto* p = std::get_if<AnisoParams>(&material.params);  // not ashik2's
            if (p && (p->uRoughness <= kFtiny || p->vRoughness <= kFtiny)) {
                Fail(object, "roughness too small");
            }
            scene_.patterns.push_back(MakePattern(object, kOrientationSpec));
            material.function = static_cast<int>(scene_.patterns.size()) - 1;
        } else if (spec->function == MaterialFunction::Bsdf) {
            SetBsdf(object, material);
        } else if (spec->function == MaterialFunction::Redirect) {
            // DxA… the function may read, before its file.
            Functions().DefineRedirectVariables();
            scene_.patterns.push_back(MakePattern(
                object, spec->type == MaterialType::Prism1 ? kRedirect1Spec : kRedirect2Spec));
            material.function = static_cast<int>(scene_.patterns.size()) - 1;
        } else if (spec->function != MaterialFunction::None) {
            // The BRDF variables the function may read, before its file.
            Functions().DefineBrdfVariables();
            scene_.patterns.push_back(MakePattern(
                object, spec->function == MaterialFunction::Brdf   ? kBrdfSpec
                        : spec->function == MaterialFunction::Brtd ? kBrtdSpec
                                                                   : kBrdfDataSpec));
            material.function = static_cast<int>(scene_.patterns.size()) - 1;
        } else if (spec->type == MaterialType::Antimatter) {
            SetClipped(object, std::get<ClipParams>(material.params));
        } else if (spec->type == MaterialType::Mist) {
            std::get<MistParams>(material.params).sourceNames = object.sargs;
        } else if (!object.sargs.empty() && object.sargs[0] != "void") {
            const auto alternate = Lookup(object.sargs[0]);
            if (!alternate) {
                ThrowUserError(object.loc, "undefined alternate material \"" +
                                               PrintableWord(object.sargs[0]) + "\" for " +
                                               Describe(object));
            }
            material.alternate = defs_[static_cast<std::size_t>(*alternate)].material;
        }
        if (spec->type == MaterialType::Spotlight) {
            if (material.args[3] <= kFtiny) Fail(object, "zero angle");
            if (LengthSquared(Vec3(material.args[4], material.args[5], material.args[6])) == 0) {
                Fail(object, "zero focus vector");
            }
        }
        material.patterns = MaterialChain(object, modifier);
        scene_.materials.push_back(std::move(material));
        Define(object.name, ModifierDef{static_cast<int>(scene_.materials.size()) - 1, -1, modifier});
    }

    /// BSDF and aBSDF: the file (loaded once per scene) and the frame's
    /// expressions, read as an orientation's once the file's name is out.
    void SetBsdf(const SceneObject& object, Material& material) {
        const bool thick = material.type == MaterialType::Bsdf;
        const std::size_t fileAt = thick ? 1 : 0;
        auto& p = std::get<BsdfParams>(material.params);
        p.data = bsdfFiles_.Load(object.sargs[fileAt], object.loc.ToString() + ": " + Describe(object),
                                 warn_);
        p.proxy = thick && object.sargs[0] != "0";
        SceneObject frame = object;
        frame.sargs.erase(frame.sargs.begin() + static_cast<std::ptrdiff_t>(fileAt));
        scene_.patterns.push_back(MakePattern(frame, thick ? kBsdfFrameSpec : kOrientationSpec));
        material.function = static_cast<int>(scene_.patterns.size()) - 1;
    }

    /// antimatter's strings (m_clip.c): each names a modifier whose surfaces
    /// rays entering the antimatter pass, the definition before the
    /// antimatter (Radiance's lastmod()). The first is the same, though
    /// Radiance meant it to shade the clipped solid's cut too: 5.4a never does
    /// (README, "Differences"). Inside an instance Radiance takes the scene's
    /// own last definition of a name wherever it has one, so those are
    /// resolved when the scene is finished (ResolvePendingClips).
    void SetClipped(const SceneObject& object, ClipParams& clip) {
        if (object.sargs.empty() || object.sargs.size() > kMaxClipped) BadArgs(object);
        PendingClip pending{scene_.materials.size(), object.loc, Describe(object), {}};
        for (const std::string& name : object.sargs) {
            if (name == "void") continue;
            const auto def = Lookup(name);
            pending.names.push_back({name, def ? defs_[static_cast<std::size_t>(*def)].id : -1});
        }
        if (surfaces_ == &scene_.surfaces) {
            Clip(pending, clip);
        } else {
            pendingClips_.push_back(std::move(pending));
        }
    }

    /// An antimatter's modifier names, each with the Surface::modifierId it
    /// resolved to (-1: none), until they are added to its ClipParams.
    struct PendingClip {
        std::size_t material;  // index into Scene::materials
        FileLoc loc;
        std::string owner;     // Describe() of the antimatter
        struct Name {
            std::string name;
            int id;
        };
        std::vector<Name> names;
    };

    /// Adds `pending`'s modifiers to `clip` and to the scene's list, with
    /// Radiance's warnings.
    void Clip(const PendingClip& pending, ClipParams& clip) {
        for (const PendingClip::Name& n : pending.names) {
            const std::string where = pending.loc.ToString() + ": ";
            if (n.id < 0) {
                if (warn_) {
                    warn_(where + "unknown modifier \"" + PrintableWord(n.name) + "\" for " +
                          pending.owner);
                }
                continue;
            }
            const auto at = std::lower_bound(clip.clipped.begin(), clip.clipped.end(), n.id);
            if (at != clip.clipped.end() && *at == n.id) {
                if (warn_) warn_(where + "duplicate modifier for " + pending.owner);
                continue;
            }
            clip.clipped.insert(at, n.id);
            const auto all = std::lower_bound(scene_.clippedModifiers.begin(),
                                              scene_.clippedModifiers.end(), n.id);
            if (all == scene_.clippedModifiers.end() || *all != n.id) {
                scene_.clippedModifiers.insert(all, n.id);
            }
        }
    }

    /// The antimatter read inside instanced octrees and meshes: a name the
    /// scene itself defines means the scene's last definition of it.
    void ResolvePendingClips() {
        for (PendingClip& p : pendingClips_) {
            for (PendingClip::Name& n : p.names) {
                if (const auto def = Lookup(n.name)) n.id = defs_[static_cast<std::size_t>(*def)].id;
            }
            Clip(p, std::get<ClipParams>(scene_.materials[p.material].params));
        }
        pendingClips_.clear();
    }

    /// Sets the surface's material and the patterns between it and the
    /// material from the chain starting at definition `modifier`; a chain
    /// without a material leaves the surface as void.
    void SetModifiers(Surface& surface, int modifier) const {
        surface.modifierId = modifier < 0 ? -1 : defs_[static_cast<std::size_t>(modifier)].id;
        ModifierChain chain = ChainFrom(modifier);
        surface.material = chain.material;
        surface.patterns = std::move(chain.modifiers);
    }

    void AddSurface(SceneObject& object) {
        if (object.type == "instance" || object.type == "mesh") {
            AddPlacement(object);
            return;
        }
        const int modifier = ResolveModifier(object);
        if (!object.sargs.empty()) BadArgs(object);

        Surface surface;
        SetModifiers(surface, modifier);
        bool keep = true;
        if (object.type == "polygon") {
            keep = SetPolygon(object, surface);
        } else if (object.type == "sphere" || object.type == "bubble") {
            keep = SetSphere(object, surface);
        } else if (object.type == "ring") {
            keep = SetRing(object, surface);
        } else if (object.type == "source") {
            SetSource(object, surface);
        } else {
            keep = SetCone(object, surface);
        }
        if (!keep) return;
        // Geometry from huge coordinates can overflow even though every argument is finite.
        const Bounds3 bounds = SurfaceBounds(surface);
        if (!bounds.Empty() && (!IsFinite(bounds.lo) || !IsFinite(bounds.hi))) {
            Fail(object, "coordinates too large");
        }
        // Moved last: until here an error may name the object.
        surface.name = std::move(object.name);
        surface.modifierName = std::move(object.modifier);
        surface.loc = std::move(object.loc);
        surfaces_->push_back(std::move(surface));
    }

    /// `mod instance id 1+ octree [xf] 0 0` and `mod mesh id 1+ file [xf] 0 0`
    /// (radiance-functions.md §13.1, §13.4).
    void AddPlacement(const SceneObject& object) {
        if (object.sargs.empty() || !object.rargs.empty()) BadArgs(object);
        const int modifier = ResolveModifier(object);
        Placement placement;
        placement.name = object.name;
        placement.loc = object.loc;
        if (object.sargs.size() > 1) {
            const ParsedTransform xf = ParseTransformArgs(object.sargs, 1);
            if (xf.next != object.sargs.size()) Fail(object, "bad transform");
            placement.outerFromObject = xf.transform;
            // Radiance keeps a mirror's uniform scale positive (§13.1).
            placement.outerFromObject.scale = std::fabs(placement.outerFromObject.scale);
        }
        if (object.modifier != "void") {
            Surface override;
            override.name = object.name;
            override.modifierName = object.modifier;
            override.type = SurfaceType::Instance;
            override.loc = object.loc;
            SetModifiers(override, modifier);
            placement.override = std::move(override);
        }
        placement.prototype = LoadPrototype(object);
        placements_->push_back(std::move(placement));
    }

    /// The prototype for the file an instance or mesh names, read the first
    /// time it is named (one copy per name as written, as Radiance).
    int LoadPrototype(const SceneObject& object) {
        const bool mesh = object.type == "mesh";
        const std::string& file = object.sargs[0];
        const std::string key = (mesh ? "mesh:" : "octree:") + file;
        if (const auto it = prototypeIndex_.find(key); it != prototypeIndex_.end()) {
            if (it->second < 0) {
                Fail(object, "octree \"" + PrintableWord(file) + "\" includes itself");
            }
            return it->second;
        }
        if (!options_.readFiles) Fail(object, "files disabled");
        const auto path = cal::FindFilePath(file, searchPath_);
        if (!path) {
            ThrowSystemError(object.loc.ToString() + ": cannot find " +
                             (mesh ? "mesh" : "octree") + " file \"" + PrintableWord(file) + "\"");
        }
        std::ifstream in(*path, std::ios::binary);
        if (!in) ThrowSystemError(object.loc.ToString() + ": cannot open \"" + *path + "\"");
        prototypeIndex_[key] = -1;  // being read: naming it again is a cycle
        Prototype prototype;
        prototype.file = file;
        std::vector<Placement> nested;
        if (mesh) {
            ReadMeshPrototype(in, *path, prototype);
        } else {
            OctreeFile octree = ReadOctree(in, *path);
            std::vector<SceneObject> objects = OctreeSceneObjects(octree, *path, options_, warn_);
            prototype.cubeOrigin = octree.cubeOrigin;
            prototype.cubeSize = octree.cubeSize;
            // The octree's modifier names are its own (§13.1): build it with
            // a fresh name table, into the prototype.
            auto savedDefs = std::exchange(defs_, {});
            auto savedNames = std::exchange(byName_, {});
            auto* savedSurfaces = std::exchange(surfaces_, &prototype.surfaces);
            auto* savedPlacements = std::exchange(placements_, &nested);
            for (SceneObject& o : objects) Add(o);
            defs_ = std::move(savedDefs);
            byName_ = std::move(savedNames);
            surfaces_ = savedSurfaces;
            placements_ = savedPlacements;
        }
        scene_.prototypes.push_back(std::move(prototype));
        prototypePlacements_.push_back(std::move(nested));
        const int index = static_cast<int>(scene_.prototypes.size()) - 1;
        prototypeIndex_[key] = index;
        return index;
    }

    /// A mesh file's triangles and, for each material they use, the
    /// pseudo-surface that shades them (Radiance's "M-Tri" face objects).
    void ReadMeshPrototype(std::istream& in, const std::string& path, Prototype& prototype) {
        MeshFile file = ReadMesh(in, path);
        prototype.cubeOrigin = file.cubeOrigin;
        prototype.cubeSize = file.cubeSize;
        // The mesh's materials have names of their own, as an instanced
        // octree's do; each object defines exactly one modifier.
        auto savedDefs = std::exchange(defs_, {});
        auto savedNames = std::exchange(byName_, {});
        std::vector<int> defOf;
        defOf.reserve(file.materials.size());
        for (SceneObject& o : file.materials) {
            Add(o);
            defOf.push_back(static_cast<int>(defs_.size()) - 1);
        }
        // Index into prototype.surfaces per material (+1: slot 0 is void).
        std::vector<int> surfaceOf(file.materials.size() + 1, -1);
        const auto surfaceFor = [&](int material) {
            int& slot = surfaceOf[static_cast<std::size_t>(material + 1)];
            if (slot < 0) {
                Surface surface;
                surface.name = "M-Tri";
                surface.type = SurfaceType::Mesh;
                surface.modifierName =
                    material < 0 ? "void" : file.materials[static_cast<std::size_t>(material)].name;
                if (material >= 0) SetModifiers(surface, defOf[static_cast<std::size_t>(material)]);
                surface.loc = FileLoc{path, 0, 0};
                prototype.surfaces.push_back(std::move(surface));
                slot = static_cast<int>(prototype.surfaces.size()) - 1;
            }
            return slot;
        };
        auto mesh = std::make_shared<TriangleMesh>();
        mesh->triangles.reserve(file.triangles.size());
        for (const MeshFile::Triangle& t : file.triangles) {
            mesh->triangles.push_back({t.v, surfaceFor(t.material)});
        }
        mesh->vertices = std::move(file.vertices);
        mesh->normals = std::move(file.normals);
        mesh->uvs = std::move(file.uvs);
        mesh->hasUv = std::move(file.hasUv);
        prototype.mesh = std::move(mesh);
        defs_ = std::move(savedDefs);
        byName_ = std::move(savedNames);
    }

    /// Scene::instances for `placement`, written in a space that
    /// `renderFromOuter` takes to world, and for every placement nested in its
    /// prototype. An outer override wins over inner ones (Radiance's hit
    /// object becomes the outermost instance with a modifier).
    void Flatten(const Placement& placement, const Transform& renderFromOuter,
                 const Surface* outerOverride, const std::optional<Transform>& outerOverrideSpace) {
        if (scene_.instances.size() >= kMaxInstances) {
            ThrowUserError(placement.loc, "more than " + std::to_string(kMaxInstances) +
                                              " instances in all");
        }
        Instance instance;
        instance.name = placement.name;
        instance.prototype = placement.prototype;
        instance.renderFromObject = Compose(placement.outerFromObject, renderFromOuter);
        instance.objectFromRender = Inverse(instance.renderFromObject);
        instance.loc = placement.loc;
        const Surface* override = outerOverride;
        std::optional<Transform> overrideSpace = outerOverrideSpace;
        if (!override && placement.override) {
            override = &*placement.override;
            // Its patterns see the space it was written in.
            if (!IsIdentity(renderFromOuter)) overrideSpace = Inverse(renderFromOuter);
        }
        if (override) {
            instance.override = *override;
            instance.overrideFromRender = overrideSpace;
        }
        const Transform renderFromObject = instance.renderFromObject;
        scene_.instances.push_back(std::move(instance));
        // By index: the vector of nested placements is not touched, but
        // instances may reallocate.
        const auto& nested = prototypePlacements_[static_cast<std::size_t>(placement.prototype)];
        for (const Placement& inner : nested) {
            Flatten(inner, renderFromObject, override, overrideSpace);
        }
    }

    static bool IsIdentity(const Transform& t) {
        const Transform identity;
        for (int i = 0; i < 4; ++i) {
            for (int j = 0; j < 4; ++j) {
                if (t.m[i][j] != identity.m[i][j]) return false;
            }
        }
        return true;
    }

    bool SetPolygon(const SceneObject& object, Surface& surface) {
        const auto& a = object.rargs;
        if (a.size() < 9 || a.size() % 3 != 0) BadArgs(object);
        Polygon polygon;
        polygon.vertices.reserve(a.size() / 3);
        for (std::size_t i = 0; i < a.size(); i += 3) polygon.vertices.emplace_back(a[i], a[i + 1], a[i + 2]);
        auto& v = polygon.vertices;
        if (v.size() > 3 && LengthSquared(v.back() - v.front()) <= kFtiny * kFtiny) v.pop_back();

        Vec3 sum;
        for (std::size_t i = 2; i < v.size(); ++i) sum += Cross(v[i - 1] - v[0], v[i] - v[0]);
        const double length = Length(sum);
        if (!std::isfinite(length)) Fail(object, "coordinates too large");
        // Radiance tests for an exactly zero area; collinear vertices that are
        // not collinear in binary leave rounding noise, a sliver with a random
        // normal (and, as a light, "cannot hit source center"). Areas below
        // 1e-14 of the polygon's squared size count as zero.
        double size2 = 0;
        for (const Vec3& p : v) size2 = std::max(size2, LengthSquared(p - v[0]));
        // Also as a light source, which Radiance's rtrace refuses ("zero source
        // area"): README, Robustness.
        if (length <= kDegenerateArea * size2) {
            Warn(object, "zero area");
            return false;
        }
        polygon.normal = sum / length;
        polygon.area = 0.5 * length;

        double offsetSum = 0;
        double size = 0;
        for (const Vec3& p : v) {
            offsetSum += Dot(polygon.normal, p);
            size = std::max(size, Length(p - v[0]));
        }
        polygon.offset = offsetSum / static_cast<double>(v.size());
        bool nonPlanar = false;
        for (const Vec3& p : v) {
            nonPlanar = nonPlanar || std::fabs(Dot(polygon.normal, p) - polygon.offset) > kVertexEpsilon * size;
        }
        if (nonPlanar && v.size() > 3) Warn(object, "non-planar vertex");
        surface.type = SurfaceType::Polygon;
        surface.shape = std::move(polygon);
        return true;
    }

    /// A degenerate shape, which oconv warns about (`what`, in its words) and
    /// leaves out of the octree, so that Radiance's rtrace never meets it;
    /// false, for the caller to drop it. As a light source it stops Radiance's
    /// rtrace, which sets sources up from the objects themselves
    /// (marksources()), with `asSource`.
    bool Degenerate(const SceneObject& object, const Surface& surface, const char* what,
                    const char* asSource) const {
        if (surfaces_ == &scene_.surfaces && surface.material >= 0 &&
            IsSourceMaterial(scene_.materials[static_cast<std::size_t>(surface.material)],
                             surface.type)) {
            Fail(object, asSource);
        }
        Warn(object, what);
        return false;
    }

    bool SetSphere(const SceneObject& object, Surface& surface) {
        const auto& a = object.rargs;
        if (a.size() != 4) BadArgs(object);
        Sphere sphere;
        sphere.center = Vec3(a[0], a[1], a[2]);
        sphere.radius = a[3];
        sphere.inward = object.type == "bubble";
        surface.type = sphere.inward ? SurfaceType::Bubble : SurfaceType::Sphere;
        if (sphere.radius < -kFtiny) {
            Warn(object, "negative radius");
            sphere.radius = -sphere.radius;
            sphere.inward = !sphere.inward;
        } else if (sphere.radius <= kFtiny) {
            // A bubble cannot be a source at all.
            return Degenerate(object, surface, "zero radius",
                              sphere.inward ? "illegal material" : "illegal source radius");
        }
        surface.type = sphere.inward ? SurfaceType::Bubble : SurfaceType::Sphere;
        surface.shape = sphere;
        return true;
    }

    static int Sign(double r) { return r < -kFtiny ? -1 : (r > kFtiny ? 1 : 0); }

    bool SetCone(const SceneObject& object, Surface& surface) {
        const auto& a = object.rargs;
        const bool cylinderLike = object.type == "cylinder" || object.type == "tube";
        // As a source a cylinder is Radiance's "illegal source" when
        // degenerate; a cone or cup cannot be one at all.
        surface.type = cylinderLike ? SurfaceType::Cylinder : SurfaceType::Cone;
        const char* asSource = cylinderLike ? "illegal source" : "illegal material";
        if (a.size() != (cylinderLike ? 7u : 8u)) BadArgs(object);
        Cone cone;
        cone.p0 = Vec3(a[0], a[1], a[2]);
        cone.p1 = Vec3(a[3], a[4], a[5]);
        cone.inward = object.type == "cup" || object.type == "tube";
        bool cylinder = cylinderLike;
        if (cylinderLike) {
            double r = a[6];
            if (r < -kFtiny) {
                Warn(object, "negative radius");
                cone.inward = !cone.inward;
                r = -r;
            } else if (r <= kFtiny) {
                return Degenerate(object, surface, "illegal radii", asSource);
            }
            cone.r0 = cone.r1 = r;
        } else {
            const int sign0 = Sign(a[6]), sign1 = Sign(a[7]);
            if (sign0 + sign1 == 0) return Degenerate(object, surface, "illegal radii", asSource);
            if (sign0 < 0 || sign1 < 0) {
                Warn(object, "negative radii");
                cone.inward = !cone.inward;
            }
            const double r0 = a[6] * sign0, r1 = a[7] * sign1;
            if (r1 - r0 > kFtiny) {
                cone.r0 = r0;
                cone.r1 = r1;
            } else if (r0 - r1 > kFtiny) {
                // cone.c keeps the narrow end first.
                std::swap(cone.p0, cone.p1);
                cone.r0 = r1;
                cone.r1 = r0;
            } else {
                cylinder = true;
                cone.r0 = cone.r1 = r0;
            }
        }
        if (LengthSquared(cone.p1 - cone.p0) == 0) {
            return Degenerate(object, surface, "unknown orientation", asSource);
        }
        surface.type = cylinder ? (cone.inward ? SurfaceType::Tube : SurfaceType::Cylinder)
                                : (cone.inward ? SurfaceType::Cup : SurfaceType::Cone);
        surface.shape = cone;
        return true;
    }

    bool SetRing(const SceneObject& object, Surface& surface) {
        const auto& a = object.rargs;
        if (a.size() != 8) BadArgs(object);
        surface.type = SurfaceType::Ring;
        const int sign0 = Sign(a[6]), sign1 = Sign(a[7]);
        const double r0 = a[6] * sign0, r1 = a[7] * sign1;
        // Negative or equal radii.
        if (sign0 < 0 || sign1 < 0 || std::fabs(r1 - r0) <= kFtiny) {
            return Degenerate(object, surface, "illegal radii", "illegal source");
        }
        const Vec3 normal(a[3], a[4], a[5]);
        if (LengthSquared(normal) == 0) {
            return Degenerate(object, surface, "unknown orientation", "illegal source");
        }
        Ring ring;
        ring.center = Vec3(a[0], a[1], a[2]);
        ring.normal = Normalize(normal);
        ring.r0 = std::min(r0, r1);
        ring.r1 = std::max(r0, r1);
        surface.shape = ring;
        return true;
    }

    void SetSource(const SceneObject& object, Surface& surface) {
        const auto& a = object.rargs;
        if (a.size() != 4) BadArgs(object);
        const Vec3 direction(a[0], a[1], a[2]);
        if (LengthSquared(direction) == 0) Fail(object, "zero direction");
        if (kPi / 180.0 / 2.0 * a[3] <= kFtiny) Fail(object, "zero size");
        surface.type = SurfaceType::Source;
        surface.shape = DistantSource{Normalize(direction), a[3]};
    }

    /// oconv's cube. Its circle2bbox() (bbox.c) is not the exact extent of a
    /// circle, so cones and rings are bounded here as oconv does, not with
    /// SurfaceBounds(), to reproduce Radiance's cube size (and so -ar) exactly.
    void SetCube() {
        Bounds3 bounds;
        const auto circle = [&bounds](const Vec3& center, const Vec3& normal, double radius) {
            for (int i = 0; i < 3; ++i) {
                Vec3 axis;
                axis[i] = 1;
                const Vec3 v = Cross(normal, axis);
                if (LengthSquared(v) == 0) continue;
                const Vec3 d = Normalize(v) * radius;
                bounds.Extend(center + d);
                bounds.Extend(center - d);
            }
        };
        for (const Instance& instance : scene_.instances) {
            bounds.Extend(InstanceBounds(scene_, instance));
        }
        for (const Surface& surface : scene_.surfaces) {
            if (const auto* cone = std::get_if<Cone>(&surface.shape)) {
                const Vec3 axis = Normalize(cone->p1 - cone->p0);
                circle(cone->p0, axis, cone->r0);
                circle(cone->p1, axis, cone->r1);
            } else if (const auto* ring = std::get_if<Ring>(&surface.shape)) {
                circle(ring->center, ring->normal, ring->r1);
            } else {
                bounds.Extend(SurfaceBounds(surface));
            }
        }
        if (bounds.Empty()) {
            // No local geometry at all (empty scene or distant sources only): oconv
            // would leave a zero-size cube; a unit cube centred on the origin keeps
            // distances derived from the cube (-ar, miss lengths) finite and sensible.
            scene_.cubeOrigin = Vec3(-0.5, -0.5, -0.5);
            scene_.cubeSize = 1;
            return;
        }
        scene_.distanceTolerance = DistanceTolerance(MaxAbs(bounds.hi - bounds.lo),
                                                     std::max(MaxAbs(bounds.lo), MaxAbs(bounds.hi)));
        const double margin = kCubeMargin * scene_.ToleranceScale();
        const Vec3 lo = bounds.lo - Vec3(margin, margin, margin);
        const Vec3 hi = bounds.hi + Vec3(margin, margin, margin);
        double size = 0;
        for (int i = 0; i < 3; ++i) size = std::max(size, hi[i] - lo[i]);
        for (int i = 0; i < 3; ++i) scene_.cubeOrigin[i] = (hi[i] + lo[i] - size) * 0.5;
        scene_.cubeSize = size;
    }

    const WarningSink& warn_;
    const SceneLoadOptions& options_;
    cal::SearchPath searchPath_ = cal::SearchPath::FromEnvironment();
    Scene scene_;  // before surfaces_, which points into it from the start
    /// Where surfaces and placements go: the scene's, or those of the
    /// prototype being read.
    std::vector<Surface>* surfaces_ = &scene_.surfaces;
    std::vector<Placement> topPlacements_;
    std::vector<Placement>* placements_ = &topPlacements_;
    /// "octree:name" / "mesh:name" -> index into Scene::prototypes; -1 while
    /// that file is being read.
    std::unordered_map<std::string, int> prototypeIndex_;
    /// Per prototype, the placements written inside it.
    std::vector<std::vector<Placement>> prototypePlacements_;
    DataFileCache dataFiles_{searchPath_};
    FontCache fonts_{searchPath_};
    BsdfFileCache bsdfFiles_{searchPath_};
    std::shared_ptr<cal::Program> functions_;
    std::vector<ModifierDef> defs_;
    std::unordered_map<std::string, int> byName_;
    int nextModifierId_ = 0;  // ModifierDef::id
    std::vector<PendingClip> pendingClips_;
};

}  // namespace

class SceneAssembler::Impl {
public:
    Impl(const WarningSink& warn, const SceneLoadOptions& options) : builder(warn, options) {}
    SceneBuilder builder;
};

SceneAssembler::SceneAssembler(const WarningSink& warn, const SceneLoadOptions& options)
    : impl_(std::make_unique<Impl>(warn, options)) {}
SceneAssembler::~SceneAssembler() = default;
void SceneAssembler::Add(SceneObject& object) { impl_->builder.Add(object); }
void SceneAssembler::ReserveSurfaces(std::size_t n) { impl_->builder.ReserveSurfaces(n); }
void SceneAssembler::ReserveForText(std::uintmax_t bytes) {
    ReserveHeapInHugePages(
        static_cast<std::size_t>(std::min<std::uintmax_t>(bytes, 1ULL << 40) * kHeapPerTextByte));
}
Scene SceneAssembler::Finish() { return impl_->builder.Finish(); }

Scene BuildScene(std::vector<SceneObject> objects, const WarningSink& warn,
                 const SceneLoadOptions& options) {
    SceneAssembler assembler(warn, options);
    assembler.ReserveSurfaces(objects.size());
    for (SceneObject& object : objects) assembler.Add(object);
    return assembler.Finish();
}

}  // namespace rt
