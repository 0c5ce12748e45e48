// SPDX-License-Identifier: MIT
//
// The leak test of Radiance 5 (ambient.c plugaleak, radiance-notes.md §4.3):
// a record can pass every distance and normal test and still lie behind a
// wall, for instance on the ground outside a room, a centimetre below the
// floor inside, with a radius of metres because it sees the open sky. The
// classic cache (§4.12) has no such test; without it, second-bounce floor
// queries in the daylit room take those outdoor records and come out bright
// (README, "Differences"). The test ray goes from the query point toward the
// record's position lifted along the record's normal, far enough that the ray
// leaves the query surface 20° above it and so does not graze the surface it
// starts on. As in Radiance 5 it is only sent where the record's corral bits
// saw an occluder nearby in the query's direction: a test for every record
// used would cost more rays than the rest of the calculation
// (docs/measured-choices.md).
#pragma once

#include <cstdint>

#include "ambient/hemisphere.h"
#include "ambient/hessian.h"
#include "ambient/record.h"
#include "core/vecmath.h"

namespace rt {

struct LeakTest {
    enum class Outcome {
        kVisible,  // nothing to trace: the record is in view
        kHidden,   // no ray leaves the query surface toward it: reject the record
        kTrace,    // visible unless something blocks `dir` before `length`
    };
    Outcome outcome = Outcome::kVisible;
    Vec3 dir;            // unit
    double length = 0;   // scene units
};

/// Radiance 5's corral bits (ambcorral, radiance-notes.md §4.7 step 7) for a
/// record made from `hemisphere` (frame u, v = n × u) and valid within
/// `validityRadius` (its radius times -aa): bit k, for azimuths in
/// [kπ/16, (k+1)π/16) from u, is set where a sample next to the horizon hit
/// something closer than the validity radius, that is, where a wall may stand
/// between the record and a query it would accept (however close: unlike
/// Radiance 5, and whatever lies overhead: see leak.cpp). Zero (no test
/// needed) when the hemisphere is incomplete.
std::uint32_t CorralBits(const Hemisphere& hemisphere, double validityRadius);

/// The same for a Radiance 5 hemisphere (ambcorral, §4.7 step 7) and a record
/// with unit u-axis `u` (v = n × u) and validity semi-axes `validityRadius0`
/// along u and `validityRadius1` along v (its radii times -aa): the samples
/// are the cells on the grid's perimeter, each flagging the sectors within
/// π/(2ns) of its azimuth when it hit something nearer than the ellipse's
/// reach in its direction, sqrt((R0·x)² + (R1·y)²)/sqrt(x² + y²). Zero for
/// fewer than 8 cells per axis or an incomplete hemisphere. Unlike Radiance
/// 5, near occluders flag too, and there is no "ceiling too low" rule
/// (leak.cpp says why).
std::uint32_t CorralBits(const HessianHemisphere& hemisphere, const Vec3& u,
                         double validityRadius0, double validityRadius1);

/// True if `record`'s corral bit for the direction of `point` is set, so that
/// the leak test must look (records without bits never leak).
bool CorralCovers(const AmbientRecord& record, const Vec3& point);

/// The leak test for a query at `point` with unit normal `normal` and a
/// record at `recordPoint` with unit normal `recordNormal`. A lift of at most
/// `tolerance` (Scene::distanceTolerance; Radiance's FTINY) needs no ray.
LeakTest MakeLeakTest(const Vec3& point, const Vec3& normal, const Vec3& recordPoint,
                      const Vec3& recordNormal, double tolerance);

}  // namespace rt
