// SPDX-License-Identifier: MIT
//
// Patterns at a hit (radiance-functions.md §10.3, §11.1-11.7): the ray's
// quantities in the pattern's space as the function language's channels, and
// the pattern colour each pattern of a modifier chain multiplies in.
#include <algorithm>
#include <cmath>

#include "cal/ray_variables.h"
#include "scene/data_file.h"
#include "shading/integrator.h"

namespace rt {
namespace {

/// Radiance treats a ray whose length is at least this as one that hit
/// nothing (func.c: rot >= 0.99*FHUGE): its point is the origin.
constexpr double kMissLength = 0.99 * kFhuge;

/// The ray quantities $1 … $27 of `ray` in the space of `pattern` (§10.3).
/// F acts on row vectors: the pattern's own transform, after the instance's
/// when the hit is inside one (§10.1, §13.2); s is its scale.
class PatternChannels final : public cal::ChannelSource {
public:
    PatternChannels(const TracedRay& ray, const Pattern& pattern)
        : ray_(ray),
          f_(ray.objectFromRender ? Compose(*ray.objectFromRender, pattern.patternFromWorld)
                                  : pattern.patternFromWorld),
          s_(f_.scale) {}

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
    const Transform f_;
    const double s_;
};

}  // namespace

void Integrator::ApplyPatternChain(TracedRay& ray, const std::vector<int>& patterns) {
    const cal::Program& functions = *scene_.functions;
    cal::Context& context = *functionContext_;
    for (const int index : patterns) {
        const Pattern& pattern = scene_.patterns[static_cast<std::size_t>(index)];
        const PatternChannels channels(ray, pattern);
        context.SetChannels(&channels);
        context.SetArguments(pattern.args, pattern.owner);
        context.NextEvaluation();
        double v[3] = {1.0, 1.0, 1.0};
        if (pattern.data.arrays.empty()) {
            for (std::size_t k = 0; k < pattern.values.size(); ++k) {
                v[k] = functions.Evaluate(pattern.values[k], context);
            }
        } else {
            // *data and *pict: the expressions are the coordinates (at most
            // kMaxDataDimensions; pictures 2) of the data point.
            double point[kMaxDataDimensions] = {};
            for (std::size_t k = 0; k < pattern.values.size(); ++k) {
                point[k] = functions.Evaluate(pattern.values[k], context);
            }
            const auto f = EvaluateDataLookup(
                pattern.data, std::span<const double>(point, pattern.values.size()), functions,
                context);
            std::copy(f.begin(), f.end(), v);
        }
        context.SetChannels(nullptr);
        if (context.mathError() != cal::MathError::None) {
            // Radiance skips the pattern for this ray (its value counts as 1)
            // and warns; once per pattern here, not once per ray.
            if (patternWarned_.insert(index).second && warn_) {
                warn_("compute error for " + pattern.owner + " (" + context.mathErrorText() + ")");
            }
            continue;
        }
        const bool grey =
            pattern.type == PatternType::BrightFunc || pattern.type == PatternType::BrightData;
        ray.pcol *= grey ? Rgb(v[0], v[0], v[0]) : Rgb(v[0], v[1], v[2]);
    }
}

}  // namespace rt
