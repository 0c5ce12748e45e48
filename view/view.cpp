// SPDX-License-Identifier: MIT
#include "view/view.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <numbers>

#include "core/error.h"

namespace rt {
namespace {

// Radiance's FTINY for double-precision builds.
constexpr double kTiny = 1e-6;
constexpr double kPi = std::numbers::pi;

// Radiance's normalize(): lengths within FTINY of 1 use a first-order
// correction instead of a square root. Kept so rays agree with Radiance's to
// the last bit. Returns the original length, 0 (and v unchanged) for zero.
double NormalizeLikeRadiance(Vec3& v) {
    double d = Dot(v, v);
    if (d == 0.0)
        return 0.0;
    double len;
    if (d <= 1.0 + kTiny && d >= 1.0 - kTiny) {
        len = 0.5 + 0.5 * d;
        d = 2.0 - len;
    } else {
        len = std::sqrt(d);
        d = 1.0 / len;
    }
    v *= d;
    return len;
}

// Radiance's isflt(): the whole word is one floating-point number.
bool ParseNumber(const std::string& word, double& value) {
    if (word.empty())
        return false;
    const char* begin = word.c_str();
    char* end = nullptr;
    value = std::strtod(begin, &end);
    if (end == begin)
        return false;
    while (*end == ' ' || *end == '\t' || *end == '\r' || *end == '\n')
        ++end;
    return *end == '\0' && std::isfinite(value);
}

bool IsKnownType(char c) {
    switch (c) {
        case 'v':
        case 'l':
        case 'a':
        case 'h':
        case 's':
        case 'c':
            return true;
        default:
            return false;
    }
}

// Radiance's getviewopt() without -vf. Returns the number of value words used,
// -1 when args[0] is not a view option, -2 (with `error` set) when it is one but
// its values are bad.
int GetViewOpt(View& view, std::span<const std::string> args, std::string& error) {
    if (args.empty())
        return -1;
    const std::string& opt = args[0];
    if (opt.size() < 3 || opt[0] != '-' || opt[1] != 'v')
        return -1;
    auto numbers = [&](std::size_t count, double* out) -> bool {
        if (opt.size() != 3)
            return false;
        if (args.size() < count + 1) {
            error =
                opt + ": expects " + std::to_string(count) + (count == 1 ? " number" : " numbers");
            return false;
        }
        for (std::size_t i = 0; i < count; ++i) {
            if (!ParseNumber(args[i + 1], out[i])) {
                error = opt + ": '" + args[i + 1] + "' is not a number";
                return false;
            }
        }
        return true;
    };
    std::array<double, 3> v{};
    switch (opt[2]) {
        case 't':
            if (opt.size() != 4) {
                error = "'" + opt + "': view type must be one letter of v l a h s c";
                return -2;
            }
            if (!IsKnownType(opt[3])) {
                error = opt + ": unknown view type '" + std::string(1, opt[3]) + "'";
                return -2;
            }
            view.type = static_cast<ViewType>(opt[3]);
            return 0;
        case 'p':
        case 'd':
        case 'u': {
            if (opt.size() != 3)
                return -1;
            if (!numbers(3, v.data()))
                return -2;
            Vec3& target = opt[2] == 'p' ? view.vp : (opt[2] == 'd' ? view.vd : view.vu);
            target = {v[0], v[1], v[2]};
            return 3;
        }
        case 'h':
        case 'v':
        case 'o':
        case 'a':
        case 's':
        case 'l': {
            if (opt.size() != 3)
                return -1;
            if (!numbers(1, v.data()))
                return -2;
            double* field = nullptr;
            switch (opt[2]) {
                case 'h':
                    field = &view.vh;
                    break;
                case 'v':
                    field = &view.vv;
                    break;
                case 'o':
                    field = &view.vo;
                    break;
                case 'a':
                    field = &view.va;
                    break;
                case 's':
                    field = &view.vs;
                    break;
                default:
                    field = &view.vl;
                    break;
            }
            *field = v[0];
            return 1;
        }
        default:
            return -1;
    }
}

std::vector<std::string> SplitWords(std::string_view line) {
    std::vector<std::string> words;
    std::size_t i = 0;
    auto isSpace = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
    while (i < line.size()) {
        while (i < line.size() && isSpace(line[i]))
            ++i;
        const std::size_t start = i;
        while (i < line.size() && !isSpace(line[i]))
            ++i;
        if (i > start)
            words.emplace_back(line.substr(start, i - start));
    }
    return words;
}

}  // namespace

std::optional<int> ParseViewOption(View& view, std::span<const std::string> args) {
    if (args.empty())
        return std::nullopt;
    if (args[0] == "-vf") {
        if (args.size() < 2)
            ThrowUserError("-vf: expects a view file name");
        ReadViewFile(args[1], view);
        return 1;
    }
    std::string error;
    const int n = GetViewOpt(view, args, error);
    if (n == -2)
        ThrowUserError(error);
    if (n < 0)
        return std::nullopt;
    return n;
}

View ParseViewArgs(std::span<const std::string> args, const View& start) {
    View view = start;
    std::size_t i = 0;
    while (i < args.size()) {
        const std::optional<int> used = ParseViewOption(view, args.subspan(i));
        if (!used)
            ThrowUserError("'" + args[i] + "' is not a view option");
        i += static_cast<std::size_t>(*used) + 1;
    }
    return view;
}

View ParseViewArgs(const std::vector<std::string>& args, const View& start) {
    return ParseViewArgs(std::span<const std::string>(args), start);
}

int ScanViewString(View& view, std::string_view line) {
    std::vector<std::string> words = SplitWords(line);
    std::size_t i = 0;
    if (!words.empty() && words[0][0] != '-')
        i = 1;  // "rview", "VIEW=", a path
    int applied = 0;
    std::string error;
    while (i < words.size()) {
        const int n = GetViewOpt(view, std::span<const std::string>(words).subspan(i), error);
        if (n >= 0) {
            ++applied;
            i += static_cast<std::size_t>(n) + 1;
        } else {
            ++i;  // sscanview skips what it does not understand
        }
    }
    return applied;
}

bool IsViewLine(std::string_view line) {
    std::size_t start = 0;
    while (start < line.size() && (line[start] == ' ' || line[start] == '\t'))
        ++start;
    std::size_t end = start;
    while (end < line.size() && line[end] != ' ' && line[end] != '\t' && line[end] != '\n')
        ++end;
    std::string_view word = line.substr(start, end - start);
    if (const std::size_t slash = word.rfind('/'); slash != std::string_view::npos) {
        word = word.substr(slash + 1);
    }
    static constexpr std::array<std::string_view, 7> kNames = {"VIEW=",  "rpict",   "rview", "rvu",
                                                               "rpiece", "pinterp", "vwrays"};
    for (std::string_view name : kNames) {
        if (word.substr(0, name.size()) == name)
            return true;
    }
    return false;
}

int ApplyViewHeader(std::istream& in, View& view) {
    // Radiance's getheader(): the header ends at the first empty line, which
    // also keeps us out of a picture's binary data.
    int found = 0;
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        if (line.empty())
            break;
        if (IsViewLine(line) && ScanViewString(view, line) > 0)
            ++found;
    }
    return found;
}

