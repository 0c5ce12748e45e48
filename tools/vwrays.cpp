// SPDX-License-Identifier: MIT
//
// vwrays: the primary rays of a Radiance view, in scanline order (top row
// first, left to right), as Radiance's src/util/vwrays.c writes them, ready for
// `rtrace -x X -y Y`. Usage:
//   vwrays [-i -u -f{a|f|d} -c rept -pa aspect -pj jitter -pd aperture | -d]
//          -x X -y Y view-options
// -d prints the resolution after pixel-aspect adjustment ("-x X -y Y -ld±").
// -pj and -pd draw from a fixed-seed generator, so jittered runs repeat exactly.
// Picture (and depth buffer) arguments of Radiance's vwrays are not supported.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "core/conventions.h"
#include "core/error.h"
#include "view/view.h"

namespace {

enum class Format { Ascii, Float, Double };

void PutRay(Format format, const rt::Vec3& o, const rt::Vec3& d) {
    switch (format) {
        case Format::Ascii:
            std::printf("%.5e %.5e %.5e %.5e %.5e %.5e\n", o.x, o.y, o.z, d.x, d.y, d.z);
            break;
        case Format::Float: {
            const float v[6] = {static_cast<float>(o.x), static_cast<float>(o.y),
                                static_cast<float>(o.z), static_cast<float>(d.x),
                                static_cast<float>(d.y), static_cast<float>(d.z)};
            std::fwrite(v, sizeof(float), 6, stdout);
            break;
        }
        case Format::Double: {
            const double v[6] = {o.x, o.y, o.z, d.x, d.y, d.z};
            std::fwrite(v, sizeof(double), 6, stdout);
            break;
        }
    }
}

[[noreturn]] void Usage(const char* progname) {
    std::fprintf(stderr,
                 "Usage: %s [ -i -u -f{a|f|d} -c rept -pa aspect -pj jitter -pd aperture | -d ] "
                 "-x X -y Y view-options\n",
                 progname);
    std::exit(1);
}

/// Depth of field, as Radiance 5.4a's jitteraperture(): the ray from
/// `origin` along unit `dir` is moved to a uniformly random point of an
/// aperture disc of diameter `aperture` (world units) in the image plane's
/// directions, and aimed at the point the unmoved ray reaches at the focal
/// distance |vd| (perspective: on the plane that far along vd). For the
/// fisheye and cylindrical views the point also moves by up to ±π/8 of the
/// aperture along vd, and the disc is in the plane vectors' own units
/// where Radiance leaves them unnormalised. False when the new direction is
/// zero (the point was the focus).
bool JitterAperture(const rt::PreparedView& pv, double aperture, double u1, double u2, double u3,
                    rt::Vec3& origin, rt::Vec3& dir) {
    using rt::ViewType;
    // A uniform point of the disc (not Radiance's concentric map, which
    // draws other random numbers anyway: the same distribution).
    const double r = 0.5 * aperture * std::sqrt(u1), phi = 2.0 * rt::kPi * u2;
    double dh = r * std::cos(phi), dv = r * std::sin(phi);
    const ViewType type = pv.view.type;
    rt::Vec3 focus;
    if (type == ViewType::Perspective || type == ViewType::Parallel) {
        const double along = type == ViewType::Perspective ? 1.0 / rt::Dot(dir, pv.view.vd) : 1.0;
        focus = pv.view.vp + dir * (along * pv.vdist);
        origin += pv.hvec * (dh / std::sqrt(pv.hn2)) + pv.vvec * (dv / std::sqrt(pv.vn2));
    } else {
        const double forward = rt::kPi / 4.0 * aperture * (0.5 - u3);
        if (type != ViewType::Angular && type != ViewType::Planisphere) {
            if (type != ViewType::Cylindrical) dh /= std::sqrt(pv.hn2);
            dv /= std::sqrt(pv.vn2);
        }
        focus = pv.view.vp + dir * pv.vdist;
        origin += pv.hvec * dh + pv.vvec * dv + pv.view.vd * forward;
    }
    const rt::Vec3 toFocus = focus - origin;
    const double length = rt::Length(toFocus);
    if (length == 0.0) return false;
    dir = toFocus / length;
    return true;
}

int ParseResolution(const std::vector<std::string>& args, std::size_t& i, const char* progname,
                    const char* what) {
    if (i + 1 >= args.size())
        Usage(progname);
    const int value = std::atoi(args[++i].c_str());
    if (value <= 0) {
        std::fprintf(stderr, "%s: bad %s resolution\n", progname, what);
        std::exit(1);
    }
    return value;
}

}  // namespace

