// SPDX-License-Identifier: MIT
//
// gensky: writes a CIE sky (clear, intermediate, overcast or uniform) as a
// `skybr` brightfunc over skybright.cal, with an optional sun, exactly as
// Radiance 5.4a's gensky does (radiance-functions.md §12.2–§12.4), so
// `!gensky …` scene lines work without Radiance and give the same scene.
//
//   gensky month day hour [options]
//   gensky -ang altitude azimuth [options]
//   gensky -defaults
//
// Numbers are read as Radiance reads them (C's atof/atoi, so "abc" is 0).
// Radiance's usage errors also print the usage; ours are the same first line
// only. A missing option value, which crashes Radiance, is an error here.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "solar.h"

namespace {

using namespace rt::sky;

enum class SkyType { Clear = 1, Overcast = 2, Uniform = 3, Intermediate = 4 };

// Photometric-to-Radiance conversions gensky uses (lm/W), §12.1.
constexpr double kSkyEfficacy = 203;
constexpr double kSunEfficacy = 208;
// Solid angle (sr) gensky assumes for the sun when converting irradiance.
constexpr double kSunSolidAngle = 6e-5;

struct Options {
    SkyType sky = SkyType::Clear;
    bool sun = true;
    // How the user set the zenith radiance: 0 not at all, 'b' as radiance
    // (W/sr/m²), 'B' as horizontal diffuse irradiance (W/m²).
    char zenithGiven = 0;
    double zenithValue = 0;
    // Likewise for the sun: 'r' radiance, 'R' horizontal direct irradiance.
    char solarGiven = 0;
    double solarValue = 0;
    double turbidity = 2.45;
    double groundReflectance = 0.2;
    Site site;
    int year = 0;  // 0: the default solar position algorithm
};

// North American and European time zones and their standard meridians
// (degrees west). The second AST, ADT and NDT can never match; Radiance lists
// them anyway, and its "unknown time zone" help prints them.
struct TimeZone {
    const char* name;
    double meridianDegrees;
};
constexpr TimeZone kTimeZones[] = {
    {"YST", 135},  {"YDT", 120},  {"PST", 120},   {"PDT", 105},  {"MST", 105},  {"MDT", 90},
    {"CST", 90},   {"CDT", 75},   {"EST", 75},    {"EDT", 60},   {"AST", 60},   {"ADT", 45},
    {"NST", 52.5}, {"NDT", 37.5}, {"GMT", 0},     {"BST", -15},  {"CET", -15},  {"CEST", -30},
    {"EET", -30},  {"EEST", -45}, {"AST", -45},   {"ADT", -60},  {"GST", -60},  {"GDT", -75},
    {"IST", -82.5}, {"IDT", -97.5}, {"JST", -135}, {"NDT", -150}, {"NZST", -180},
    {"NZDT", -195},
};

[[noreturn]] void UseError(const char* program, const std::string& message) {
    std::fprintf(stderr, "%s: Use error - %s\n", program, message.c_str());
    std::exit(1);
}

struct Hour {
    double hours = 0;
    bool solarTime = false;   // a leading '+': local solar time
    bool zoneGiven = false;   // a zone suffix set the standard meridian
    double zoneMeridian = 0;  // radians west
};

// `H`, `H.hh` or `H:MM`, a leading '+' for solar time, or a zone suffix on
// standard time. Exits on a malformed time or an unknown zone.
Hour ParseHour(const char* program, const char* text) {
    Hour hour;
    const char* cp = text;
    hour.solarTime = *cp == '+';
    if (hour.solarTime) ++cp;
    while (std::isdigit(static_cast<unsigned char>(*cp))) ++cp;
    if (*cp == ':') {
        ++cp;
        hour.hours = LenientInteger(text) + LenientInteger(cp) / 60.0;
    } else {
        hour.hours = LenientReal(text);
        if (*cp == '.') ++cp;
    }
    while (std::isdigit(static_cast<unsigned char>(*cp))) ++cp;
    if (*cp == '\0') return hour;
    if (hour.solarTime || !std::isalpha(static_cast<unsigned char>(*cp))) {
        std::fprintf(stderr, "%s: bad time format: %s\n", program, text);
        std::exit(1);
    }
    std::string zone;
    for (const char* c = cp; *c != '\0'; ++c) {
        zone += static_cast<char>(std::toupper(static_cast<unsigned char>(*c)));
    }
    for (const TimeZone& z : kTimeZones) {
        if (zone == z.name) {
            hour.zoneGiven = true;
            hour.zoneMeridian = z.meridianDegrees * kRadiansPerDegree;
            return hour;
        }
    }
    std::fprintf(stderr, "%s: unknown time zone: %s\n", program, cp);
    std::exit(1);
}

void PrintDefaults(const Options& o) {
    std::printf("%s\t\t\t\t# Sunny sky with sun\n", "+s");
    std::printf("-g %f\t\t\t# Ground plane reflectance\n", o.groundReflectance);
    std::printf("-t %f\t\t\t# Atmospheric turbidity\n", o.turbidity);
    std::printf("-a %f\t\t\t# Site latitude (degrees)\n", o.site.latitude / kRadiansPerDegree);
    std::printf("-o %f\t\t\t# Site longitude (degrees)\n", o.site.longitude / kRadiansPerDegree);
    std::printf("-m %f\t\t\t# Standard meridian (degrees)\n", o.site.meridian / kRadiansPerDegree);
}

}  // namespace