void ReadViewFile(const std::string& path, View& view) {
    std::ifstream file;
    std::istream* in = &std::cin;
    const std::string name = path == "-" ? "<stdin>" : path;
    if (path != "-") {
        file.open(path, std::ios::binary);
        if (!file)
            throw Error(Error::Kind::System, FileLoc{path}, "cannot open view file");
        in = &file;
    }
    if (ApplyViewHeader(*in, view) == 0)
        ThrowUserError(FileLoc{name}, "no view in file");
}

PreparedView SetupView(const View& view) {
    PreparedView pv;
    pv.view = view;
    View& v = pv.view;
    // Radiance's setview() messages as they are; rvimage says "bad view: ".
    auto fail = [](const std::string& message) { ThrowUserError(message); };
    if (v.va < -kTiny || (v.va > kTiny && v.va <= v.vo))
        fail("illegal fore/aft clipping plane");
    pv.vdist = NormalizeLikeRadiance(v.vd);
    if (pv.vdist == 0.0)
        fail("zero view direction");
    if (NormalizeLikeRadiance(v.vu) == 0.0)
        fail("zero view up vector");
    pv.hvec = Cross(v.vd, v.vu);
    if (NormalizeLikeRadiance(pv.hvec) == 0.0)
        fail("view up parallel to view direction");
    pv.vvec = Cross(pv.hvec, v.vd);

    const std::string illHoriz = "illegal horizontal view size";
    const std::string illVert = "illegal vertical view size";
    if (v.vh <= kTiny)
        fail(illHoriz);
    if (v.vv <= kTiny)
        fail(illVert);
    const double halfH = v.vh * (kPi / 180.0 / 2.0);
    const double halfV = v.vv * (kPi / 180.0 / 2.0);
    double hn = 0, vn = 0;
    switch (v.type) {
        case ViewType::Parallel:
            hn = v.vh;
            vn = v.vv;
            break;
        case ViewType::Perspective:
            if (v.vh >= 180.0 - kTiny)
                fail(illHoriz);
            if (v.vv >= 180.0 - kTiny)
                fail(illVert);
            hn = 2.0 * std::tan(halfH);
            vn = 2.0 * std::tan(halfV);
            break;
        case ViewType::Cylindrical:
            if (v.vh > 360.0 + kTiny)
                fail(illHoriz);
            if (v.vv >= 180.0 - kTiny)
                fail(illVert);
            hn = v.vh * (kPi / 180.0);
            vn = 2.0 * std::tan(halfV);
            break;
        case ViewType::Angular:
            if (v.vh > 360.0 + kTiny)
                fail(illHoriz);
            if (v.vv > 360.0 + kTiny)
                fail(illVert);
            hn = v.vh * (kPi / 180.0);
            vn = v.vv * (kPi / 180.0);
            break;
        case ViewType::Hemispherical:
            if (v.vh > 180.0 + kTiny)
                fail(illHoriz);
            if (v.vv > 180.0 + kTiny)
                fail(illVert);
            hn = 2.0 * std::sin(halfH);
            vn = 2.0 * std::sin(halfV);
            break;
        case ViewType::Planisphere:
            if (v.vh >= 360.0 - kTiny)
                fail(illHoriz);
            if (v.vv >= 360.0 - kTiny)
                fail(illVert);
            hn = 2.0 * std::sin(halfH) / (1.0 + std::cos(halfH));
            vn = 2.0 * std::sin(halfV) / (1.0 + std::cos(halfV));
            break;
        default:
            fail("unknown view type");
    }
    // Angular and planisphere views keep unit image vectors and scale in
    // ViewRay; the cylinder scales only its perspective (vertical) axis.
    if (v.type != ViewType::Angular && v.type != ViewType::Planisphere) {
        if (v.type != ViewType::Cylindrical)
            pv.hvec *= hn;
        pv.vvec *= vn;
    }
    pv.hn2 = hn * hn;
    pv.vn2 = vn * vn;
    return pv;
}

