// SPDX-License-Identifier: MIT
#include "scene/transform.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/conventions.h"
#include "core/quote.h"
#include "scene/object_types.h"
#include "scene/reader.h"

namespace rt {
namespace {

/// xf.c's badarg(): the `count` words after `i` exist and are numbers of the given
/// kinds ('f' real, 'i' integer).
bool ValuesOk(const std::vector<std::string>& args, std::size_t i, const char* kinds) {
    for (std::size_t k = 0; kinds[k] != '\0'; ++k) {
        if (i + 1 + k >= args.size()) return false;
        const std::string& word = args[i + 1 + k];
        if (kinds[k] == 'i' ? !IsIntegerWord(word) : !ParseRealWord(word)) return false;
    }
    return true;
}

double Real(const std::string& word) { return *ParseRealWord(word); }

[[noreturn]] void BadObject(const SceneObject& object) {
    ThrowUserError(object.loc, "bad " + object.type + " \"" + PrintableWord(object.name) + "\"");
}

const char* InverseSurfaceType(const std::string& type) {
    if (type == "cone") return "cup";
    if (type == "cup") return "cone";
    if (type == "sphere") return "bubble";
    if (type == "bubble") return "sphere";
    if (type == "cylinder") return "tube";
    if (type == "tube") return "cylinder";
    return nullptr;  // polygon, ring, source, instance, mesh keep their type
}

void PutPoint(std::vector<double>& r, std::size_t at, const Vec3& p) {
    r[at] = p.x;
    r[at + 1] = p.y;
    r[at + 2] = p.z;
}
Vec3 GetVec(const std::vector<double>& r, std::size_t at) { return {r[at], r[at + 1], r[at + 2]}; }

}  // namespace

ParsedTransform ParseTransformArgs(const std::vector<std::string>& args, std::size_t start) {
    Transform total;
    Transform group;  // transforms since the last -i, applied `repeat` times
    long long repeat = 1;
    const auto flush = [&] {
        // Step by step as xf.c (same rounding) for sane counts; by squaring beyond,
        // so "-i 1000000000" stays cheap.
        for (; repeat > 0 && repeat <= 1024; --repeat) total = Compose(total, group);
        Transform power = group;
        for (; repeat > 0; repeat >>= 1) {
            if (repeat & 1) total = Compose(total, power);
            power = Compose(power, power);
        }
        repeat = 0;
    };
    std::size_t i = start;
    for (; i < args.size() && !args[i].empty() && args[i][0] == '-'; ++i) {
        const std::string& option = args[i];
        Transform step;
        if (option == "-t" && ValuesOk(args, i, "fff")) {
            for (int k = 0; k < 3; ++k) step.m[3][k] = Real(args[i + 1 + static_cast<std::size_t>(k)]);
            i += 3;
        } else if ((option == "-rx" || option == "-ry" || option == "-rz") && ValuesOk(args, i, "f")) {
            const double angle = kPi / 180.0 * Real(args[++i]);
            const double c = std::cos(angle), s = std::sin(angle);
            // Counter-clockwise looking down the axis towards the origin, row vectors.
            const int a = option[2] == 'x' ? 1 : (option[2] == 'y' ? 2 : 0);
            const int b = option[2] == 'x' ? 2 : (option[2] == 'y' ? 0 : 1);
            step.m[a][a] = step.m[b][b] = c;
            step.m[a][b] = s;
            step.m[b][a] = -s;
        } else if (option == "-s" && ValuesOk(args, i, "f") && Real(args[i + 1]) != 0) {
            const double s = Real(args[++i]);
            step.m[0][0] = step.m[1][1] = step.m[2][2] = s;
            step.scale = s;
        } else if (option == "-mx" || option == "-my" || option == "-mz") {
            const int axis = option[2] - 'x';
            step.m[axis][axis] = -1;
            step.scale = -1;
        } else if (option == "-i" && ValuesOk(args, i, "i")) {
            flush();
            repeat = std::atoll(args[++i].c_str());
            group = Transform();
            continue;
        } else {
            break;
        }
        group = Compose(group, step);
    }
    flush();
    return {total, i};
}

SceneObject TransformSceneObject(const SceneObject& object, const XformSettings& settings) {
    SceneObject out = object;
    const Transform& xf = settings.transform;
    const double scale = std::fabs(xf.scale);
    const bool reverse = (xf.scale < 0) != settings.invert;
    const std::string& type = object.type;
    auto& r = out.rargs;
    const auto expect = [&](std::size_t nsargs, std::size_t nrargs) {
        if (object.sargs.size() != nsargs || object.rargs.size() != nrargs) BadObject(object);
    };

    if (IsSurfaceObjectType(type)) {
        if (!settings.newModifier.empty()) out.modifier = settings.newModifier;
        if (settings.invert) {
            if (const char* inverse = InverseSurfaceType(type)) out.type = inverse;
        }
        if (!settings.idPrefix.empty()) out.name = settings.idPrefix + "." + object.name;
    }

    if (type == "source") {
        expect(0, 4);
        PutPoint(r, 0, xf.Vector(GetVec(object.rargs, 0)));
    } else if (type == "sphere" || type == "bubble") {
        expect(0, 4);
        PutPoint(r, 0, xf.Point(GetVec(object.rargs, 0)));
        r[3] *= scale;
    } else if (type == "polygon") {
        if (!object.sargs.empty() || object.rargs.size() % 3 != 0) BadObject(object);
        const std::size_t n = object.rargs.size();
        for (std::size_t i = 0; i < n; i += 3) {
            PutPoint(r, i, xf.Point(GetVec(object.rargs, reverse ? n - i - 3 : i)));
        }
    } else if (type == "cone" || type == "cup" || type == "cylinder" || type == "tube") {
        const bool cylinder = type == "cylinder" || type == "tube";
        expect(0, cylinder ? 7 : 8);
        PutPoint(r, 0, xf.Point(GetVec(object.rargs, 0)));
        PutPoint(r, 3, xf.Point(GetVec(object.rargs, 3)));
        for (std::size_t i = 6; i < r.size(); ++i) r[i] *= scale;
    } else if (type == "ring") {
        expect(0, 8);
        PutPoint(r, 0, xf.Point(GetVec(object.rargs, 0)));
        const Vec3 normal = xf.Vector(GetVec(object.rargs, 3));
        PutPoint(r, 3, settings.invert ? -normal : normal);
        r[6] *= scale;
        r[7] *= scale;
    } else if (type == "glow") {
        expect(0, 4);
        r[3] *= scale;
    } else if (type == "spotlight") {
        expect(0, 7);
        PutPoint(r, 4, xf.Vector(GetVec(object.rargs, 4)));
    } else if (type == "dielectric" || type == "interface") {
        const bool dielectric = type == "dielectric";
        expect(0, dielectric ? 5 : 8);
        // Transmission per unit length changes with the length unit.
        for (const std::size_t i : {0, 1, 2, 4, 5, 6}) {
            if (dielectric && i > 2) break;
            r[i] = std::pow(r[i], 1.0 / scale);
        }
    } else if (type == "mist") {
        if (object.rargs.size() > 7) BadObject(object);
        if (!settings.idPrefix.empty()) {
            // Source names (and each part of a relay>source path) get the prefix too.
            for (std::string& name : out.sargs) {
                std::string renamed;
                std::size_t from = 0;
                while (from < name.size()) {
                    const std::size_t stop = name.find('>', from);
                    const std::size_t end = stop == std::string::npos ? name.size() : stop + 1;
                    renamed += settings.idPrefix + "." + name.substr(from, end - from);
                    from = end;
                }
                name = renamed;
            }
        }
        if (r.size() > 2) {
            for (std::size_t i = 0; i < 3; ++i) r[i] /= scale;
        }
    } else if (IsTextType(type)) {
        if (object.rargs.size() < 9) BadObject(object);
        PutPoint(r, 0, xf.Point(GetVec(object.rargs, 0)));
        PutPoint(r, 3, xf.Vector(GetVec(object.rargs, 3)));
        PutPoint(r, 6, xf.Vector(GetVec(object.rargs, 6)));
    } else if (TakesTransformArgs(type)) {
        // Reset any iteration count left by the object's own transform before ours.
        const auto& words = settings.transformArgs;
        if (!words.empty() && words[0] != "-i") {
            out.sargs.push_back("-i");
            out.sargs.push_back("1");
        }
        out.sargs.insert(out.sargs.end(), words.begin(), words.end());
    }
    return out;
}

namespace {

/// `n` reals from `r` at `first`, each as `format` (" %18.12g" and the like).
void AppendReals(std::string& text, const std::vector<double>& r, std::size_t first,
                 std::size_t n, const char* format) {
    char number[64];
    for (std::size_t i = first; i < first + n && i < r.size(); ++i) {
        std::snprintf(number, sizeof number, format, r[i]);
        text += number;
    }
}

/// The real arguments as Radiance's xform writes each type (its o_face,
/// o_cone, o_cylinder, o_ring, m_spot, m_dielectric, m_interface, m_mist,
/// text and o_default), after the count.
void AppendRealArgs(std::string& text, const std::string& type, const std::vector<double>& r) {
    const std::size_t n = r.size();
    text += std::to_string(n);
    const char* wide = " %18.12g";
    // Points and vectors three to a line: polygons' vertices; cones', cups'
    // and rings' two points (or point and normal) and two radii; cylinders'
    // and tubes' two points and one radius.
    const bool eightReals = type == "cone" || type == "cup" || type == "ring";
    const bool sevenReals = type == "cylinder" || type == "tube";
    if ((type == "polygon" && n > 0) || (eightReals && n == 8) || (sevenReals && n == 7)) {
        text += '\n';
        for (std::size_t i = 0; i < n; i += 3) {
            AppendReals(text, r, i, 3, wide);
            text += '\n';
        }
    } else if (type == "spotlight" && n == 7) {
        AppendReals(text, r, 0, 4, wide);
        text += "\n\t";
        AppendReals(text, r, 4, 1, "%18.12g");
        AppendReals(text, r, 5, 2, wide);
        text += '\n';
    } else if (type == "dielectric" && n == 5) {
        AppendReals(text, r, 0, 5, " %12.6g");
        text += '\n';
    } else if (type == "interface" && n == 8) {
        for (std::size_t i = 0; i < 8; i += 4) {
            text += '\n';
            AppendReals(text, r, i, 1, "%12.6g");
            AppendReals(text, r, i + 1, 3, " %12.6g");
        }
        text += '\n';
    } else if (type == "mist") {
        AppendReals(text, r, 0, n, " %12.6g");
        text += '\n';
    } else if (IsTextType(type) && n >= 9) {
        // Anchor, right and down vectors one to a line, then the rest three
        // to a line.
        for (std::size_t i = 0; i < n; ++i) {
            if (i % 3 == 0) text += '\n';
            AppendReals(text, r, i, 1, wide);
        }
        text += '\n';
    } else {
        AppendReals(text, r, 0, n, wide);
        text += '\n';
    }
}

}  // namespace

std::string FormatSceneObject(const SceneObject& object) {
    // Appends only: GCC 12 reports a false -Wrestrict for "literal" + temporary.
    std::string text = "\n";
    text += QuoteWord(object.modifier);
    text += ' ';
    text += object.type;
    text += ' ';
    text += QuoteWord(object.name);
    text += '\n';
    if (object.type == "alias") {
        text += '\t';
        text += QuoteWord(object.sargs.empty() ? "" : object.sargs[0]);
        text += '\n';
        return text;
    }
    text += std::to_string(object.sargs.size());
    for (const std::string& s : object.sargs) {
        text += ' ';
        // mist's source names go out as they are (m_mist), others quoted as fputword() does.
        text += object.type == "mist" ? s : QuoteWord(s);
    }
    text += "\n0\n";
    AppendRealArgs(text, object.type, object.rargs);
    return text;
}

}  // namespace rt
