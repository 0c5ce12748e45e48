// SPDX-License-Identifier: MIT
#include "rtrace/command_line.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>

#include "core/error.h"
#include "program/arguments.h"

namespace rt {
namespace {

// Radiance's default RAYPATH, searched for -aI/-aE/-tI/-tE files.
constexpr const char* kDefaultRaypath = ".:/usr/local/lib/ray";
// DEFAULT_PMAP_GATHER in Radiance's pmapparm.h.
constexpr int kDefaultPhotonGather = 40;

[[noreturn]] void CommandLineError(const std::string& arg) {
    ThrowUserError("command line error at '" + arg + "'");
}

int ToInt(const std::string& s) { return std::atoi(s.c_str()); }
double ToReal(const std::string& s) { return std::atof(s.c_str()); }

// Radiance's getpath(name, getrlibpath(), R_OK): names with a directory part
// are used as given, others are searched on RAYPATH.
std::string FindOnRaypath(const std::string& name) {
    if (name.find('/') != std::string::npos) return name;
    const char* env = std::getenv("RAYPATH");
    std::string path = env ? env : kDefaultRaypath;
    std::size_t start = 0;
    while (start <= path.size()) {
        std::size_t end = path.find(':', start);
        if (end == std::string::npos) end = path.size();
        std::string dir = path.substr(start, end - start);
        std::string candidate = dir.empty() ? name : dir + "/" + name;
        if (std::ifstream(candidate)) return candidate;
        start = end + 1;
    }
    return name;
}

std::vector<std::string> ReadWordFile(const std::string& name, const char* what) {
    errno = 0;
    std::optional<std::vector<std::string>> words = ReadWords(FindOnRaypath(name));
    if (!words) {
        // With the reason, as Radiance's SYSTEM errors give it.
        const int err = errno;
        ThrowSystemError(std::string("cannot open ") + what + " file \"" + name + "\"" +
                         (err != 0 ? std::string(": ") + std::strerror(err) : std::string()));
    }
    return std::move(*words);
}

// -ai/-ae and -ti/-te share Radiance's rule: the first use of the other kind
// restarts the list.
void AddToList(std::vector<std::string>& list, bool& isInclude, bool* isSet, bool include,
               std::vector<std::string> words) {
    bool set = isSet ? *isSet : true;
    if (!set || isInclude != include) {
        list.clear();
        isInclude = include;
        if (isSet) *isSet = true;
    }
    list.insert(list.end(), std::make_move_iterator(words.begin()),
                std::make_move_iterator(words.end()));
}

void Appendf(std::string& out, const char* format, ...) __attribute__((format(printf, 2, 3)));
void Appendf(std::string& out, const char* format, ...) {
    char buf[512];
    va_list ap;
    va_start(ap, format);
    int n = std::vsnprintf(buf, sizeof buf, format, ap);
    va_end(ap);
    if (n < 0) return;
    if (static_cast<std::size_t>(n) < sizeof buf) {
        out.append(buf, static_cast<std::size_t>(n));
        return;
    }
    std::string big(static_cast<std::size_t>(n) + 1, '\0');
    va_start(ap, format);
    std::vsnprintf(big.data(), big.size(), format, ap);
    va_end(ap);
    big.resize(static_cast<std::size_t>(n));
    out += big;
}

const char* OutputLetterName(char c) {
    switch (c) {
        case 't': case 'T': return " trace";
        case 'o': return " origin";
        case 'd': return " direction";
        case 'r': return " reflect_contrib";
        case 'R': return " reflect_length";
        case 'x': return " unreflect_contrib";
        case 'X': return " unreflect_length";
        case 'v': return " value";
        case 'V': return " contribution";
        case 'l': return " length";
        case 'L': return " first_length";
        case 'p': return " point";
        case 'n': return " normal";
        case 'N': return " unperturbed_normal";
        case 's': return " surface";
        case 'w': return " weight";
        case 'W': return " coefficient";
        case 'm': return " modifier";
        case 'M': return " material";
        case '-': return " stroke";
    }
    return "";
}

// ----- the table -----

using ToggleField = bool& (*)(RtraceOptions&);
using IntField = int& (*)(RtraceOptions&);
using RealField = double& (*)(RtraceOptions&);
using RgbField = Rgb& (*)(RtraceOptions&);
using WordAction = void (*)(RtraceOptions&, const std::string&);
using AttachedAction = bool (*)(RtraceOptions&, std::string_view rest);  // false: bad
/// Gets the words after the option; returns how many it used, -1 if bad.
using CustomAction = int (*)(RtraceOptions&, std::span<const std::string>, const WarningSink&);
/// Appends a row's -defaults line in a layout of its own.
using DefaultsLine = void (*)(std::string& out, const RtraceOptions&);

struct OptionRow {
    OptionInfo info;
    ToggleField toggle = nullptr;
    IntField integer = nullptr;
    RealField real = nullptr;
    RgbField rgb = nullptr;
    WordAction word = nullptr;
    AttachedAction attached = nullptr;
    CustomAction custom = nullptr;
    /// Checks, or clamps, each value as it is stored; throws rt::Error.
    void (*validate)(RtraceOptions&) = nullptr;
    /// Printed by -defaults, in table order: by `line`, or else in the layout
    /// of the row's kind with `help` as the comment ("-dt %f\t\t\t# direct
    /// threshold"); toggles print "+" and `whenOn` or "-" and `whenOff`, and
    /// nothing when off if `whenOff` is empty.
    bool listed = false;
    DefaultsLine line = nullptr;
    std::string_view whenOn = {}, whenOff = {};

