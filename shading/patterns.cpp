// SPDX-License-Identifier: MIT
//
// Function modifiers at a hit (radiance-functions.md §10.3, §11.1-11.9;
// Radiance's p_func.c, p_data.c, t_func.c, mx_func.c and raymixture()):
// the ray's quantities in the modifier's space as the function language's
// channels; the pattern colour a pattern multiplies in, the normal
// perturbation a texture adds, and the two shadings a mixture blends.
#include "shading/patterns.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>

#include "cal/ray_variables.h"
#include "scene/data_file.h"
#include "shading/ray_tree.h"

namespace rt {
namespace {

/// Radiance treats a ray whose length is at least this as one that hit
/// nothing (func.c: rot >= 0.99*FHUGE): its point is the origin.
constexpr double kMissLength = 0.99 * kFhuge;

/// Where a modifier evaluates a ray (§10.1): its own transform, after the
/// instance's when the hit is inside one whose materials shade it (§13.2:
/// F = objectFromRender then patternFromWorld; back = worldFromPattern then
/// the instance's renderFromObject; scales multiply). The one place that
/// composes them, so that patterns, textures and mixtures all follow. It
/// runs for every modifier a ray meets (every sky ray): outside instances it
/// only refers to the modifier's own transforms, and the inverse is made
/// only for textures.
class PatternSpace {
public:
    PatternSpace(const TracedRay& ray, const Pattern& modifier) : ray_(ray), modifier_(modifier) {
        if (ray.objectFromRender) composed_ = Compose(*ray.objectFromRender, modifier.patternFromWorld);
    }
    /// F, on row vectors; scale s > 0.
    const Transform& PatternFromRender() const {
        return ray_.objectFromRender ? composed_ : modifier_.patternFromWorld;
    }
    /// F's inverse, for texture displacements; scale 1/s.
    Transform RenderFromPattern() const {
        if (!ray_.objectFromRender) return modifier_.worldFromPattern;
        return Compose(modifier_.worldFromPattern, Inverse(*ray_.objectFromRender));
    }

private:
    const TracedRay& ray_;
    const Pattern& modifier_;
    Transform composed_;  // set inside instances only
};

/// A render-space direction as the function sees directions (Dx…): turned
/// into `space` and divided by its scale.
Vec3 FunctionDirection(const PatternSpace& space, const Vec3& v) {
    const Transform& f = space.PatternFromRender();
    return f.Vector(v) / f.scale;
}

/// The ray quantities $1 … $27 of `ray` in a modifier's space (§10.3).
class PatternChannels final : public cal::ChannelSource {
public:
    PatternChannels(const TracedRay& ray, const PatternSpace& space)
        : ray_(ray), f_(space.PatternFromRender()), s_(f_.scale) {}

    double Channel(int n) const override {
        using namespace cal;
        switch (n) {
            case kDx: case kDy: case kDz: return f_.Vector(ray_.dir)[n - kDx] / s_;
            case kNx: case kNy: case kNz: return f_.Vector(Normal())[n - kNx] / s_;
            case kPx: case kPy: case kPz:
                return ray_.rot >= kMissLength ? 0.0 : f_.Point(ray_.rop)[n - kPx];
            case kT: return s_ * PathLength(false);
            case kRdot: return std::clamp(-Dot(ray_.dir, Normal()), -1.0, 1.0);
            case kS: return s_;
            case kTx: case kTy: case kTz: return f_.m[3][n - kTx];
            case kIx: case kIy: case kIz: return f_.m[0][n - kIx] / s_;
            case kJx: case kJy: case kJz: return f_.m[1][n - kJx] / s_;
            case kKx: case kKy: case kKz: return f_.m[2][n - kKx] / s_;
            case kTs: return s_ * PathLength(true);
            case kLu: return ray_.lu;
            case kLv: return ray_.lv;
            default: return 0.0;
        }
    }

private:
    /// The geometric normal as the surface defines it, not flipped toward the
    /// ray; a ray that hit nothing (a sky) has N = -D.
    Vec3 Normal() const { return ray_.hitDistant ? -ray_.dir : ray_.geometricNormal; }

