// SPDX-License-Identifier: MIT
//
// vwrays: the primary rays of a Radiance view, in scanline order (top row
// first, left to right), as Radiance's src/util/vwrays.c writes them, ready for
// `rtrace -x X -y Y`. Usage:
//   vwrays [-i -u -f{a|f|d} -c rept -pa aspect -pj jitter | -d] -x X -y Y view-options
// -d prints the resolution after pixel-aspect adjustment ("-x X -y Y -ld±").
// -pj draws from a fixed-seed generator, so jittered runs repeat exactly.
// Picture (and depth buffer) arguments of Radiance's vwrays are not supported.
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

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
                 "Usage: %s [ -i -u -f{a|f|d} -c rept -pa aspect -pj jitter | -d ] "
                 "-x X -y Y view-options\n",
                 progname);
    std::exit(1);
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
    double pixelAspect = 1.0, jitter = 0.0;
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
            const std::optional<rt::CameraRay> ray = rt::ViewRay(pv, lx, ly);
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