    constexpr OptionRow Listed() const {
        OptionRow r = *this;
        r.listed = true;
        return r;
    }
    constexpr OptionRow Listed(DefaultsLine ownLine) const {
        OptionRow r = Listed();
        r.line = ownLine;
        return r;
    }
    constexpr OptionRow Listed(std::string_view on, std::string_view off) const {
        OptionRow r = Listed();
        r.whenOn = on;
        r.whenOff = off;
        return r;
    }
    constexpr OptionRow Validated(void (*check)(RtraceOptions&)) const {
        OptionRow r = *this;
        r.validate = check;
        return r;
    }
};

constexpr std::string_view kYes = "yes";

/// A row of `kind` whose action `f` goes in member `field` (the row
/// constructors below differ only in these).
template <auto field, typename Action>
constexpr OptionRow MakeRow(ValueKind kind, std::string_view name, std::string_view help,
                            Action f, std::string_view status) {
    OptionRow r{{name, kind, help, status}};
    r.*field = f;
    return r;
}
constexpr OptionRow Toggle(std::string_view name, std::string_view help, ToggleField f,
                           std::string_view status = kYes) {
    return MakeRow<&OptionRow::toggle>(ValueKind::Toggle, name, help, f, status);
}
constexpr OptionRow Int(std::string_view name, std::string_view help, IntField f,
                        std::string_view status = kYes) {
    return MakeRow<&OptionRow::integer>(ValueKind::Int, name, help, f, status);
}
constexpr OptionRow Real(std::string_view name, std::string_view help, RealField f,
                         std::string_view status = kYes) {
    return MakeRow<&OptionRow::real>(ValueKind::Real, name, help, f, status);
}
constexpr OptionRow Color(std::string_view name, std::string_view help, RgbField f,
                          std::string_view status = kYes) {
    return MakeRow<&OptionRow::rgb>(ValueKind::Rgb, name, help, f, status);
}
constexpr OptionRow Word(std::string_view name, std::string_view help, WordAction f,
                         std::string_view status = kYes) {
    return MakeRow<&OptionRow::word>(ValueKind::Word, name, help, f, status);
}
constexpr OptionRow Attached(std::string_view name, std::string_view help, AttachedAction f) {
    return MakeRow<&OptionRow::attached>(ValueKind::Attached, name, help, f, kYes);
}
constexpr OptionRow Custom(std::string_view name, std::string_view help, CustomAction f,
                           std::string_view status) {
    return MakeRow<&OptionRow::custom>(ValueKind::Custom, name, help, f, status);
}

bool SetFormats(RtraceOptions& o, std::string_view rest) {
    auto isData = [](char c) { return c == 'a' || c == 'f' || c == 'd'; };
    if (rest.empty() || !isData(rest[0])) return false;
    if (rest.size() == 1) {
        o.inputFormat = o.outputFormat = rest[0];
        return true;
    }
    if (rest.size() != 2 || !(isData(rest[1]) || rest[1] == 'c')) return false;
    o.inputFormat = rest[0];
    o.outputFormat = rest[1];
    return true;
}

int ParsePhotonMap(RtraceOptions& o, std::span<const std::string> v, const WarningSink& warn) {
    // Asking for a photon map implies indirect light (pmapopt.c does this even
    // when the rest of the option turns out to be bad).
    o.ambient.bounces += (o.ambient.bounces == 0);
    if (v.empty() || !IsWordArgument(v[0])) return -1;
    PhotonMapOption map{v[0], kDefaultPhotonGather, kDefaultPhotonGather};
    if (v.size() < 2 || !IsIntArgument(v[1])) {
        warn("missing photon lookup bandwidth, defaulting to " +
             std::to_string(kDefaultPhotonGather));
        o.photonMaps.push_back(map);
        return 1;
    }
    map.minGather = map.maxGather = ToInt(v[1]);
    if (map.minGather == 0) return -1;
    if (v.size() < 3 || !IsIntArgument(v[2])) {
        o.photonMaps.push_back(map);
        return 2;
    }
    map.maxGather = ToInt(v[2]);
    if (map.minGather >= map.maxGather) return -1;
    o.photonMaps.push_back(map);
    return 3;
}

int ParsePhotonRadius(RtraceOptions& o, std::span<const std::string> v, const WarningSink&) {
    if (v.empty() || !IsRealArgument(v[0]) || (o.photonMaxRadius = ToReal(v[0])) <= 0)
        ThrowUserError("invalid max photon search radius");
    return 1;
}

constexpr std::string_view kNoPretest = "parsed; no pretest is needed (README, Differences)";


void CheckProcesses(RtraceOptions& o) {
    if (o.processes <= 0) ThrowUserError("bad number of processes");
}

// -defaults lines that do not follow their kind's layout.
void ProcessesLine(std::string& s, const RtraceOptions& o) {
    Appendf(s, "-n %-2d\t\t\t\t# number of rendering processes\n", o.processes);
}
void XResolutionLine(std::string& s, const RtraceOptions& o) {
    Appendf(s, "-x %-9d\t\t\t# %s\n", o.xResolution,
            o.yResolution && o.xResolution ? "x resolution" : "flush interval");
}
void FormatsLine(std::string& s, const RtraceOptions& o) {
    Appendf(s, "-f%c%c\t\t\t\t# format input/output = %s/%s\n", o.inputFormat, o.outputFormat,
            FormatName(o.inputFormat).data(), FormatName(o.outputFormat).data());
}
void OutputSpecLine(std::string& s, const RtraceOptions& o) {
    Appendf(s, "-o%-9s\t\t\t# output", o.outputSpec.c_str());
    for (char c : o.outputSpec) s += OutputLetterName(c);
    s += '\n';
}
void ReflectionLimitLine(std::string& s, const RtraceOptions& o) {
    const int lr = o.shading.limits.reflections;
    Appendf(s, "-lr %-9d\t\t\t# limit reflection%s\n", lr, lr <= 0 ? " (Russian roulette)" : "");
}
void WeightLimitLine(std::string& s, const RtraceOptions& o) {
    Appendf(s, "-lw %.2e\t\t\t# limit weight\n", o.shading.limits.weight);
}
void ExtinctionLine(std::string& s, const RtraceOptions& o) {
    const Rgb& e = o.shading.medium.extinction;
    Appendf(s, "-me %.2e %.2e %.2e\t# mist extinction coefficient\n", e.r, e.g, e.b);
}
void PhotonRadiusLine(std::string& s, const RtraceOptions& o) {
    Appendf(s, "-am %.1f\t\t\t\t# max photon search radius\n", o.photonMaxRadius);
}

// In Radiance's -defaults order (rtmain.c printdefaults(), then renderopts.c
// print_rdefaults()); rows that -defaults does not show sit with their group.
/// Radiance's toggle suffix (-bv+, -bvn, ...): true for one of yYtT+1, false
/// for one of nNfF-0, nullopt for anything else.
std::optional<bool> ToggleSuffix(std::string_view rest) {
    if (rest.size() != 1 || rest[0] == '\0') return std::nullopt;
    if (std::strchr("yYtT+1", rest[0])) return true;
    if (std::strchr("nNfF-0", rest[0])) return false;
    return std::nullopt;
}

constexpr OptionRow kOptionRows[] = {
    // rtrace-specific (rtmain.c)
    Toggle("-I", "immediate irradiance at point/normal",
           [](RtraceOptions& o) -> bool& { return o.immediateIrradiance; })
        .Listed("immediate irradiance on", ""),
    Int("-n", "number of rendering processes", [](RtraceOptions& o) -> int& { return o.processes; },
        "yes: N threads sharing one cache and the ambient file (max 64)")
        .Validated(CheckProcesses)
        .Listed(ProcessesLine),
    Int("-x", "x resolution / flush interval", [](RtraceOptions& o) -> int& { return o.xResolution; })
        .Listed(XResolutionLine),
    Int("-y", "y resolution", [](RtraceOptions& o) -> int& { return o.yResolution; }).Listed(),
    Toggle("-ld", "limit ray distance to |direction|", [](RtraceOptions& o) -> bool& { return o.limitDistance; })
        .Listed("limit distance on", "limit distance off"),
    Toggle("-h", "output header", [](RtraceOptions& o) -> bool& { return o.header; })
        .Listed("output header", "no header"),
    Attached("-f", "input/output format a|f|d [a|f|d|c]", SetFormats).Listed(FormatsLine),
    Attached("-o", "output specification",
             [](RtraceOptions& o, std::string_view rest) { o.outputSpec = std::string(rest); return true; })
        .Listed(OutputSpecLine),
    Toggle("-w", "warning messages", [](RtraceOptions& o) -> bool& { return o.warnings; })
        .Listed("warning messages on", "warning messages off"),
    Int("-seed", "random seed", [](RtraceOptions& o) -> int& { return o.seed; },
        "lazyrad extension: runs are repeatable; change the seed for another sample"),
    Int("-t", "progress report interval in seconds", [](RtraceOptions& o) -> int& { return o.reportSeconds; },
        "lazyrad extension (rpict's -t): progress on stderr, summary at exit"),
    Word("-e", "append error messages to file", [](RtraceOptions& o, const std::string& v) { o.errorFile = v; }),
    Word("-ti", "trace include modifier",
         [](RtraceOptions& o, const std::string& v) {
             AddToList(o.traceModifiers, o.traceListIsInclude, &o.traceListSet, true, {v});
         }),
    Word("-tI", "trace include modifiers from file",
         [](RtraceOptions& o, const std::string& v) {
             AddToList(o.traceModifiers, o.traceListIsInclude, &o.traceListSet, true,
                       ReadWordFile(v, "trace include"));
         }),
    Word("-te", "trace exclude modifier",
         [](RtraceOptions& o, const std::string& v) {
             AddToList(o.traceModifiers, o.traceListIsInclude, &o.traceListSet, false, {v});
         }),
    Word("-tE", "trace exclude modifiers from file",
         [](RtraceOptions& o, const std::string& v) {
             AddToList(o.traceModifiers, o.traceListIsInclude, &o.traceListSet, false,
                       ReadWordFile(v, "trace exclude"));
         }),
    Word("-P", "persist file",
         [](RtraceOptions& o, const std::string& v) { o.persistFile = v; o.persistParallel = false; },
         "parsed; persistent mode not implemented (warning)"),
    Word("-PP", "parallel persist file",
         [](RtraceOptions& o, const std::string& v) { o.persistFile = v; o.persistParallel = true; },
         "parsed; persistent mode not implemented (warning)"),
    // common rendering options (renderopts.c)
    Toggle("-i", "irradiance calculation", [](RtraceOptions& o) -> bool& { return o.irradianceAtHit; })
        .Listed("irradiance calculation on", "irradiance calculation off"),
    Toggle("-u", "uncorrelated Monte Carlo sampling", [](RtraceOptions& o) -> bool& { return o.shading.uncorrelated; })
        .Listed("uncorrelated Monte Carlo sampling", "correlated quasi-Monte Carlo sampling"),
    Toggle("-bv", "back face visibility", [](RtraceOptions& o) -> bool& { return o.shading.backfaceVisible; })
        .Listed("back face visibility on", "back face visibility off"),
    Real("-dt", "direct threshold", [](RtraceOptions& o) -> double& { return o.shading.direct.threshold; }).Listed(),
    Real("-dc", "direct certainty", [](RtraceOptions& o) -> double& { return o.shading.direct.certainty; }).Listed(),
    Real("-dj", "direct jitter", [](RtraceOptions& o) -> double& { return o.shading.direct.jitter; }).Listed(),
    Real("-ds", "direct sampling", [](RtraceOptions& o) -> double& { return o.shading.direct.sampling; }).Listed(),
    Int("-dr", "direct relays", [](RtraceOptions& o) -> int& { return o.shading.direct.relays; }).Listed(),
    Int("-dp", "direct pretest density", [](RtraceOptions& o) -> int& { return o.shading.direct.pretest; }, kNoPretest).Listed(),
    Toggle("-dv", "direct (light source) visibility", [](RtraceOptions& o) -> bool& { return o.shading.direct.sourcesVisible; })
        .Listed("direct visibility on", "direct visibility off"),
    Real("-ss", "specular sampling", [](RtraceOptions& o) -> double& { return o.shading.specular.sampling; }).Listed(),
    Real("-st", "specular threshold", [](RtraceOptions& o) -> double& { return o.shading.specular.threshold; }).Listed(),
    Color("-av", "ambient value", [](RtraceOptions& o) -> Rgb& { return o.ambient.value; }).Listed(),
    Int("-aw", "ambient value weight", [](RtraceOptions& o) -> int& { return o.ambient.valueWeight; }).Listed(),
    Int("-ab", "ambient bounces", [](RtraceOptions& o) -> int& { return o.ambient.bounces; }).Listed(),
    Real("-aa", "ambient accuracy", [](RtraceOptions& o) -> double& { return o.ambient.accuracy; }).Listed(),
    Int("-ar", "ambient resolution", [](RtraceOptions& o) -> int& { return o.ambient.resolution; }).Listed(),
    Int("-ad", "ambient divisions", [](RtraceOptions& o) -> int& { return o.ambient.divisions; }).Listed(),
    Int("-as", "ambient super-samples", [](RtraceOptions& o) -> int& { return o.ambient.superSamples; }).Listed(),
    // lazyrad's own; not Listed: -defaults stays Radiance's.
    // -ah+ Hessian records at every level, -ah- classic ones, -ahm (the
    // default) classic first-level records and Hessian deeper ones; a bare
    // -ah is -ah+, as it was when -ah was a toggle.
    Attached("-ah", "ambient record methods (+ Hessian, - classic, m mixed)",
             [](RtraceOptions& o, std::string_view rest) {
                 const std::optional<bool> on = ToggleSuffix(rest);
                 if (rest.empty() || on == true) {
                     o.ambient.recordMethods = RecordMethods::Hessian;
                 } else if (on == false) {
                     o.ambient.recordMethods = RecordMethods::Classic;
                 } else if (rest == "m") {
                     o.ambient.recordMethods = RecordMethods::Mixed;
                 } else {
                     return false;
                 }
                 return true;
             }),
    Word("-ai", "ambient include modifier",
         [](RtraceOptions& o, const std::string& v) {
             AddToList(o.ambient.modifierList, o.ambient.listIsInclude, nullptr, true, {v});
         }),
    Word("-aI", "ambient include modifiers from file",
         [](RtraceOptions& o, const std::string& v) {
             AddToList(o.ambient.modifierList, o.ambient.listIsInclude, nullptr, true,
                       ReadWordFile(v, "ambient include"));
         }),
    Word("-ae", "ambient exclude modifier",
         [](RtraceOptions& o, const std::string& v) {
             AddToList(o.ambient.modifierList, o.ambient.listIsInclude, nullptr, false, {v});
         }),
    Word("-aE", "ambient exclude modifiers from file",
         [](RtraceOptions& o, const std::string& v) {
             AddToList(o.ambient.modifierList, o.ambient.listIsInclude, nullptr, false,
                       ReadWordFile(v, "ambient exclude"));
         }),
    Word("-af", "ambient file", [](RtraceOptions& o, const std::string& v) { o.ambient.file = v; }),
    Color("-me", "mist extinction coefficient", [](RtraceOptions& o) -> Rgb& { return o.shading.medium.extinction; })
        .Listed(ExtinctionLine),
    Color("-ma", "mist scattering albedo", [](RtraceOptions& o) -> Rgb& { return o.shading.medium.albedo; }).Listed(),
    Real("-mg", "mist scattering eccentricity", [](RtraceOptions& o) -> double& { return o.shading.medium.eccentricity; }).Listed(),
    Real("-ms", "mist sampling distance", [](RtraceOptions& o) -> double& { return o.shading.medium.samplingDistance; }).Listed(),
    Int("-lr", "limit reflection", [](RtraceOptions& o) -> int& { return o.shading.limits.reflections; })
        .Listed(ReflectionLimitLine),
    Real("-lw", "limit weight", [](RtraceOptions& o) -> double& { return o.shading.limits.weight; })
        .Listed(WeightLimitLine),
    // photon map options (pmapopt.c)
    Custom("-ap", "photon map file [bandwidth [max bandwidth]]", ParsePhotonMap,
           "parsed; photon maps not implemented (warning)"),
    Custom("-am", "max photon search radius", ParsePhotonRadius, "parsed; photon maps not implemented")
        .Listed(PhotonRadiusLine),
};

constexpr auto kOptionInfos = [] {
    std::array<OptionInfo, std::size(kOptionRows)> infos{};
    for (std::size_t i = 0; i < infos.size(); ++i) infos[i] = kOptionRows[i].info;
    return infos;
}();

const OptionRow* FindRow(std::string_view arg) {
    for (const OptionRow& row : kOptionRows) {
        std::string_view name = row.info.name;
        switch (row.info.kind) {
            case ValueKind::Attached:
                if (arg.starts_with(name)) return &row;
                break;
            case ValueKind::Toggle:
                // Radiance's check_bool() reads one character after the name
                // and ignores the rest (-I+, -Iyes and -h++ are all "on").
                if (arg.starts_with(name) &&
                    (arg.size() == name.size() || ToggleSuffix(arg.substr(name.size(), 1))))
                    return &row;
                break;
            default:
                if (arg == name) return &row;
        }
    }
    return nullptr;
}

/// Applies `row` to the option word args[i]; returns how many following words
/// it used, or -1 for Radiance's "badopt".
int ApplyRow(const OptionRow& row, RtraceOptions& o, std::span<const std::string> args,
             std::size_t i, const WarningSink& warn) {
    const std::string& arg = args[i];
    std::span<const std::string> rest = args.subspan(i + 1);
    switch (row.info.kind) {
        case ValueKind::Toggle: {
            bool& field = row.toggle(o);
            if (arg.size() == row.info.name.size()) {
                field = !field;
                return 0;
            }
            const std::optional<bool> on =
                ToggleSuffix(std::string_view(arg).substr(row.info.name.size(), 1));
            if (!on) return -1;
            field = *on;
            return 0;
        }
        case ValueKind::Int:
            if (rest.empty() || !IsIntArgument(rest[0])) return -1;
            row.integer(o) = ToInt(rest[0]);
            return 1;
        case ValueKind::Real:
            if (rest.empty() || !IsRealArgument(rest[0])) return -1;
            row.real(o) = ToReal(rest[0]);
            return 1;
        case ValueKind::Rgb:
            if (rest.size() < 3 || !IsRealArgument(rest[0]) || !IsRealArgument(rest[1]) ||
                !IsRealArgument(rest[2]))
                return -1;
            row.rgb(o) = Rgb(ToReal(rest[0]), ToReal(rest[1]), ToReal(rest[2]));
            return 3;
        case ValueKind::Word:
            if (rest.empty() || !IsWordArgument(rest[0])) return -1;
            row.word(o, rest[0]);
            return 1;
        case ValueKind::Attached:
            return row.attached(o, std::string_view(arg).substr(row.info.name.size())) ? 0 : -1;
        case ValueKind::Custom:
            return row.custom(o, rest, warn);
    }
    return -1;
}

/// Appends `row`'s -defaults line; `o` is a copy, as the table's fields are
/// reached through mutable references.
void AppendDefaultsLine(std::string& s, const OptionRow& row, RtraceOptions& o) {
    if (row.line) {
        row.line(s, o);
        return;
    }
    const std::string name(row.info.name), help(row.info.help);
    switch (row.info.kind) {
        case ValueKind::Toggle:
            if (row.toggle(o)) {
                Appendf(s, "%s+\t\t\t\t# %s\n", name.c_str(), std::string(row.whenOn).c_str());
            } else if (!row.whenOff.empty()) {
                Appendf(s, "%s-\t\t\t\t# %s\n", name.c_str(), std::string(row.whenOff).c_str());
            }
            break;
        case ValueKind::Int:
            Appendf(s, "%s %-9d\t\t\t# %s\n", name.c_str(), row.integer(o), help.c_str());
            break;
        case ValueKind::Real:
            Appendf(s, "%s %f\t\t\t# %s\n", name.c_str(), row.real(o), help.c_str());
            break;
        case ValueKind::Rgb: {
            const Rgb& c = row.rgb(o);
            Appendf(s, "%s %f %f %f\t# %s\n", name.c_str(), c.r, c.g, c.b, help.c_str());
            break;
        }
        default:
            throw Error(Error::Kind::Internal, "no -defaults layout for " + name);
    }
}

/// The options the renderer reads in a form of its own.
void DeriveOptions(RtraceOptions& o) {
    o.shading.irradiance = o.immediateIrradiance ? IrradianceMode::Immediate
                           : o.irradianceAtHit   ? IrradianceMode::AtHit
                                                 : IrradianceMode::Off;
    // Repeatable runs: the random streams come from -seed and each ray's
    // position in the input, never the clock (Radiance seeds -u+ runs with
    // time(0), so two of its runs differ).
    o.shading.seed = static_cast<unsigned long long>(static_cast<unsigned>(o.seed));
}

}  // namespace

std::span<const OptionInfo> OptionTable() { return kOptionInfos; }

std::string_view FormatName(char format) {
    switch (format) {
        case 'a': return "ascii";
        case 'f': return "float";
        case 'd': return "double";
        case 'c': return "32-bit_rle_rgbe";
    }
    return "unknown";
}

void RequireScene(const CommandLine& cl) {
    if (cl.sceneFiles.empty()) ThrowUserError("missing octree argument");
}

CommandLine ParseCommandLine(std::span<const std::string> argsIn, const WarningSink& warn,
                             SceneArgument scene) {
    CommandLine cl;
    std::vector<std::string>& args = cl.args;
    args.assign(argsIn.begin(), argsIn.end());
    if (args.empty()) args.emplace_back("rtrace");
    args[0] = ProgramName(args[0]);
    RtraceOptions& o = cl.options;

    std::size_t i = 1;
    for (; i < args.size(); ++i) {
        ExpandInPlace(args, i);
        if (i >= args.size() || args[i].empty() || args[i][0] != '-' || args[i] == "-") break;
        const std::string& arg = args[i];
        if (arg == "-version") {
            cl.action = CommandLine::Action::PrintVersion;
            return cl;
        }
        if (arg == "-defaults" || arg == "-help") {
            cl.action = CommandLine::Action::PrintDefaults;
            DeriveOptions(o);
            return cl;
        }
        const OptionRow* row = FindRow(arg);
        // Radiance's pmapopt.c reads any -am... as the photon radius option
        // and rejects one with letters after it in that option's words.
        if (!row && arg.size() > 3 && arg.compare(0, 3, "-am") == 0)
            ThrowUserError("invalid max photon search radius");
        if (!row) CommandLineError(arg);
        int used = ApplyRow(*row, o, args, i, warn);
        if (used < 0) CommandLineError(arg);
        if (row->validate) row->validate(o);
        i += static_cast<std::size_t>(used);
    }
    if (o.processes > 1 && !o.persistFile.empty())
        ThrowUserError("multiprocessing incompatible with persist file");
    // Radiance takes any int and runs out of memory; one hemisphere's
    // divisions are bounded instead (ambient/ambient_options.h).
    if (o.ambient.divisions > kMaxAmbientDivisions) {
        ThrowUserError("-ad " + std::to_string(o.ambient.divisions) + " is above the limit of " +
                       std::to_string(kMaxAmbientDivisions) + " hemisphere divisions");
    }
    DeriveOptions(o);

    cl.firstScene = i;
    for (std::size_t k = i; k < args.size(); ++k) {
        ExpandInPlace(args, k);
        if (k >= args.size()) break;
        // "-" is a scene on standard input; a "!command" argument is one whose
        // output is an octree. An option among the scenes is an error named
        // after the first scene, as Radiance names the octree when more than
        // one argument follows the options.
        if (args[k].empty()) CommandLineError(args[k]);
        if (args[k][0] == '-' && args[k] != "-") CommandLineError(args[i]);
        cl.sceneFiles.push_back(args[k]);
    }
    if (scene == SceneArgument::Required) RequireScene(cl);
    return cl;
}

std::string FormatDefaults(const RtraceOptions& options) {
    RtraceOptions o = options;
    std::string s;
    for (const OptionRow& row : kOptionRows)
        if (row.listed) AppendDefaultsLine(s, row, o);
    return s;
}

std::optional<std::string> InfoText(const CommandLine& cl) {
    switch (cl.action) {
        case CommandLine::Action::PrintVersion: return std::string(kVersionString) + '\n';
        case CommandLine::Action::PrintDefaults: return FormatDefaults(cl.options);
        case CommandLine::Action::Render: break;
    }
    return std::nullopt;
}

}  // namespace rt