    /// T: this ray's length plus all its ancestors'. Ts: plus only the
    /// ancestors that are themselves shadow rays (a shadow ray's chain through
    /// trans surfaces).
    double PathLength(bool shadowChain) const {
        double length = ray_.rot;
        for (const TracedRay* p = ray_.parent; p != nullptr; p = p->parent) {
            if (shadowChain && !(p->rtype & kShadowRay)) break;
            length += p->rot;
        }
        return length;
    }

    const TracedRay& ray_;
    const Transform& f_;
    const double s_;
};

/// A BRDF material's channels: the ray's, then the BRDF variables (§10.4).
class BrdfChannels final : public cal::ChannelSource {
public:
    BrdfChannels(const TracedRay& ray, const PatternSpace& space, const Vec3& normal,
                 double rdot, const Rgb& color)
        : ray_(ray, space), normal_(normal), rdot_(rdot), color_(color) {}

    double Channel(int n) const override {
        using namespace cal;
        switch (n) {
            case kNxP: case kNyP: case kNzP: return normal_[n - kNxP];
            case kRdotP: return rdot_;
            case kCrP: return color_.r;
            case kCgP: return color_.g;
            case kCbP: return color_.b;
            default: return ray_.Channel(n);
        }
    }

private:
    PatternChannels ray_;
    Vec3 normal_;
    double rdot_;
    Rgb color_;
};

/// A prism's channels: the ray's, then DxA… (m_direct.c's varset()).
class RedirectChannels final : public cal::ChannelSource {
public:
    RedirectChannels(const TracedRay& ray, const PatternSpace& space, const Vec3& sourceDir)
        : ray_(ray, space), sourceDir_(FunctionDirection(space, sourceDir)) {}