int main(int argc, char** argv) {
    const char* program = argv[0];
    Options o;
    if (argc == 2 && std::strcmp(argv[1], "-defaults") == 0) {
        PrintDefaults(o);
        return 0;
    }
    if (argc < 4) UseError(program, "arg count");

    // Date form (month > 0) or explicit sun angles (month 0).
    int month = 0, day = 0;
    Hour hour;
    double altitude = 0, azimuth = 0;  // radians
    if (std::strcmp(argv[1], "-ang") == 0) {
        altitude = LenientReal(argv[2]) * kRadiansPerDegree;
        azimuth = LenientReal(argv[3]) * kRadiansPerDegree;
    } else {
        month = LenientInteger(argv[1]);
        if (month < 1 || month > 12) UseError(program, "bad month");
        day = LenientInteger(argv[2]);
        if (day < 1 || day > 31) UseError(program, "bad day");
        hour = ParseHour(program, argv[3]);
        if (hour.zoneGiven) o.site.meridian = hour.zoneMeridian;
    }

    for (int i = 4; i < argc; ++i) {
        const char* word = argv[i];
        if (word[0] != '-' && word[0] != '+') UseError(program, "bad option");
        // Only the letter after the sign counts: "-sun" is "-s", as in Radiance.
        const char letter = word[1];
        auto value = [&]() -> const char* {
            if (i + 1 >= argc) UseError(program, std::string("missing value for ") + word);
            return argv[++i];
        };
        switch (letter) {
            case 's':
            case 'i':
                o.sky = letter == 's' ? SkyType::Clear : SkyType::Intermediate;
                o.sun = word[0] == '+';
                break;
            case 'c':
            case 'u':
                o.sky = letter == 'c' ? SkyType::Overcast : SkyType::Uniform;
                o.sun = false;
                break;
            case 'r':
            case 'R':
                o.solarGiven = letter;
                o.solarValue = LenientReal(value());
                break;
            case 'b':
            case 'B':
                o.zenithGiven = letter;
                o.zenithValue = LenientReal(value());
                break;
            case 't':
                o.turbidity = LenientReal(value());
                break;
            case 'g':
                o.groundReflectance = LenientReal(value());
                break;
            case 'a':
                o.site.latitude = LenientReal(value()) * kRadiansPerDegree;
                break;
            case 'o':
                o.site.longitude = LenientReal(value()) * kRadiansPerDegree;
                break;
            case 'm': {
                const char* meridian = value();
                // A time zone on the hour wins over -m.
                if (!hour.zoneGiven) o.site.meridian = LenientReal(meridian) * kRadiansPerDegree;
                break;
            }
            case 'y':
                o.year = LenientInteger(value());
                if (o.year < 1950 || o.year > 2050) {
                    std::fprintf(stderr, "%s: warning - year should be in range 1950-2050\n",
                                 program);
                }
                break;
            default:
                UseError(program, std::string("unknown option: ") + word);
        }
    }

    double solarTime = 0;  // hours; date form only
    if (month != 0) {
        if (!hour.solarTime && std::fabs(o.site.meridian - o.site.longitude) > 45 * kRadiansPerDegree) {
            std::fprintf(stderr, "%s: warning - %.1f hours btwn. standard meridian and longitude\n",
                         program, (o.site.longitude - o.site.meridian) * 12 / kPi);
        }
        double declination;
        if (o.year != 0) {
            const SolarDayTime t =
                MichalskyPosition(o.year, month, day, hour.hours, hour.solarTime, o.site);
            declination = t.declination;
            solarTime = t.solarTimeHours;
        } else {
            const int dayOfYear = DayOfYear(month, day);
            declination = Declination(dayOfYear);
            solarTime = hour.hours;
            if (!hour.solarTime) solarTime += SolarTimeOffset(dayOfYear, o.site);
        }
        altitude = SolarAltitude(o.site, declination, solarTime);
        azimuth = SolarAzimuth(o.site, declination, solarTime);
    }
    const double printedAltitude = altitude;

    // The CIE clear and intermediate formulas are not valid with the sun
    // near the zenith.
    const bool hasSunTerm = o.sky == SkyType::Clear || o.sky == SkyType::Intermediate;
    const bool tooHigh = hasSunTerm && altitude > 87 * kRadiansPerDegree;
    if (tooHigh) {
        std::fprintf(stderr,
                     "%s: warning - sun too close to zenith, reducing altitude to 87 degrees\n",
                     program);
        altitude = 87 * kRadiansPerDegree;
    }
    const Direction sun = SunDirection(altitude, azimuth);

    // F2 and the normalisation K = (horizontal diffuse irradiance)/(π·Lz).
    double f2 = 1, normalisation = 1;
    switch (o.sky) {
        case SkyType::Clear:
            f2 = ClearSkyF2(altitude, sun.z);
            normalisation = ClearSkyNormalisation(altitude, f2);
            break;
        case SkyType::Intermediate:
            f2 = IntermediateSkyF2(altitude);
            normalisation = IntermediateSkyNormalisation(altitude, f2);
            break;
        case SkyType::Overcast:
            normalisation = kOvercastNormalisation;
            break;
        case SkyType::Uniform:
            break;
    }

    // Zenith radiance Lz (W/sr/m²); the CIE formulas give kcd/m².
    double zenith;
    if (o.zenithGiven == 'b') {
        zenith = o.zenithValue;
    } else if (o.zenithGiven == 'B') {
        zenith = o.zenithValue / (kPi * normalisation);
    } else {
        const double overcast = 8.6 * sun.z + 0.123;
        const double clear = (1.376 * o.turbidity - 1.81) * std::tan(altitude) + 0.38;
        switch (o.sky) {
            case SkyType::Clear:
                zenith = clear;
                break;
            case SkyType::Intermediate:
                zenith = (clear + overcast) / 2;
                break;
            default:
                zenith = overcast;
                break;
        }
        zenith = zenith < 0 ? 0 : zenith * (1000 / kSkyEfficacy);
    }

    const double groundAmbient = zenith * normalisation;
    double ground = groundAmbient;
    // The sun lights the ground even when `-s`/`-i` leave its source out.
    const bool sunShines =
        hasSunTerm && sun.z > 0 && (o.solarGiven == 0 || o.solarValue > 0);
    const bool withSun = o.sun && sunShines;
    double solar = 0;  // sun radiance, W/sr/m²
    if (sunShines) {
        if (o.solarGiven == 'r') {
            solar = o.solarValue;
        } else if (o.solarGiven == 'R') {
            solar = o.solarValue / (kSunSolidAngle * sun.z);
        } else {
            solar = 1.5e9 / kSunEfficacy * (1.147 - 0.147 / (sun.z > 0.16 ? sun.z : 0.16));
            if (o.sky == SkyType::Intermediate) solar *= 0.15;
        }
        ground += kSunSolidAngle / kPi * solar * sun.z;
    }
    ground *= o.groundReflectance;

    rt::sky::PrintCommandLine(stdout, argc, argv, true);
    if (month != 0) {
        std::printf("# Local solar time: %.2f\n", solarTime);
        std::printf("# Solar altitude and azimuth: %.1f %.1f\n", printedAltitude / kRadiansPerDegree,
                    azimuth / kRadiansPerDegree);
    }
    if (tooHigh) {
        std::printf("# warning - sun too close to zenith, reducing altitude to 87 degrees\n");
    }
    std::printf("# Ground ambient level: %.1f\n", groundAmbient);
    if (withSun) {
        std::printf("\nvoid light solar\n0\n0\n3 %.2e %.2e %.2e\n", solar, solar, solar);
        std::printf("\nsolar source sun\n0\n0\n4 %f %f %f 0.5\n", sun.x, sun.y, sun.z);
    }
    std::printf("\nvoid brightfunc skyfunc\n2 skybr skybright.cal\n0\n");
    if (hasSunTerm) {
        std::printf("7 %d %.2e %.2e %.2e %f %f %f\n", static_cast<int>(o.sky), zenith, ground, f2,
                    sun.x, sun.y, sun.z);
    } else {
        std::printf("3 %d %.2e %.2e\n", static_cast<int>(o.sky), zenith, ground);
    }
    return std::fflush(stdout) == 0 ? 0 : 1;
}
