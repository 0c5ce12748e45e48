// SPDX-License-Identifier: MIT
#include "shading/shading_state.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string_view>

#include "scene/reader.h"
#include "shading/patterns.h"

namespace rt {
namespace {

bool HasGlowSky(const Scene& scene) {
    for (const Surface& s : scene.surfaces) {
        if (s.material >= 0 && scene.materials[s.material].type == MaterialType::Glow) return true;
    }
    return false;
}

/// Radiance's srcmatch(): whether source `i` is the one `id` names, a
/// surface name, or `relay>id` for its image in the mirror `relay`.
bool SourceMatches(const Scene& scene, const std::vector<LightSource>& sources, int i,
                   std::string_view id) {
    for (auto cut = id.find('>'); cut != std::string_view::npos; cut = id.find('>')) {
        const LightSource& s = sources[static_cast<std::size_t>(i)];
        if (!s.IsVirtual() || scene.surfaces[static_cast<std::size_t>(s.relay)].name != id.substr(0, cut)) {
            return false;
        }
        id.remove_prefix(cut + 1);
        i = s.next;
    }
    const LightSource& s = sources[static_cast<std::size_t>(i)];
    return !s.IsVirtual() && scene.surfaces[static_cast<std::size_t>(s.surface)].name == id;
}

/// m_mist.c's source list for `m`: each name's last matching source.
std::vector<int> MistSourceList(const Scene& scene, const std::vector<LightSource>& sources,
                                const Material& m, const WarningSink& warn) {
    std::vector<int> list;
    for (const std::string& name : std::get<MistParams>(m.params).sourceNames) {
        int found = static_cast<int>(sources.size()) - 1;
        while (found >= 0 && !SourceMatches(scene, sources, found, name)) --found;
        const char* problem = found < 0 ? "unknown source"
                              : std::find(list.begin(), list.end(), found) != list.end()
                                  ? "duplicate source"
                                  : nullptr;
        if (problem) {
            if (warn) {
                warn(m.loc.ToString() + ": " + problem + " \"" + PrintableWord(name) +
                     "\" for mist \"" + PrintableWord(m.name) + "\"");
            }
            continue;
        }
        list.push_back(found);
    }
    return list;
}

/// Radiance's dir_proj() test of a prism: the ray from a source toward the
/// prism's disc must meet it, and the prism's function then gives the
/// redirection (DxA… zero), warning after a math error.
RedirectionProbe PrismProbe(const Scene& scene, const RayCore& core, const WarningSink& warn) {
    if (!scene.functions) return {};
    auto context = std::make_shared<cal::Context>(*scene.functions);
    return [&scene, &core, warn, context](int surface, int n, const Vec3& org,
                                          const Vec3& dir) -> std::optional<Vec3> {
        const auto hit = core.IntersectSurface(surface, org, dir);
        if (!hit) return std::nullopt;
        TracedRay ray;
        ray.org = org;
        ray.dir = dir;
        ray.SetHit(*hit, nullptr);
        const Material& m = RelayMaterial(scene, scene.surfaces[surface]);
        const Redirection r = EvaluateRedirection(scene, *context, ray, m.function, n, Vec3());
        if (r.outcome == Redirection::Outcome::MathError && warn) {
            warn("projection compute error for " + scene.patterns[m.function].owner);
        }
        if (r.outcome != Redirection::Outcome::Redirected) return std::nullopt;
        return r.dir;
    };
}

}  // namespace

ShadingSetup::ShadingSetup(const Scene& scene_, const RayCore& core_,
                           const ShadingOptions& shading_, const AmbientOptions& ambient_,
                           const WarningSink& warn, std::shared_ptr<AmbientCache> cache_)
    : scene(scene_),
      core(core_),
      shading(shading_),
      ambient(ambient_),
      cache(std::move(cache_)),
      irradiance(
          IrradianceSettings{
              MethodsFor(ambient_.recordMethods).firstLevel,
              MethodsFor(ambient_.recordMethods).deeper,
              ambient_.accuracy, ambient_.divisions, ambient_.superSamples,
              shading_.limits.weight, scene_.distanceTolerance,
              HessianFarDistance(scene_.cubeSize), ambient_.bounces},
          cache) {
    lambertian.name = "Lamb";
    lambertian.type = MaterialType::Plastic;
    lambertian.args = {kPi, kPi, kPi, 0.0, 0.0};
    lambertian.params = MakeMaterialParams(lambertian.type, lambertian.args);

    // With indirect bounces, a glow sky lights the scene through ambient rays,
    // so the absence of direct sources is not worth a warning (as Radiance).
    const bool quiet = ambient.bounces > 0 && HasGlowSky(scene);
    WarningSink sourceWarn = [&warn, quiet](const std::string& msg) {
        if (quiet && msg == "no light sources found") return;
        if (warn) warn(msg);
    };
    Rng frameRng(MixSeed(shading.seed, 0x5eed5eedULL));
    sources = FindLightSources(scene, sourceWarn, shading.uncorrelated, frameRng);
    AddVirtualSources(scene, shading.direct.relays, sourceWarn, PrismProbe(scene, core, warn),
                      sources);

    obstructorLayouts.reserve(sources.size());
    for (const LightSource& src : sources) {
        obstructorLayouts.push_back(shading.direct.obstructorCache
                                        ? MakeObstructorLayout(src, scene.cubeOrigin, scene.cubeSize)
                                        : ObstructorLayout{});
    }
    reliableBlockers.resize(scene.surfaces.size());
    for (std::size_t i = 0; i < scene.surfaces.size(); ++i) {
        reliableBlockers[i] = IsReliableBlocker(scene, scene.surfaces[i]);
    }

    ambientList.insert(ambient.modifierList.begin(), ambient.modifierList.end());

    shadowCheckCounts.resize(257);
    for (size_t n = 0; n < shadowCheckCounts.size(); ++n) {
        shadowCheckCounts[n] = static_cast<int>(std::pow(double(n), shading.direct.certainty) + 0.5);
    }

    medium = Medium{shading.medium.extinction, shading.medium.albedo, shading.medium.eccentricity};
    hasMedium = Intens(medium.extinction) > 1.0 / kFhuge;
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        if (scene.materials[i].type != MaterialType::Mist) continue;
        mistSources[static_cast<int>(i)] = MistSourceList(scene, sources, scene.materials[i], warn);
    }
    queryShadows = shading.backfaceVisible;
    transmitting = core.HasTransmitting();
}