    double Channel(int n) const override {
        using namespace cal;
        switch (n) {
            case kDxA: case kDyA: case kDzA: return sourceDir_[n - kDxA];
            default: return ray_.Channel(n);
        }
    }

private:
    PatternChannels ray_;
    Vec3 sourceDir_;
};

/// Radiance's rayshade() from some modifier on: true if a material shaded the ray.
bool ShadeChain(const RayTree& tree, ThreadState& ts, TracedRay& ray, const ModifierChain& chain) {
    if (tree.ApplyModifiers(ts, ray, chain.modifiers)) return true;
    if (chain.material < 0) return false;
    tree.ShadeSurfaceMaterial(ts, ray,
                              tree.setup().scene.materials[static_cast<std::size_t>(chain.material)]);
    return true;
}

/// Radiance's raymixture(): shades copies of `ray` with `mixture`'s fore and
/// back chains, weighted c and 1-c (c = `coefficient` clamped to [0, 1]), and
/// blends their pcol and pert into `ray`, and their values when either
/// reached a material (then returns true).
bool Mix(const RayTree& tree, ThreadState& ts, TracedRay& ray, const Pattern& mixture,
         double coefficient) {
    const double c = std::clamp(coefficient, 0.0, 1.0);
    // Each side shades its own copy of the ray, with its share of the
    // weight, so neither sees the other's flips, patterns or results.
    TracedRay fore = ray, back = ray;
    bool foreMaterial = false, backMaterial = false;
    if (c > kFtiny) {
        fore.rweight *= c;
        fore.sourceWeight *= c;
        fore.rcoef *= c;
        foreMaterial = ShadeChain(tree, ts, fore, mixture.fore);
    }
    if (c < 1.0 - kFtiny) {
        back.rweight *= 1.0 - c;
        back.sourceWeight *= 1.0 - c;
        back.rcoef *= 1.0 - c;
        backMaterial = ShadeChain(tree, ts, back, mixture.back);
    }
    // Where only one side is a material, the other is a hole in it.
    if (foreMaterial != backMaterial) {
        if (backMaterial && c > kFtiny) {
            tree.PassThrough(ts, fore);
        } else if (foreMaterial && c < 1.0 - kFtiny) {
            tree.PassThrough(ts, back);
        }
    }
    ray.pert = fore.pert * c + back.pert * (1.0 - c);
    ray.pcol = fore.pcol * c + back.pcol * (1.0 - c);
    if (!foreMaterial && !backMaterial) return false;  // acted as a pattern/texture
    ray.rcol = fore.rcol * c + back.rcol * (1.0 - c);
    ray.mcol = fore.mcol * c + back.mcol * (1.0 - c);
    // One distance each: the dominant side's.
    const TracedRay& major = c >= 0.5 ? fore : back;
    ray.rmt = major.rmt;
    ray.rxt = major.rxt;
    return true;
}

/// The values of modifier `index` (in Scene::patterns) for this ray,
/// evaluated in `space`, into v (as many entries as it has values, at
/// least 3; entries it has no value for keep theirs).
/// False after a math error, which a pattern, texture or mixture (`warn`)
/// reports once per modifier.
bool EvaluateModifier(const Scene& scene, ThreadState& ts, const TracedRay& ray, int index,
                      const PatternSpace& space, double* v, bool warn) {
    const cal::Program& functions = *scene.functions;
    const Pattern& modifier = scene.patterns[static_cast<std::size_t>(index)];
    // Mixtures recurse into ApplyModifiers through ShadeChain, so the
    // context is set up afresh for each modifier.
    cal::Context& context = *ts.functionContext;
    const PatternChannels channels(ray, space);
    context.SetChannels(&channels);
    context.SetArguments(modifier.args, modifier.owner);
    context.NextEvaluation();
    if (modifier.data.arrays.empty()) {
        for (std::size_t k = 0; k < modifier.values.size(); ++k) {
            v[k] = functions.Evaluate(modifier.values[k], context);
        }
    } else {
        // *data and *pict: the expressions are the coordinates (at most
        // kMaxDataDimensions; pictures 2) of the data point.
        double point[kMaxDataDimensions] = {};
        for (std::size_t k = 0; k < modifier.values.size(); ++k) {
            point[k] = functions.Evaluate(modifier.values[k], context);
        }
        const auto f = EvaluateDataLookup(
            modifier.data, std::span<const double>(point, modifier.values.size()), functions,
            context);
        std::copy(f.begin(), f.end(), v);
    }
    context.SetChannels(nullptr);
    if (context.mathError() == cal::MathError::None) return true;
    // Radiance skips the modifier for this ray (a pattern counts as 1, a
    // texture adds nothing, a mixture is no material) and warns; once per
    // modifier here, not once per ray. An orientation is silently none.
    if (warn && ts.patternWarned.insert(index).second) {
        ts.Warn("compute error for " + modifier.owner + " (" + context.mathErrorText() + ")");
    }
    return false;
}

}  // namespace

Vec3 EvaluateOrientation(const Scene& scene, ThreadState& ts, const TracedRay& ray, int index) {
    const Pattern& modifier = scene.patterns[static_cast<std::size_t>(index)];
    const PatternSpace space(ray, modifier);
    double v[3] = {0.0, 0.0, 0.0};
    if (!EvaluateModifier(scene, ts, ray, index, space, v, false)) return Vec3();
    // Turned by the material's own transform only (getacoords()): unlike a
    // texture's displacement, not by an instance's, whose object space the
    // function saw. Only its direction matters.
    return modifier.worldFromPattern.Vector(Vec3(v[0], v[1], v[2]));
}

BsdfFrame EvaluateBsdfFrame(const Scene& scene, ThreadState& ts, const TracedRay& ray, int index) {
    const Pattern& modifier = scene.patterns[static_cast<std::size_t>(index)];
    const PatternSpace space(ray, modifier);
    double v[4] = {0.0, 0.0, 0.0, 0.0};
    EvaluateModifier(scene, ts, ray, index, space, v, false);
    const bool thick = modifier.values.size() == 4;
    BsdfFrame f;
    if (thick && std::fabs(v[0]) > kFtiny) f.thickness = v[0];
    const Transform back = space.RenderFromPattern();
    f.up = back.Vector(thick ? Vec3(v[1], v[2], v[3]) : Vec3(v[0], v[1], v[2]));
    f.thickness *= std::fabs(back.scale);
    return f;
}

namespace {

/// Sets `context` up for BRDF function `brdf` at this ray (setbrdfunc()).
class BrdfEvaluation {
public:
    BrdfEvaluation(cal::Context& context, const TracedRay& ray, const Pattern& brdf,
                   const BrdfInputs& in)
        : context_(context),
          space_(ray, brdf),
          channels_(ray, space_, FunctionDirection(space_, in.normal),
                    std::clamp(in.cosine, -1.0, 1.0), in.color) {
        context_.SetChannels(&channels_);
        context_.SetArguments(brdf.args, brdf.owner);
        context_.NextEvaluation();
    }
    ~BrdfEvaluation() { context_.SetChannels(nullptr); }
    BrdfEvaluation(const BrdfEvaluation&) = delete;
    BrdfEvaluation& operator=(const BrdfEvaluation&) = delete;

