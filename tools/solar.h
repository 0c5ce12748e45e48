// SPDX-License-Identifier: MIT
//
// What the bundled gensky and gendaylit share: the solar position as
// Radiance's sun.c computes it (radiance-functions.md §12.3 step 1), the CIE
// sky normalisations both use for the ground (§12.3 step 3, §12.6 step 8), and
// Radiance's numeric argument conventions, so both programs print exactly what
// Radiance 5.4a prints for the same command line.
//
// Angles are radians; longitudes and meridians are positive west of Greenwich
// (Radiance's convention, §12.1); times are hours.
#pragma once

#include <cstdio>
#include <string>

namespace rt::sky {

/// Radiance's PI; every angle conversion of both programs goes through it.
inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kRadiansPerDegree = kPi / 180;

/// Where the sky is computed. The defaults are Radiance's (San Francisco Bay):
/// 0.66 and 2.13 radians, meridian 120° west.
struct Site {
    double latitude = 0.66;                     // radians, north positive
    double longitude = 2.13;                    // radians, west positive
    double meridian = 120 * kRadiansPerDegree;  // standard meridian, radians west
};

/// Day of the year 1…365 with Radiance's calendar (no leap years).
int DayOfYear(int month, int day);

/// Solar declination (radians) on day `dayOfYear` with the default algorithm.
double Declination(int dayOfYear);

/// Local solar time minus local standard time (hours) on `dayOfYear`: the
/// equation of time plus the site's offset from its standard meridian.
double SolarTimeOffset(int dayOfYear, const Site& site);

/// Sun altitude (radians above the horizon) for declination and solar time.
double SolarAltitude(const Site& site, double declination, double solarTimeHours);

/// Sun azimuth (radians from south, positive towards west).
double SolarAzimuth(const Site& site, double declination, double solarTimeHours);

/// Declination and local solar time of the `-y year` algorithm (Michalsky
/// 1988). `hour` is standard time unless `solarTime`, in which case it is
/// returned unchanged as the solar time.
struct SolarDayTime {
    double declination = 0;     // radians
    double solarTimeHours = 0;  // [0, 24) unless given as solar time
};
SolarDayTime MichalskyPosition(int year, int month, int day, double hour, bool solarTime,
                               const Site& site);

/// Unit vector towards the sun (+x east, +y north, +z zenith).
struct Direction {
    double x = 0, y = 0, z = 0;
};
Direction SunDirection(double altitude, double azimuth);

/// Zenith-luminance distribution factors F2 (the integral normaliser printed
/// as the 4th skybright.cal argument) of the CIE clear and intermediate skies
/// for a sun `altitude` radians high whose direction has z component `sunZ`.
double ClearSkyF2(double altitude, double sunZ);
double IntermediateSkyF2(double altitude);

/// Horizontal diffuse irradiance over π·(zenith radiance) for each CIE sky.
inline constexpr double kOvercastNormalisation = 0.777778;
double ClearSkyNormalisation(double altitude, double f2);
double IntermediateSkyNormalisation(double altitude, double f2);

/// C's atof/atoi: Radiance reads every numeric argument with them, so a word
/// like "40deg" is 40 and "abc" is 0 rather than an error.
double LenientReal(const char* word);
int LenientInteger(const char* word);

/// The leading comment both programs write: "# argv[0] arg1 …". gensky quotes
/// words containing white space, with ' when the word holds a " and no ', with "
/// otherwise; gendaylit writes them as they are.
void PrintCommandLine(std::FILE* out, int argc, char** argv, bool quoteBlanks);

}  // namespace rt::sky