std::optional<CameraRay> ViewRay(const PreparedView& pv, double x, double y) {
    const View& v = pv.view;
    x += v.vs - 0.5;
    y += v.vl - 0.5;
    CameraRay ray{};
    const double aftSpan = v.va > kTiny ? v.va - v.vo : 0.0;
    switch (v.type) {
        case ViewType::Parallel:
            ray.origin = v.vp + v.vo * v.vd + x * pv.hvec + y * pv.vvec;
            ray.direction = v.vd;
            ray.maxDistance = aftSpan;
            return ray;
        case ViewType::Perspective: {
            Vec3 dir = v.vd + x * pv.hvec + y * pv.vvec;
            ray.origin = v.vp + v.vo * dir;
            const double len = NormalizeLikeRadiance(dir);
            ray.direction = dir;
            ray.maxDistance = aftSpan * len;
            return ray;
        }
        case ViewType::Hemispherical: {
            double z = 1.0 - x * x * pv.hn2 - y * y * pv.vn2;
            if (z < 0.0)
                return std::nullopt;
            z = std::sqrt(z);
            ray.direction = z * v.vd + x * pv.hvec + y * pv.vvec;
            ray.origin = v.vp + v.vo * ray.direction;
            ray.maxDistance = aftSpan;
            return ray;
        }
        case ViewType::Cylindrical: {
            const double angle = x * v.vh * (kPi / 180.0);
            Vec3 dir = std::cos(angle) * v.vd + std::sin(angle) * pv.hvec + y * pv.vvec;
            ray.origin = v.vp + v.vo * dir;
            const double len = NormalizeLikeRadiance(dir);
            ray.direction = dir;
            ray.maxDistance = aftSpan * len;
            return ray;
        }
        case ViewType::Angular: {
            x *= (1.0 / 180.0) * v.vh;
            y *= (1.0 / 180.0) * v.vv;
            double d = x * x + y * y;
            if (d > 1.0)
                return std::nullopt;
            d = std::sqrt(d);
            const double z = std::cos(kPi * d);
            d = d <= kTiny ? kPi : std::sqrt(1.0 - z * z) / d;
            x *= d;
            y *= d;
            ray.direction = z * v.vd + x * pv.hvec + y * pv.vvec;
            ray.origin = v.vp + v.vo * ray.direction;
            ray.maxDistance = aftSpan;
            return ray;
        }
        case ViewType::Planisphere: {
            x *= std::sqrt(pv.hn2);
            y *= std::sqrt(pv.vn2);
            double d = x * x + y * y;
            const double z = (1.0 - d) / (1.0 + d);
            d = d <= kTiny * kTiny ? kPi : std::sqrt((1.0 - z * z) / d);
            x *= d;
            y *= d;
            ray.direction = z * v.vd + x * pv.hvec + y * pv.vvec;
            ray.origin = v.vp + v.vo * ray.direction;
            ray.maxDistance = aftSpan;
            return ray;
        }
    }
    return std::nullopt;
}

double ViewAspect(const PreparedView& view) { return std::sqrt(view.vn2 / view.hn2); }

void NormalizeAspect(double viewAspect, double& pixelAspect, int& xRes, int& yRes) {
    if (pixelAspect <= kTiny) {
        pixelAspect = viewAspect * xRes / yRes;
    } else if (viewAspect * xRes > pixelAspect * yRes) {
        xRes = static_cast<int>(yRes / viewAspect * pixelAspect + 0.5);
    } else {
        yRes = static_cast<int>(xRes * viewAspect / pixelAspect + 0.5);
    }
}

std::string FormatView(const View& v) {
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  " -vt%c -vp %.6g %.6g %.6g -vd %.6g %.6g %.6g -vu %.6g %.6g %.6g"
                  " -vh %.6g -vv %.6g -vo %.6g -va %.6g -vs %.6g -vl %.6g",
                  static_cast<char>(v.type), v.vp.x, v.vp.y, v.vp.z, v.vd.x, v.vd.y, v.vd.z, v.vu.x,
                  v.vu.y, v.vu.z, v.vh, v.vv, v.vo, v.va, v.vs, v.vl);
    return buf;
}

}  // namespace rt