    /// A direction in the function's space, as Dx… are.
    Vec3 Direction(const Vec3& v) const { return FunctionDirection(space_, v); }

private:
    cal::Context& context_;
    PatternSpace space_;
    BrdfChannels channels_;
};

}  // namespace

std::optional<Rgb> EvaluateBrdf(const Scene& scene, ThreadState& ts, const TracedRay& ray,
                                int index, const BrdfInputs& in, const Vec3& ldir,
                                double omega) {
    const cal::Program& functions = *scene.functions;
    const Pattern& brdf = scene.patterns[static_cast<std::size_t>(index)];
    cal::Context& context = *ts.functionContext;
    const BrdfEvaluation evaluation(context, ray, brdf, in);
    const Vec3 l = evaluation.Direction(ldir);
    const double light[4] = {l.x, l.y, l.z, omega};
    Rgb value;
    if (brdf.type == PatternType::Brtd) {
        // BRTDfunc: a function per channel, none (a name from '0') for 0.
        for (int c = 0; c < 3; ++c) {
            const cal::Function f = brdf.data.functions[static_cast<std::size_t>(c)];
            value[c] = f.slot < 0 ? 0.0 : functions.Call(f, light, context);
        }
    } else if (brdf.data.arrays.empty()) {
        value = Rgb::Grey(functions.Call(brdf.data.functions[0], light, context));
    } else {
        // *data: the coordinates are functions of the light (as the BRDF),
        // then the BRDF takes the data's value there before the light.
        const std::size_t dimensions = brdf.data.functions.size() - 1;
        double point[kMaxDataDimensions] = {};
        for (std::size_t k = 0; k < dimensions; ++k) {
            point[k] = functions.Call(brdf.data.functions[k + 1], light, context);
        }
        const double args[5] = {
            brdf.data.arrays[0]->Value(std::span<const double>(point, dimensions)), l.x, l.y,
            l.z, omega};
        value = Rgb::Grey(functions.Call(brdf.data.functions[0], args, context));
    }
    if (context.mathError() != cal::MathError::None) return std::nullopt;
    return value;
}

std::optional<Rgb> EvaluateBrdfColour(const Scene& scene, ThreadState& ts, const TracedRay& ray,
                                      int index, const BrdfInputs& in, int first) {
    const cal::Program& functions = *scene.functions;
    const Pattern& brdf = scene.patterns[static_cast<std::size_t>(index)];
    cal::Context& context = *ts.functionContext;
    const BrdfEvaluation evaluation(context, ray, brdf, in);
    Rgb value;
    for (int c = 0; c < 3; ++c) {
        value[c] = functions.Evaluate(brdf.values[static_cast<std::size_t>(first + c)], context);
    }
    if (context.mathError() != cal::MathError::None) return std::nullopt;
    return value;
}

Redirection EvaluateRedirection(const Scene& scene, cal::Context& context, const TracedRay& ray,
                                int index, int n, const Vec3& sourceDir) {
    const cal::Program& functions = *scene.functions;
    const Pattern& prism = scene.patterns[static_cast<std::size_t>(index)];
    const PatternSpace space(ray, prism);
    const RedirectChannels channels(ray, space, sourceDir);
    context.SetChannels(&channels);
    context.SetArguments(prism.args, prism.owner);
    context.NextEvaluation();
    Redirection r;
    const std::size_t first = static_cast<std::size_t>(4 * n);
    r.coefficient = functions.Evaluate(prism.values[first], context);
    if (context.mathError() != cal::MathError::None) {
        r.outcome = Redirection::Outcome::MathError;
    } else if (r.coefficient > kFtiny) {
        double v[3];
        for (std::size_t k = 0; k < 3; ++k) {
            v[k] = functions.Evaluate(prism.values[first + 1 + k], context);
        }
        if (context.mathError() != cal::MathError::None) {
            r.outcome = Redirection::Outcome::MathError;
        } else {
            // The function's transform, then the instance's (m_direct.c).
            r.dir = space.RenderFromPattern().Vector(Vec3(v[0], v[1], v[2]));
            r.outcome = Redirection::Outcome::Redirected;
        }
    }
    context.SetChannels(nullptr);
    return r;
}

namespace {

/// A text pattern or mixture at this ray (Radiance's do_text()): ink or not
/// at the hit point in the object's space (an instance's; text patterns take
/// no transform of their own). A pattern multiplies pcol by its foreground
/// or background; a mixture shades with its fore or back side alone. True
/// when that side reached a material.
bool ApplyText(const RayTree& tree, ThreadState& ts, TracedRay& ray, const Pattern& modifier) {
    const TextPattern& text = *modifier.text;
    const Vec3 p = ray.objectFromRender ? ray.objectFromRender->Point(ray.rop) : ray.rop;
    const bool ink = text.block.Foreground(p - text.anchor);
    if (modifier.kind == ModifierKind::Mixture) return Mix(tree, ts, ray, modifier, ink ? 1.0 : 0.0);
    ray.pcol *= ink ? text.foreground : text.background;
    return false;
}

}  // namespace

bool ApplyModifierChain(const RayTree& tree, ThreadState& ts, TracedRay& ray,
                        const std::vector<int>& modifiers) {
    const Scene& scene = tree.setup().scene;
    for (const int index : modifiers) {
        const Pattern& modifier = scene.patterns[static_cast<std::size_t>(index)];
        if (modifier.text) {
            if (ApplyText(tree, ts, ray, modifier)) return true;
            continue;
        }
        const PatternSpace space(ray, modifier);
        double v[3] = {1.0, 1.0, 1.0};
        if (!EvaluateModifier(scene, ts, ray, index, space, v, true)) continue;
        switch (modifier.kind) {
            case ModifierKind::Pattern: {
                const bool grey = modifier.type == PatternType::BrightFunc ||
                                  modifier.type == PatternType::BrightData;
                ray.pcol *= grey ? Rgb(v[0], v[0], v[0]) : Rgb(v[0], v[1], v[2]);
                break;
            }
            case ModifierKind::Texture: {
                // Turned into render space; its length is not scaled (§11.8).
                const Transform back = space.RenderFromPattern();
                ray.pert += back.Vector(Vec3(v[0], v[1], v[2])) / back.scale;
                break;
            }
            case ModifierKind::Mixture:
                if (Mix(tree, ts, ray, modifier, v[0])) return true;
                break;
        }
    }
    return false;
}

}  // namespace rt