int main(int argc, char** argv) {
    const char* progname = "vwrays";
    const std::vector<std::string> args(argv + 1, argv + argc);
    rt::View view;
    Format format = Format::Ascii;
    int xRes = 512, yRes = 512;
    double pixelAspect = 1.0, jitter = 0.0, aperture = 0.0;
    int repeat = 1;
    bool dimensionsOnly = false, fromStdin = false, unbuffered = false;
    try {
        if (args.empty())
            Usage(progname);
        for (std::size_t i = 0; i < args.size(); ++i) {
            const std::string& a = args[i];
            if (a.size() < 2 || a[0] != '-')
                Usage(progname);
            if (a[1] == 'v') {
                const auto used =
                    rt::ParseViewOption(view, std::span<const std::string>(args).subspan(i));
                if (!used)
                    Usage(progname);
                i += static_cast<std::size_t>(*used);
            } else if (a == "-fa") {
                format = Format::Ascii;
            } else if (a == "-ff") {
                format = Format::Float;
            } else if (a == "-fd") {
                format = Format::Double;
            } else if (a == "-d") {
                dimensionsOnly = true;
            } else if (a == "-x") {
                xRes = ParseResolution(args, i, progname, "x");
            } else if (a == "-y") {
                yRes = ParseResolution(args, i, progname, "y");
            } else if (a == "-c" && i + 1 < args.size()) {
                repeat = std::atoi(args[++i].c_str());
            } else if (a == "-pa" && i + 1 < args.size()) {
                pixelAspect = std::atof(args[++i].c_str());
            } else if (a == "-pj" && i + 1 < args.size()) {
                jitter = std::atof(args[++i].c_str());
            } else if (a == "-pd" && i + 1 < args.size()) {
                aperture = std::atof(args[++i].c_str());
            } else if (a == "-i") {
                fromStdin = true;
            } else if (a == "-u") {
                unbuffered = true;
            } else {
                Usage(progname);
            }
        }
        const rt::PreparedView pv = rt::SetupView(view);
        rt::NormalizeAspect(rt::ViewAspect(pv), pixelAspect, xRes, yRes);
        if (dimensionsOnly) {
            std::printf("-x %d -y %d -ld%c\n", xRes, yRes, view.va > 1e-6 ? '+' : '-');
            return 0;
        }
        std::mt19937_64 rng(0);
        std::uniform_real_distribution<double> uniform(0.0, 1.0);
        auto emit = [&](double lx, double ly) {
            if (jitter > 1e-6) {
                lx += jitter * (0.5 - uniform(rng)) / xRes;
                ly += jitter * (0.5 - uniform(rng)) / yRes;
            }
            std::optional<rt::CameraRay> ray = rt::ViewRay(pv, lx, ly);
            if (ray && aperture > 1e-6 &&
                !JitterAperture(pv, aperture, uniform(rng), uniform(rng), uniform(rng), ray->origin,
                                ray->direction)) {
                ray.reset();
            }
            if (!ray) {
                PutRay(format, {}, {});  // rtrace reads a zero direction as "no ray"
                return;
            }
            const double scale = ray->maxDistance > 1e-6 ? ray->maxDistance : 1.0;
            PutRay(format, ray->origin, ray->direction * scale);
        };
        if (fromStdin) {
            double px = 0, py = 0;
            while (std::scanf("%lf %lf", &px, &py) == 2) {
                emit((px + 0.5) / xRes, (py + 0.5) / yRes);
                if (unbuffered)
                    std::fflush(stdout);
            }
            if (!std::feof(stdin)) {
                std::fprintf(stderr, "%s: expected px py on input\n", progname);
                return 1;
            }
            return 0;
        }
        for (int scan = 0; scan < yRes; ++scan) {
            const int yUp = yRes - 1 - scan;  // Radiance's y points up: top scan first
            for (int x = 0; x < xRes; ++x) {
                for (int c = 0; c < repeat; ++c)
                    emit((x + 0.5) / xRes, (yUp + 0.5) / yRes);
            }
        }
        if (std::fflush(stdout) != 0) {
            std::fprintf(stderr, "%s: write error\n", progname);
            return 2;
        }
    } catch (const rt::Error& e) {
        std::fprintf(stderr, "%s: %s\n", progname, e.what());
        return e.ExitCode();
    }
    return 0;
}