ThreadState::ThreadState(const ShadingSetup& setup, WarningSink warn_)
    : warn(std::move(warn_)),
      rng(setup.shading.seed),
      sourceTallies(setup.sources.size()),
      obstructors(setup.sources.size()) {
    for (size_t i = 0; i < setup.sources.size(); ++i) {
        sourceTallies[i].aimSuccess = SourceTally::FirstAimCount(setup.sources[i]);
    }
    if (setup.scene.functions) {
        functionContext = std::make_unique<cal::Context>(*setup.scene.functions);
    }
}

void ThreadState::EnableTiming(bool on) {
    timing = on;
    ambient.timing = on;
    if (!on) return;
    // The fastest of a few back-to-back reads: the clock's own cost.
    double fastest = 1.0;
    for (int i = 0; i < 64; ++i) {
        const auto a = std::chrono::steady_clock::now();
        const auto b = std::chrono::steady_clock::now();
        fastest = std::min(fastest, std::chrono::duration<double>(b - a).count());
    }
    clockReadSeconds = fastest;
}

void ThreadState::StartInputRay(const ShadingOptions& shading, std::uint64_t rayIndex) {
    rng.Seed(MixSeed(shading.seed, shading.uncorrelated ? rayIndex : 0));
    firstAmbientSeen = false;
    firstOutcome = RayResult::AmbientOutcome::None;
    firstIndirectIrradiance = Rgb();
}

}  // namespace rt
