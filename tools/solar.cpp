// SPDX-License-Identifier: MIT
//
// Solar position and CIE sky normalisations shared by gensky and gendaylit
// (radiance-functions.md §12.3, §12.6). The formulas are the published ones
// Radiance's sun.c and gensky.c use; the order of operations follows the
// specification so that printed digits agree with Radiance's.
#include "solar.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace rt::sky {

int DayOfYear(int month, int day) {
    // Days before each month of a 365-day year.
    static constexpr int kDaysBefore[12] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
    return kDaysBefore[month - 1] + day;
}

double Declination(int dayOfYear) { return 0.4093 * std::sin((2 * kPi / 365) * (dayOfYear - 81)); }

double SolarTimeOffset(int dayOfYear, const Site& site) {
    return 0.170 * std::sin((4 * kPi / 373) * (dayOfYear - 80)) -
           0.129 * std::sin((2 * kPi / 355) * (dayOfYear - 8)) +
           12 * (site.meridian - site.longitude) / kPi;
}

double SolarAltitude(const Site& site, double declination, double solarTimeHours) {
    return std::asin(std::sin(site.latitude) * std::sin(declination) -
                     std::cos(site.latitude) * std::cos(declination) *
                         std::cos(solarTimeHours * (kPi / 12)));
}

double SolarAzimuth(const Site& site, double declination, double solarTimeHours) {
    return -std::atan2(std::cos(declination) * std::sin(solarTimeHours * (kPi / 12)),
                       -std::cos(site.latitude) * std::sin(declination) -
                           std::sin(site.latitude) * std::cos(declination) *
                               std::cos(solarTimeHours * (kPi / 12)));
}

namespace {

// x reduced to [0, period).
double Wrap(double x, double period) {
    x = std::fmod(x, period);
    return x < 0 ? x + period : x;
}

}  // namespace

SolarDayTime MichalskyPosition(int year, int month, int day, double hour, bool solarTime,
                               const Site& site) {
    int dayOfYear = DayOfYear(month, day);
    if (month > 2 && year % 4 == 0) ++dayOfYear;
    const int yearsSince1949 = year - 1949;
    // Days from the J2000.0 epoch (Julian date 2451545.0) to the given
    // universal time; 2432916.5 is the Julian date of 1949 January 0, 0h UT.
    const double n = 2432916.5 + 365 * yearsSince1949 + yearsSince1949 / 4 + dayOfYear +
                     (hour + 12 * site.meridian / kPi) / 24 - 2451545.0;
    const double meanLongitude = Wrap(280.460 + 0.9856474 * n, 360);   // degrees
    const double meanAnomaly = Wrap(357.528 + 0.9856003 * n, 360);     // degrees
    const double eclipticLongitude =
        (meanLongitude + 1.915 * std::sin(meanAnomaly * kRadiansPerDegree) +
         0.020 * std::sin(2 * meanAnomaly * kRadiansPerDegree)) *
        kRadiansPerDegree;
    const double obliquity = (23.439 - 0.0000004 * n) * kRadiansPerDegree;
    SolarDayTime result;
    result.declination = std::asin(std::sin(obliquity) * std::sin(eclipticLongitude));
    if (solarTime) {
        result.solarTimeHours = hour;
        return result;
    }
    const double rightAscension = std::atan2(std::sin(eclipticLongitude) * std::cos(obliquity),
                                             std::cos(eclipticLongitude));  // radians
    const double universalTime = 24 * (n - std::floor(n)) + 12;           // hours
    const double greenwichSidereal = 6.697375 + 0.0657098242 * n + universalTime;
    const double localSidereal = greenwichSidereal - 12 * site.longitude / kPi;
    result.solarTimeHours = Wrap(localSidereal - 12 * rightAscension / kPi + 12, 24);
    return result;
}

Direction SunDirection(double altitude, double azimuth) {
    return {-std::sin(azimuth) * std::cos(altitude), -std::cos(azimuth) * std::cos(altitude),
            std::sin(altitude)};
}

double ClearSkyF2(double altitude, double sunZ) {
    return 0.274 * (0.91 + 10 * std::exp(-3 * (kPi / 2 - altitude)) + 0.45 * sunZ * sunZ);
}

double IntermediateSkyF2(double altitude) {
    return (2.739 + 0.9891 * std::sin(0.3119 + 2.6 * altitude)) *
           std::exp(-(kPi / 2 - altitude) * (0.4441 + 1.48 * altitude));
}

namespace {

// Argument of the horizontal-illuminance polynomials: 0 at 45° altitude.
double NormalisedAltitude(double altitude) { return (altitude - kPi / 4) / (kPi / 4); }

}  // namespace

double ClearSkyNormalisation(double altitude, double f2) {
    const double x = NormalisedAltitude(altitude);
    const double polynomial =
        2.766521 + x * (0.547665 + x * (-0.369832 + x * (0.009237 + x * 0.059229)));
    return polynomial / f2 / kPi;
}

double IntermediateSkyNormalisation(double altitude, double f2) {
    const double x = NormalisedAltitude(altitude);
    const double polynomial =
        3.5556 + x * (-2.7152 + x * (-1.3081 + x * (1.0660 + x * 0.60227)));
    return polynomial / f2 / kPi;
}

double LenientReal(const char* word) { return std::atof(word); }

int LenientInteger(const char* word) { return std::atoi(word); }

void PrintCommandLine(std::FILE* out, int argc, char** argv, bool quoteBlanks) {
    std::fputc('#', out);
    for (int i = 0; i < argc; ++i) {
        const char* word = argv[i];
        bool blank = false;
        for (const char* c = word; *c != '\0'; ++c) {
            if (std::isspace(static_cast<unsigned char>(*c))) blank = true;
        }
        if (!quoteBlanks || !blank) {
            std::fprintf(out, " %s", word);
            continue;
        }
        const char quote =
            std::strchr(word, '"') != nullptr && std::strchr(word, '\'') == nullptr ? '\'' : '"';
        std::fprintf(out, " %c%s%c", quote, word, quote);
    }
    std::fputc('\n', out);
}

}  // namespace rt::sky
