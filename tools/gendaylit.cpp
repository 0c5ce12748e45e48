// SPDX-License-Identifier: MIT
//
// gendaylit: writes the Perez all-weather sky (Perez, Seals & Michalsky 1993)
// for measured or given daylight as a `skybright` brightfunc over perezlum.cal,
// with the sun as a light source, exactly as Radiance 5.4a's gendaylit 2.5
// does (radiance-functions.md §12.6–§12.7). Irradiance is converted to
// illuminance with the Perez et al. (1990) luminous efficacy models.
//
//   gendaylit month day hour [options]
//   gendaylit -ang altitude azimuth [options]
//   gendaylit -defaults
//
// Inputs: -P ε Δ, -W Idn Idh, -G Ibh Idh, -L Edn Edh (lux), -E Igh (split
// with the Erbs correlation). Options: +s/-s, -c, -g, -a, -o, -m, -y, -d, -i,
// -O 0|1|2, -w. The coloured sky (-C, -l) is not supported: a clear error.
// Usage errors are Radiance's first line only; a missing option value, which
// crashes Radiance, is an error here.
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "solar.h"

namespace {

using namespace rt::sky;

// Solar constant (W/m²) and its illuminance (lux) as gendaylit uses them.
constexpr double kSolarConstant = 1367;
constexpr double kSolarIlluminance = 127500;
constexpr double kWhiteEfficacy = 179;  // lm/W, Radiance's visible radiance
// Half-angle (degrees) of the sun disk whose solid angle converts the direct
// normal quantity to sun radiance.
constexpr double kSunHalfAngleDegrees = 0.2665;
// Solid angle (sr) the ground term assumes for the sun.
constexpr double kGroundSunSolidAngle = 6.8e-5;
// Default dew point (°C): precipitable water exp(0.07·Td − 0.075) = 2 cm.
constexpr double kDefaultDewPoint = 10.97353115;

// Perez, Seals & Michalsky (1993) Table 1: for each sky-clearness bin, the
// coefficients x1…x4 of a, b, c, d, e in x = x1 + x2·Z + Δ(x3 + x4·Z).
// Kept in single precision, as gendaylit stores them.
constexpr float kLuminanceCoefficients[8][5][4] = {
    {{1.3525f, -0.2576f, -0.2690f, -1.4366f},
     {-0.7670f, 0.0007f, 1.2734f, -0.1233f},
     {2.8000f, 0.6004f, 1.2375f, 1.0000f},
     {1.8734f, 0.6297f, 0.9738f, 0.2809f},
     {0.0356f, -0.1246f, -0.5718f, 0.9938f}},
    {{-1.2219f, -0.7730f, 1.4148f, 1.1016f},
     {-0.2054f, 0.0367f, -3.9128f, 0.9156f},
     {6.9750f, 0.1774f, 6.4477f, -0.1239f},
     {-1.5798f, -0.5081f, -1.7812f, 0.1080f},
     {0.2624f, 0.0672f, -0.2190f, -0.4285f}},
    {{-1.1000f, -0.2515f, 0.8952f, 0.0156f},
     {0.2782f, -0.1812f, -4.5000f, 1.1766f},
     {24.7219f, -13.0812f, -37.7000f, 34.8438f},
     {-5.0000f, 1.5218f, 3.9229f, -2.6204f},
     {-0.0156f, 0.1597f, 0.4199f, -0.5562f}},
    {{-0.5484f, -0.6654f, -0.2672f, 0.7117f},
     {0.7234f, -0.6219f, -5.6812f, 2.6297f},
     {33.3389f, -18.3000f, -62.2500f, 52.0781f},
     {-3.5000f, 0.0016f, 1.1477f, 0.1062f},
     {0.4659f, -0.3296f, -0.0876f, -0.0329f}},
    {{-0.6000f, -0.3566f, -2.5000f, 2.3250f},
     {0.2937f, 0.0496f, -5.6812f, 1.8415f},
     {21.0000f, -4.7656f, -21.5906f, 7.2492f},
     {-3.5000f, -0.1554f, 1.4062f, 0.3988f},
     {0.0032f, 0.0766f, -0.0656f, -0.1294f}},
    {{-1.0156f, -0.3670f, 1.0078f, 1.4051f},
     {0.2875f, -0.5328f, -3.8500f, 3.3750f},
     {14.0000f, -0.9999f, -7.1406f, 7.5469f},
     {-3.4000f, -0.1078f, -1.0750f, 1.5702f},
     {-0.0672f, 0.4016f, 0.3017f, -0.4844f}},
    {{-1.0000f, 0.0211f, 0.5025f, -0.5119f},
     {-0.3000f, 0.1922f, 0.7023f, -1.6317f},
     {19.0000f, -5.0000f, 1.2438f, -1.9094f},
     {-4.0000f, 0.0250f, 0.3844f, 0.2656f},
     {1.0468f, -0.3788f, -2.4517f, 1.4656f}},
    {{-1.0500f, 0.0289f, 0.4260f, 0.3590f},
     {-0.3250f, 0.1156f, 0.7781f, 0.0025f},
     {31.0625f, -14.5000f, -46.1148f, 55.3750f},
     {-7.2312f, 0.4050f, 13.3500f, 0.6234f},
     {1.5000f, -0.6426f, 1.8564f, 0.5636f}},
};

// Perez et al. (1990) luminous efficacy (lm/W) per clearness bin: diffuse
// Kd = a + b·W + c·cos Z + d·ln Δ, direct Kb = a + b·W + c·e^(5.73Z−5) + d·Δ.
struct Efficacy {
    double a, b, c, d;
};
constexpr Efficacy kDiffuseEfficacy[8] = {
    {97.24, -0.46, 12.00, -8.91},   {107.22, 1.15, 0.59, -3.95},  {104.97, 2.96, -5.53, -8.77},
    {102.39, 5.59, -13.95, -13.90}, {100.71, 5.94, -22.75, -23.74}, {106.42, 3.83, -36.15, -28.83},
    {141.88, 1.90, -53.24, -14.03}, {152.23, 0.35, -45.27, -7.98},
};
constexpr Efficacy kDirectEfficacy[8] = {
    {57.20, -4.55, -2.98, 117.12}, {98.99, -3.46, -1.21, 12.38},  {109.83, -4.90, -1.71, -8.81},
    {110.34, -5.84, -1.99, -4.56}, {106.36, -3.97, -1.75, -6.16}, {107.19, -1.25, -1.51, -26.73},
    {105.75, 0.77, -1.26, -34.44}, {101.18, 1.58, -1.10, -8.29},
};
// Lower bounds of the clearness bins; the efficacy tables end at 12.01
// (diffuse) and 12.1 (direct).
constexpr double kClearnessBins[8] = {1, 1.065, 1.230, 1.500, 1.950, 2.800, 4.500, 6.200};

// The clearness bin of ε for the efficacy models; -1 outside [1, upper).
int EfficacyBin(double epsilon, double upper) {
    for (int bin = 7; bin >= 0; --bin) {
        const double high = bin == 7 ? upper : kClearnessBins[bin + 1];
        if (epsilon >= kClearnessBins[bin] && epsilon < high) return bin;
    }
    return -1;
}

enum class Input { Perez, DirectNormal, DirectHorizontal, Illuminance, Global };

enum class Output { Visible = 0, Solar = 1, Luminance = 2 };

struct Options {
    Input input = Input::Perez;
    double value1 = 0, value2 = 0;  // the input's two numbers (or one, -E)
    bool sun = true;
    bool limitAltitude = true;  // -c lifts the 87° limit (and the sun)
    bool warnings = true;
    double groundReflectance = 0.2;
    double dewPoint = kDefaultDewPoint;  // °C
    int outputType = 0;                  // -O, checked when output starts
    double intervalMinutes = 0;          // -i: time step around sunrise/sunset
    bool intervalGiven = false;
    Site site;
    int year = 0;
};

[[noreturn]] void UseError(const char* program, const std::string& message) {
    std::fprintf(stderr, "%s: Use error - %s\n", program, message.c_str());
    std::exit(1);
}

// Radiance's "Warning: …" lines, which -w silences.
void Warn(const Options& o, const char* format, ...) __attribute__((format(printf, 2, 3)));
void Warn(const Options& o, const char* format, ...) {
    if (!o.warnings) return;
    va_list args;
    va_start(args, format);
    std::vfprintf(stderr, format, args);
    va_end(args);
}

// Relative Perez luminance of a sky point θ from the zenith and γ from the sun.
struct PerezCoefficients {
    double a = 0, b = 0, c = 0, d = 0, e = 0;
    double RelativeLuminance(double cosTheta, double gamma) const {
        const double cosGamma = std::cos(gamma);
        return (1 + a * std::exp(b / cosTheta)) *
               (1 + c * std::exp(d * gamma) + e * cosGamma * cosGamma);
    }
};

PerezCoefficients Coefficients(double epsilon, double delta, double zenith) {
    // gendaylit picks the bin from ε in single precision: ε = 1.065 falls in
    // the second bin and ε = 2.8 in the fifth.
    const float binEpsilon = static_cast<float>(epsilon);
    int bin = 7;
    for (int k = 1; k < 8; ++k) {
        if (binEpsilon < kClearnessBins[k]) {
            bin = k - 1;
            break;
        }
    }
    // gendaylit floors the brightness of intermediate skies at 0.2 (in
    // double precision, unlike the bin choice).
    if (epsilon > 1.065 && epsilon < 2.8 && delta < 0.2) delta = 0.2;
    const float(&t)[5][4] = kLuminanceCoefficients[bin];
    auto linear = [&](int k) {
        return t[k][0] + t[k][1] * zenith + delta * (t[k][2] + t[k][3] * zenith);
    };
    PerezCoefficients p;
    p.a = linear(0);
    p.b = linear(1);
    p.e = linear(4);
    if (bin == 0) {
        p.c = std::exp(std::pow(delta * (t[2][0] + t[2][1] * zenith), t[2][2])) - t[2][3];
        p.d = -std::exp(delta * (t[3][0] + t[3][1] * zenith)) + t[3][2] + delta * t[3][3];
    } else {
        p.c = linear(2);
        p.d = linear(3);
    }
    return p;
}

// The 145 sky points (zenith angle, azimuth from the sun, degrees) over which
// the relative luminance is integrated to normalise the sky: rings of 30, 30,
// 24, 24, 18, 12 and 6 points and the zenith.
double NormalisationIntegral(const PerezCoefficients& p, double zenith) {
    struct Ring {
        int theta, count, step;
    };
    constexpr Ring kRings[] = {{84, 30, 12}, {72, 30, 12}, {60, 24, 15}, {48, 24, 15},
                               {36, 18, 20}, {24, 12, 30}, {12, 6, 60},  {0, 1, 0}};
    double sum = 0;
    for (const Ring& ring : kRings) {
        for (int k = 0; k < ring.count; ++k) {
            const float theta = static_cast<float>(ring.theta * kRadiansPerDegree);
            const float phi = static_cast<float>(k * ring.step * kRadiansPerDegree);
            const double cosGamma = std::cos(zenith) * std::cos(theta) +
                              std::sin(zenith) * std::sin(theta) * std::cos(phi);
            const double gamma = cosGamma > 1 && cosGamma < 1.1 ? 0 : std::acos(cosGamma);
            sum += p.RelativeLuminance(std::cos(theta), gamma) * std::cos(theta);
        }
    }
    return 2 * kPi / 145 * sum;
}

void PrintErrorSky(double solarTime, double altitude, double azimuth, const Direction& sun) {
    std::printf("# Local solar time: %.2f\n", solarTime);
    // Degrees as Radiance prints them (x·180/π, which can round the other
    // way from x/(π/180) at the printed digit: 43.45° input prints 43.4).
    std::printf("# Solar altitude and azimuth: %.1f %.1f\n", altitude * 180 / kPi,
                azimuth * 180 / kPi);
    std::printf("\nvoid brightfunc skyfunc\n2 skybright perezlum.cal\n0\n");
    std::printf("10 0.00 0.00  0.000 0.000 0.000 0.000 0.000  %f %f %f \n", sun.x, sun.y, sun.z);
}

void PrintDefaults(const Options& o) {
    std::printf("-g %f\t\t\t# Ground plane reflectance\n", o.groundReflectance);
    std::printf("-t %f\t\t\t# Atmospheric betaturbidity\n", 0.1);
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

    int month = 0, day = 0;
    double hour = 0;  // as given, hours
    bool solarTimeGiven = false;
    double altitude = 0, azimuth = 0;  // radians
    if (std::strcmp(argv[1], "-ang") == 0) {
        altitude = LenientReal(argv[2]) * kRadiansPerDegree;
        azimuth = LenientReal(argv[3]) * kRadiansPerDegree;
    } else {
        month = LenientInteger(argv[1]);
        if (month < 1 || month > 12) UseError(program, "bad month");
        day = LenientInteger(argv[2]);
        if (day < 1 || day > 31) UseError(program, "bad day");
        const char* h = argv[3];
        solarTimeGiven = h[0] == '+';
        hour = LenientReal(solarTimeGiven ? h + 1 : h);
        if (hour < 0 || hour >= 24) UseError(program, "bad hour");
    }

    for (int i = 4; i < argc; ++i) {
        const char* word = argv[i];
        if (word[0] != '-' && word[0] != '+') UseError(program, "bad option");
        auto value = [&]() -> const char* {
            if (i + 1 >= argc) UseError(program, std::string("missing value for ") + word);
            return argv[++i];
        };
        switch (word[1]) {
            case 's':
                o.sun = word[0] == '+';
                break;
            case 'c':
                o.sun = false;
                o.limitAltitude = false;
                break;
            case 'w':
                o.warnings = false;
                break;
            case 'C':
            case 'l':
                std::fprintf(stderr, "%s: the coloured sky (%s) is not supported\n", program, word);
                return 1;
            case 'P':
            case 'W':
            case 'L':
            case 'G':
                o.input = word[1] == 'P'   ? Input::Perez
                          : word[1] == 'W' ? Input::DirectNormal
                          : word[1] == 'L' ? Input::Illuminance
                                           : Input::DirectHorizontal;
                o.value1 = LenientReal(value());
                o.value2 = LenientReal(value());
                break;
            case 'E':
                o.input = Input::Global;
                o.value1 = LenientReal(value());
                break;
            case 'O':
                o.outputType = LenientInteger(value());
                break;
            case 'g':
                o.groundReflectance = LenientReal(value());
                break;
            case 'd':
                o.dewPoint = LenientReal(value());
                break;
            case 'i':
                o.intervalMinutes = LenientReal(value());
                o.intervalGiven = true;
                break;
            case 'a':
                o.site.latitude = LenientReal(value()) * kRadiansPerDegree;
                break;
            case 'o':
                o.site.longitude = LenientReal(value()) * kRadiansPerDegree;
                break;
            case 'm':
                o.site.meridian = LenientReal(value()) * kRadiansPerDegree;
                break;
            case 'y':
                o.year = LenientInteger(value());
                break;
            case 't':  // turbidity and brightness: read but unused, as in Radiance
            case 'b':
            case 'R':
                value();
                break;
            default:
                UseError(program, std::string("unknown option: ") + word);
        }
    }

    rt::sky::PrintCommandLine(stdout, argc, argv, false);
    if (o.intervalGiven && o.intervalMinutes < 0) {
        std::fprintf(stderr, "time interval negative\n");
        return 1;
    }
    if (o.dewPoint < -40 || o.dewPoint > 40) o.dewPoint = kDefaultDewPoint;
    const double water = std::exp(0.07 * o.dewPoint - 0.075);  // precipitable, cm

    int dayOfYear = 0;
    double solarTime = 0;
    if (month != 0) {
        if (!solarTimeGiven &&
            std::fabs(o.site.meridian - o.site.longitude) > 45 * kRadiansPerDegree) {
            std::fprintf(stderr, "%s: warning: %.1f hours btwn. standard meridian and longitude\n",
                         program, (o.site.longitude - o.site.meridian) * 12 / kPi);
        }
        dayOfYear = DayOfYear(month, day);
        double declination;
        if (o.year != 0) {
            const SolarDayTime t =
                MichalskyPosition(o.year, month, day, hour, solarTimeGiven, o.site);
            declination = t.declination;
            solarTime = t.solarTimeHours;
        } else {
            declination = Declination(dayOfYear);
            solarTime = hour;
            if (!solarTimeGiven) solarTime += SolarTimeOffset(dayOfYear, o.site);
        }
        // Sunrise and sunset, local solar time (hours). NaN in polar day and
        // night, which then never count as before sunrise or after sunset.
        const double w = -std::tan(o.site.latitude) * std::tan(Declination(dayOfYear));
        const double halfDay = (kPi / 2 - std::atan2(w, std::sqrt(1 - w * w))) * 180 / (15 * kPi);
        const double sunrise = 12 - halfDay, sunset = 12 + halfDay;
        bool errorSky = false;
        double correctedTime = solarTime;
        if (o.intervalGiven) {
            const double half = o.intervalMinutes / 120;  // hours
            if (solarTime + half < sunrise || solarTime - half > sunset) {
                Warn(o, "Warning: sun position too low, printing error sky at %d %d %.3f\n",
             month, day, hour);
                errorSky = true;
            } else if (solarTime - half < sunrise) {
                correctedTime = (sunrise + solarTime + half) / 2;
            } else if (solarTime + half > sunset) {
                correctedTime = (solarTime - half + sunset) / 2;
            }
            if (!errorSky && correctedTime != solarTime) {
                Warn(o, "Solar position corrected at time step %d %d %.3f\n", month, day, hour);
            }
        } else if (solarTime < sunrise || solarTime > sunset) {
            Warn(o, "Warning: sun altitude below zero at time step %d %d %.2f, printing error sky\n",
             month, day, hour);
            errorSky = true;
        }
        if (errorSky) {
            const double a = SolarAltitude(o.site, declination, solarTime);
            const double z = SolarAzimuth(o.site, declination, solarTime);
            PrintErrorSky(solarTime, a, z, SunDirection(a, z));
            return 0;
        }
        solarTime = correctedTime;
        altitude = SolarAltitude(o.site, declination, solarTime);
        azimuth = SolarAzimuth(o.site, declination, solarTime);
    }
    if (o.outputType < 0 || o.outputType > 2) {
        std::fprintf(stderr, "Wrong output specification.\n");
        return 1;
    }
    const Output output = static_cast<Output>(o.outputType);

    if (o.limitAltitude && altitude > 87 * kRadiansPerDegree) {
        std::fprintf(stderr,
                     "%s: warning - sun too close to zenith, reducing altitude to 87 degrees\n",
                     program);
        altitude = 87 * kRadiansPerDegree;
    }
    const Direction sun = SunDirection(altitude, azimuth);
    auto errorSky = [&]() {
        PrintErrorSky(month != 0 ? solarTime : 0, altitude, azimuth, sun);
        return 0;
    };

    // Eccentricity correction of the extraterrestrial irradiance.
    const double dayAngle = 2 * kPi * (dayOfYear - 1) / 365;
    const double eccentricity = 1.00011 + 0.034221 * std::cos(dayAngle) +
                                0.00128 * std::sin(dayAngle) + 0.000719 * std::cos(2 * dayAngle) +
                                0.000077 * std::sin(2 * dayAngle);

    // The sun's zenith angle (radians). Radiance's air_mass() limits it to
    // the horizon, with a warning, the first time it is called, and every
    // formula after that call sees the limited angle (-L's first clearness
    // comes before it and does not).
    double zenith = kPi / 2 - altitude;
    auto airMass = [&]() {
        if (zenith > kPi / 2) {
            Warn(o, "Warning: air mass has reached the maximal value\n");
            zenith = kPi / 2;
        }
        const double zenithDegrees = zenith / kRadiansPerDegree;
        return 1 / (std::cos(zenith) + 0.15 * std::exp(std::log(93.885 - zenithDegrees) * -1.253));
    };
    auto clearness = [&](double dn, double dh) {
        const double z3 = 1.041 * zenith * zenith * zenith;
        return ((dh + dn) / dh + z3) / (1 + z3);
    };
    auto brightness = [&](double dh) { return dh * airMass() / (kSolarConstant * eccentricity); };
    // Radiance's check_parametrization(): ε and Δ into the models' range.
    auto clamp = [](double& epsilon, double& delta) {
        if (epsilon < 1) epsilon = 1;
        if (epsilon > 12.01) epsilon = 12.009;
        if (delta < 0.01) delta = 0.01;
        if (delta > 0.6) delta = 0.6;
    };
    double epsilon = 0, delta = 0;
    // Efficacies (lm/W) of the diffuse and direct light. The diffuse model
    // has no bin for ε = 12.01 (only reachable with -P): Radiance warns and
    // prints the error sky there, which `clearnessTooHigh` asks the caller
    // to do.
    bool clearnessTooHigh = false;
    auto diffuseEfficacy = [&]() {
        const int bin = EfficacyBin(epsilon, 12.01);
        if (bin < 0) {
            Warn(o, "Warning: sky clearness (= %.3f) too high, printing error sky\n", epsilon);
            clearnessTooHigh = true;
            return 0.0;
        }
        const Efficacy& k = kDiffuseEfficacy[bin];
        return k.a + k.b * water + k.c * std::cos(zenith) + k.d * std::log(delta);
    };
    auto directEfficacy = [&]() {
        const int bin = EfficacyBin(epsilon, 12.1);
        if (bin < 0) return 0.0;
        const Efficacy& k = kDirectEfficacy[bin];
        const double value = k.a + k.b * water + k.c * std::exp(5.73 * zenith - 5) + k.d * delta;
        return value > 0 ? value : 0.0;
    };

    // Direct-normal and diffuse-horizontal irradiance (W/m²) and
    // illuminance (lux).
    double directNormal = 0, diffuse = 0;
    double directIlluminance = 0, diffuseIlluminance = 0;
    // Radiance's check_irradiances() and check_illuminances(): negative
    // values become 0, and no light with the sun up or a direct part above
    // the solar constant gives the error sky (false).
    auto checked = [&](double& direct, double& diff, const char* kind, double solarConstant) {
        if (direct < 0) {
            Warn(o, "Warning: direct %s < 0. Using 0.0\n", kind);
            direct = 0;
        }
        if (diff < 0) {
            Warn(o, "Warning: diffuse %s < 0. Using 0.0\n", kind);
            diff = 0;
        }
        if (direct + diff == 0 && altitude > 0) {
            Warn(o, "Warning: zero %s at sun altitude > 0, printing error sky\n", kind);
            return false;
        }
        if (direct > solarConstant) {
            Warn(o, "Warning: direct %s exceeds solar constant\n", kind);
            return false;
        }
        return true;
    };
    auto irradiancesChecked = [&] {
        return checked(directNormal, diffuse, "irradiance", kSolarConstant);
    };
    auto illuminancesChecked = [&] {
        return checked(directIlluminance, diffuseIlluminance, "illuminance", kSolarIlluminance);
    };
    // ε and Δ from the irradiances, Δ first (it calls air_mass()).
    auto skyFromIrradiances = [&] {
        delta = brightness(diffuse);
        epsilon = clearness(directNormal, diffuse);
        clamp(epsilon, delta);
    };
    // The illuminances, for -O 0 and -O 2 only (Radiance computes and checks
    // them for no other output); false: the error sky is printed.
    auto illuminancesFromIrradiances = [&] {
        if (output == Output::Solar) return true;
        diffuseIlluminance = diffuse * diffuseEfficacy();
        if (clearnessTooHigh) return false;
        directIlluminance = directNormal * directEfficacy();
        return illuminancesChecked();
    };

    switch (o.input) {
        case Input::Perez:
            epsilon = o.value1;
            delta = o.value2;
            clamp(epsilon, delta);
            diffuse = delta * kSolarConstant * eccentricity / airMass();
            directNormal = diffuse * (epsilon - 1) * (1 + 1.041 * zenith * zenith * zenith);
            if (!irradiancesChecked() || !illuminancesFromIrradiances()) return errorSky();
            break;
        case Input::DirectNormal:
            directNormal = o.value1;
            diffuse = o.value2;
            if (!irradiancesChecked()) return errorSky();
            skyFromIrradiances();
            if (!illuminancesFromIrradiances()) return errorSky();
            break;
        case Input::Illuminance: {
            directIlluminance = o.value1;
            diffuseIlluminance = o.value2;
            if (!illuminancesChecked()) return errorSky();
            // Radiance's illu_to_irra_index(): irradiances from the solar
            // constant's efficacy, then nine rounds of the efficacy models
            // (its loop's exit test never holds once ε and Δ are in range).
            // The first ε comes before the first air_mass() call.
            directNormal = directIlluminance * kSolarConstant / kSolarIlluminance;
            diffuse = diffuseIlluminance * kSolarConstant / kSolarIlluminance;
            epsilon = clearness(directNormal, diffuse);
            delta = brightness(diffuse);
            clamp(epsilon, delta);
            for (int iteration = 0; iteration < 9; ++iteration) {
                diffuse = diffuseIlluminance / diffuseEfficacy();
                if (clearnessTooHigh) return errorSky();
                const double kb = directEfficacy();
                directNormal = kb < 0.1 ? 0 : directIlluminance / kb;
                delta = brightness(diffuse);
                epsilon = clearness(directNormal, diffuse);
                clamp(epsilon, delta);
            }
            break;
        }
        case Input::DirectHorizontal:
        case Input::Global: {
            double directHorizontal = o.value1;
            diffuse = o.value2;
            if (o.input == Input::Global) {
                directHorizontal = diffuse = 0;
                if (altitude <= 0) {
                    if (o.value1 > 50) {
                        Warn(o, "Warning: global irradiance higher than 50 W/m^2 while the sun "
                                "altitude is lower than zero\n");
                    }
                } else {
                    // Erbs, Klein & Duffie (1982): the diffuse fraction from
                    // the clearness index kt against the extraterrestrial
                    // irradiance.
                    double global = o.value1;
                    const double s0 = kSolarConstant * eccentricity * std::sin(altitude);
                    if (global > s0) {
                        Warn(o, "Warning: global irradiance is higher than the time-dependent "
                                "solar constant s0\n");
                        global = s0 * 0.999;
                    }
                    const double kt = global / s0;
                    double kd = 0;
                    if (kt <= 0.22) {
                        kd = 1 - 0.09 * kt;
                    } else if (kt <= 0.80) {
                        kd = 0.9511 - 0.1604 * kt + 4.388 * kt * kt - 16.638 * kt * kt * kt +
                             12.336 * kt * kt * kt * kt;
                    } else if (kt < 1) {
                        kd = 0.165;
                    }
                    diffuse = kd * global;
                    directHorizontal = global - diffuse;
                    std::printf("# erbs_s0, erbs_kt, irr_dir_h, irr_diff: %.3f %.3f %.3f %.3f\n",
                                s0, kt, directHorizontal, diffuse);
                    std::printf("# WARNING: the -E option is only recommended for a rough "
                                "estimation!\n");
                }
            } else if (altitude <= 0) {
                Warn(o, "Warning: sun altitude < 0, proceed with irradiance values of zero\n");
                directHorizontal = diffuse = 0;
            }
            directNormal = altitude > 0 ? directHorizontal / std::sin(altitude) : directHorizontal;
            if (!irradiancesChecked()) return errorSky();
            skyFromIrradiances();
            if (!illuminancesFromIrradiances()) return errorSky();
            break;
        }
    }

    // Radiance's coeff_lum_perez() stops here for ε = 12.01 (-P 12.01 -O 1;
    // larger values were clamped below it).
    if (epsilon < 1 || epsilon >= 12.01) {
        std::fflush(stdout);
        std::fprintf(stderr, "Error: epsilon out of range in function coeff_lum_perez!\n");
        return 1;
    }
    const PerezCoefficients perez = Coefficients(epsilon, delta, zenith);
    const double integral = NormalisationIntegral(perez, zenith);
    const double sunSolidAngle = 2 * kPi * (1 - std::cos(kSunHalfAngleDegrees * kRadiansPerDegree));
    double skyNormalisation = 0, solar = 0;
    switch (output) {
        case Output::Visible:
            skyNormalisation = diffuseIlluminance / (kWhiteEfficacy * integral);
            solar = directIlluminance / (kWhiteEfficacy * sunSolidAngle);
            break;
        case Output::Solar:
            skyNormalisation = diffuse / integral;
            solar = directNormal / sunSolidAngle;
            break;
        case Output::Luminance:
            skyNormalisation = diffuseIlluminance / integral;
            solar = directIlluminance / sunSolidAngle;
            break;
    }

    // Ground: the zenith radiance times the CIE sky's diffuse normalisation
    // closest to this sky, plus the sun's contribution, times the reflectance.
    const double zenithRadiance = perez.RelativeLuminance(1, zenith) * skyNormalisation;
    double normalisation;
    if (epsilon == 1) {
        normalisation = kOvercastNormalisation;
    } else if (epsilon >= 6) {
        normalisation = ClearSkyNormalisation(altitude, ClearSkyF2(altitude, sun.z));
    } else {
        normalisation = IntermediateSkyNormalisation(altitude, IntermediateSkyF2(altitude));
    }
    double ground = zenithRadiance * normalisation;
    if (o.sun && epsilon > 1) ground += kGroundSunSolidAngle / kPi * solar * std::sin(altitude);
    ground *= o.groundReflectance;
    // A positive Perez b brightens the sky toward the horizon without bound
    // (low suns with much direct light): Radiance prints the error sky.
    if (perez.b > 0) {
        Warn(o, "Warning: positive Perez parameter B (= %f), printing error sky\n", perez.b);
        return errorSky();
    }

    std::printf("# Local solar time: %.2f\n", month != 0 ? solarTime : 0.0);
    // Degrees as Radiance prints them (x·180/π, which can round the other
    // way from x/(π/180) at the printed digit: 43.45° input prints 43.4).
    std::printf("# Solar altitude and azimuth: %.1f %.1f\n", altitude * 180 / kPi,
                azimuth * 180 / kPi);
    std::printf("# epsilon, delta, atmospheric precipitable water content : %.4f %.4f %.4f \n",
                epsilon, delta, water);
    if (o.sun) {
        if (epsilon == 1) {
            std::printf("\nvoid light solar\n0\n0\n3 0.0 0.0 0.0\n");
        } else {
            std::printf("\nvoid light solar\n0\n0\n3 %.3e %.3e %.3e\n", solar, solar, solar);
        }
        std::printf("\nsolar source sun\n0\n0\n4 %f %f %f %f\n", sun.x, sun.y, sun.z, 0.533);
    }
    std::printf("\nvoid brightfunc skyfunc\n2 skybright perezlum.cal\n0\n");
    std::printf("10 %.3e %.3e %f %f %f %f %f %f %f %f \n", skyNormalisation, ground, perez.a,
                perez.b, perez.c, perez.d, perez.e, sun.x, sun.y, sun.z);
    return std::fflush(stdout) == 0 ? 0 : 1;
}
