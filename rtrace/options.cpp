// SPDX-License-Identifier: MIT
#include "rtrace/options.h"

#include <array>
#include <cctype>
#include <cerrno>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

#include "core/error.h"

namespace rt {
namespace {

// Radiance keeps expanding the same position while it starts with @ or $; a
// file that names itself would loop forever there, so we stop at this depth.
constexpr int kMaxExpansionDepth = 64;
// Radiance's default RAYPATH, searched for -aI/-aE/-tI/-tE files.
constexpr const char* kDefaultRaypath = ".:/usr/local/lib/ray";
// DEFAULT_PMAP_GATHER in Radiance's pmapparm.h.
constexpr int kDefaultPhotonGather = 40;

[[noreturn]] void CommandLineError(const std::string& arg) {
    ThrowUserError("command line error at '" + arg + "'");
}

// ----- value validation (Radiance's words.c / badarg.c) -----

// Radiance's iskip(): returns the position after an integer, or npos.
std::size_t SkipInt(std::string_view s, std::size_t i) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
    if (i >= s.size() || !std::isdigit(static_cast<unsigned char>(s[i]))) return std::string_view::npos;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    return i;
}

// Radiance's fskip().
std::size_t SkipReal(std::string_view s) {
    std::size_t i = 0;
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
    std::size_t digits = 0;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++digits;
    if (i < s.size() && s[i] == '.') {
        ++i;
        while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i, ++digits;
    }
    if (digits == 0) return std::string_view::npos;
    if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) return SkipInt(s, i + 1);
    return i;
}

// badarg() accepts a number followed by the end or by a blank.
bool EndsAtDelimiter(std::string_view s, std::size_t end) {
    return end != std::string_view::npos &&
           (end == s.size() || s[end] == ' ' || s[end] == '\t' || s[end] == '\r' ||
            s[end] == '\n');
}

bool IsWordArgument(std::string_view s) {
    std::size_t i = 0;
    while (i < s.size() && s[i] == ' ') ++i;
    if (i == s.size()) return false;
    for (; i < s.size(); ++i)
        if (!std::isprint(static_cast<unsigned char>(s[i]))) return false;
    return true;
}

int ToInt(const std::string& s) { return std::atoi(s.c_str()); }
double ToReal(const std::string& s) { return std::atof(s.c_str()); }

std::string ReadWholeFile(const std::string& path, bool* ok) {
    std::ifstream f(path, std::ios::binary);
    if (!f) {
        *ok = false;
        return {};
    }
    *ok = true;
    return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

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
    bool ok = false;
    std::string text = ReadWholeFile(FindOnRaypath(name), &ok);
    if (!ok) ThrowSystemError(std::string("cannot open ") + what + " file \"" + name + "\"");
    return SplitWords(text);
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

// ----- the table -----

using ToggleField = bool& (*)(RtraceOptions&);
using IntField = int& (*)(RtraceOptions&);
using RealField = double& (*)(RtraceOptions&);
using RgbField = Rgb& (*)(RtraceOptions&);
using WordAction = void (*)(RtraceOptions&, const std::string&);
using AttachedAction = bool (*)(RtraceOptions&, std::string_view rest);  // false: bad
/// Gets the words after the option; returns how many it used, -1 if bad.
using CustomAction = int (*)(RtraceOptions&, std::span<const std::string>, const WarningSink&);

struct OptionRow {
    OptionInfo info;
    ToggleField toggle = nullptr;
    IntField integer = nullptr;
    RealField real = nullptr;
    RgbField rgb = nullptr;
    WordAction word = nullptr;
    AttachedAction attached = nullptr;
    CustomAction custom = nullptr;
    void (*validate)(const RtraceOptions&) = nullptr;  // after an Int value is stored
};

constexpr std::string_view kYes = "yes";

constexpr OptionRow Toggle(std::string_view name, std::string_view help, ToggleField f,
                           std::string_view status = kYes) {
    OptionRow r{{name, ValueKind::Toggle, help, status}};
    r.toggle = f;
    return r;
}
constexpr OptionRow Int(std::string_view name, std::string_view help, IntField f,
                        std::string_view status = kYes) {
    OptionRow r{{name, ValueKind::Int, help, status}};
    r.integer = f;
    return r;
}
constexpr OptionRow Real(std::string_view name, std::string_view help, RealField f,
                         std::string_view status = kYes) {
    OptionRow r{{name, ValueKind::Real, help, status}};
    r.real = f;
    return r;
}
constexpr OptionRow Color(std::string_view name, std::string_view help, RgbField f,
                          std::string_view status = kYes) {
    OptionRow r{{name, ValueKind::Rgb, help, status}};
    r.rgb = f;
    return r;
}
constexpr OptionRow Word(std::string_view name, std::string_view help, WordAction f,
                         std::string_view status = kYes) {
    OptionRow r{{name, ValueKind::Word, help, status}};
    r.word = f;
    return r;
}
constexpr OptionRow Attached(std::string_view name, std::string_view help, AttachedAction f) {
    OptionRow r{{name, ValueKind::Attached, help, kYes}};
    r.attached = f;
    return r;
}
constexpr OptionRow Custom(std::string_view name, std::string_view help, CustomAction f,
                           std::string_view status) {
    OptionRow r{{name, ValueKind::Custom, help, status}};
    r.custom = f;
    return r;
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
        warn("no photon lookup bandwidth specified, using default " +
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
        ThrowUserError("invalid max photon search radius coefficient");
    return 1;
}

constexpr std::string_view kNoVirtual = "parsed; virtual sources not implemented";
constexpr std::string_view kNoMedium = "parsed; participating media not implemented";


constexpr OptionRow kOptionRows[] = {
    // rtrace-specific (rtmain.c)
    Int("-n", "number of rendering processes", [](RtraceOptions& o) -> int& { return o.processes; },
        "yes: N threads sharing one cache and the ambient file (max 64)"),
    Int("-x", "x resolution / flush interval", [](RtraceOptions& o) -> int& { return o.xResolution; }),
    Int("-y", "y resolution", [](RtraceOptions& o) -> int& { return o.yResolution; }),
    Int("-seed", "random seed", [](RtraceOptions& o) -> int& { return o.seed; },
        "lazyrad extension: runs are repeatable; change the seed for another sample"),
    Int("-t", "progress report interval in seconds", [](RtraceOptions& o) -> int& { return o.reportSeconds; },
        "lazyrad extension (rpict's -t): progress on stderr, summary at exit"),
    Toggle("-ld", "limit ray distance to |direction|", [](RtraceOptions& o) -> bool& { return o.limitDistance; }),
    Toggle("-h", "output header", [](RtraceOptions& o) -> bool& { return o.header; }),
    Attached("-f", "input/output format a|f|d [a|f|d|c]", SetFormats),
    Attached("-o", "output specification",
             [](RtraceOptions& o, std::string_view rest) { o.outputSpec = std::string(rest); return true; }),
    Toggle("-w", "warning messages", [](RtraceOptions& o) -> bool& { return o.warnings; }),
    Word("-e", "append error messages to file", [](RtraceOptions& o, const std::string& v) { o.errorFile = v; }),
    Toggle("-I", "immediate irradiance at point/normal",
           [](RtraceOptions& o) -> bool& { return o.immediateIrradiance; }),
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
    Toggle("-u", "uncorrelated Monte Carlo sampling", [](RtraceOptions& o) -> bool& { return o.shading.uncorrelated; }),
    Toggle("-bv", "back face visibility", [](RtraceOptions& o) -> bool& { return o.shading.backfaceVisible; }),
    Real("-dt", "direct threshold", [](RtraceOptions& o) -> double& { return o.shading.direct.threshold; }),
    Real("-dc", "direct certainty", [](RtraceOptions& o) -> double& { return o.shading.direct.certainty; }),
    Real("-dj", "direct jitter", [](RtraceOptions& o) -> double& { return o.shading.direct.jitter; }),
    Int("-dr", "direct relays", [](RtraceOptions& o) -> int& { return o.shading.direct.relays; }, kNoVirtual),
    Int("-dp", "direct pretest density", [](RtraceOptions& o) -> int& { return o.shading.direct.pretest; }, kNoVirtual),
    Toggle("-dv", "direct (light source) visibility", [](RtraceOptions& o) -> bool& { return o.shading.direct.sourcesVisible; }),
    Real("-ds", "direct sampling", [](RtraceOptions& o) -> double& { return o.shading.direct.sampling; }),
    Real("-st", "specular threshold", [](RtraceOptions& o) -> double& { return o.shading.specular.threshold; }),
    Real("-ss", "specular sampling", [](RtraceOptions& o) -> double& { return o.shading.specular.sampling; }),
    Int("-lr", "limit reflection", [](RtraceOptions& o) -> int& { return o.shading.limits.reflections; }),
    Real("-lw", "limit weight", [](RtraceOptions& o) -> double& { return o.shading.limits.weight; }),
    Toggle("-i", "irradiance calculation", [](RtraceOptions& o) -> bool& { return o.irradianceAtHit; }),
    Color("-av", "ambient value", [](RtraceOptions& o) -> Rgb& { return o.ambient.value; }),
    Int("-aw", "ambient value weight", [](RtraceOptions& o) -> int& { return o.ambient.valueWeight; }),
    Real("-aa", "ambient accuracy", [](RtraceOptions& o) -> double& { return o.ambient.accuracy; }),
    Int("-ar", "ambient resolution", [](RtraceOptions& o) -> int& { return o.ambient.resolution; }),
    Int("-ad", "ambient divisions", [](RtraceOptions& o) -> int& { return o.ambient.divisions; }),
    Int("-as", "ambient super-samples", [](RtraceOptions& o) -> int& { return o.ambient.superSamples; }),
    // lazyrad's own; not in -defaults, whose output stays Radiance's.
    Toggle("-ah", "Hessian ambient records (Radiance 5's method)",
           [](RtraceOptions& o) -> bool& { return o.ambient.hessianRecords; }),
    Int("-ab", "ambient bounces", [](RtraceOptions& o) -> int& { return o.ambient.bounces; }),
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
    Color("-me", "mist extinction coefficient", [](RtraceOptions& o) -> Rgb& { return o.shading.medium.extinction; }, kNoMedium),
    Color("-ma", "mist scattering albedo", [](RtraceOptions& o) -> Rgb& { return o.shading.medium.albedo; }, kNoMedium),
    Real("-mg", "mist scattering eccentricity", [](RtraceOptions& o) -> double& { return o.shading.medium.eccentricity; }, kNoMedium),
    Real("-ms", "mist sampling distance", [](RtraceOptions& o) -> double& { return o.shading.medium.samplingDistance; }, kNoMedium),
    // photon map options (pmapopt.c)
    Custom("-ap", "photon map file [bandwidth [max bandwidth]]", ParsePhotonMap,
           "parsed; photon maps not implemented (warning)"),
    Custom("-am", "max photon search radius", ParsePhotonRadius, "parsed; photon maps not implemented"),
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
                if (arg.starts_with(name) && arg.size() <= name.size() + 1) return &row;
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
            char c = arg.back();
            if (std::strchr("yYtT+1", c)) field = true;
            else if (std::strchr("nNfF-0", c)) field = false;
            else return -1;
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

std::string BaseName(const std::string& path) {
    std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

/// Expands args[i] in place until it no longer starts with @ or $.
void ExpandInPlace(std::vector<std::string>& args, std::size_t i) {
    for (int depth = 0; i < args.size() && !args[i].empty() &&
                        (args[i][0] == '@' || args[i][0] == '$');
         ++depth) {
        if (depth == kMaxExpansionDepth) ThrowSystemError("cannot expand '" + args[i] + "'");
        std::vector<std::string> words = ExpandArgument(args[i]);
        args.erase(args.begin() + static_cast<std::ptrdiff_t>(i));
        args.insert(args.begin() + static_cast<std::ptrdiff_t>(i), words.begin(), words.end());
    }
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

const char* FormatName(char f) {
    switch (f) {
        case 'a': return "ascii";
        case 'f': return "float";
        case 'd': return "double";
        case 'c': return "32-bit_rle_rgbe";
    }
    return "unknown";
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

}  // namespace

std::span<const OptionInfo> OptionTable() { return kOptionInfos; }

bool IsIntArgument(std::string_view s) { return EndsAtDelimiter(s, SkipInt(s, 0)); }
bool IsRealArgument(std::string_view s) { return EndsAtDelimiter(s, SkipReal(s)); }

std::vector<std::string> SplitWords(std::string_view text) {
    std::vector<std::string> words;
    std::size_t i = 0;
    while (true) {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        if (i >= text.size()) break;
        char quote = 0;
        if (text[i] == '"' || text[i] == '\'') quote = text[i++];
        std::size_t start = i;
        while (i < text.size() &&
               (quote ? text[i] != quote : !std::isspace(static_cast<unsigned char>(text[i]))))
            ++i;
        words.emplace_back(text.substr(start, i - start));
        if (quote && i < text.size()) ++i;
    }
    return words;
}

std::vector<std::string> ExpandArgument(const std::string& arg) {
    if (arg.empty() || (arg[0] != '@' && arg[0] != '$')) return {arg};
    if (arg[0] == '@') {
        bool ok = false;
        std::string text = ReadWholeFile(arg.substr(1), &ok);
        if (!ok) ThrowSystemError("cannot expand '" + arg + "': " + std::strerror(ENOENT));
        return SplitWords(text);
    }
    const char* value = std::getenv(arg.c_str() + 1);
    if (!value) ThrowSystemError("cannot expand '" + arg + "'");
    return SplitWords(value);
}

CommandLine ParseCommandLine(std::span<const std::string> argsIn, const WarningSink& warn) {
    CommandLine cl;
    std::vector<std::string>& args = cl.args;
    args.assign(argsIn.begin(), argsIn.end());
    if (args.empty()) args.emplace_back("rtrace");
    args[0] = BaseName(args[0]);
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
            o.shading.irradiance = o.immediateIrradiance ? IrradianceMode::Immediate
                                   : o.irradianceAtHit   ? IrradianceMode::AtHit
                                                         : IrradianceMode::Off;
            return cl;
        }
        const OptionRow* row = FindRow(arg);
        if (!row) CommandLineError(arg);
        int used = ApplyRow(*row, o, args, i, warn);
        if (used < 0) CommandLineError(arg);
        if (row->info.name == "-n" && o.processes <= 0) ThrowUserError("bad number of processes");
        if (row->info.name == "-n" && o.processes > 64) o.processes = 64;  // Radiance's cap
        i += static_cast<std::size_t>(used);
    }
    if (o.processes > 1 && !o.persistFile.empty())
        ThrowUserError("multiprocessing incompatible with persist file");
    // Radiance takes any int and runs out of memory (a 23 GB process at -ad 5e8);
    // one hemisphere's divisions are bounded instead (ambient/options.h).
    if (o.ambient.divisions > kMaxAmbientDivisions) {
        ThrowUserError("-ad " + std::to_string(o.ambient.divisions) + " is above the limit of " +
                       std::to_string(kMaxAmbientDivisions) + " hemisphere divisions");
    }
    o.shading.irradiance = o.immediateIrradiance ? IrradianceMode::Immediate
                           : o.irradianceAtHit   ? IrradianceMode::AtHit
                                                 : IrradianceMode::Off;

    cl.firstScene = i;
    for (std::size_t k = i; k < args.size(); ++k) {
        ExpandInPlace(args, k);
        if (k >= args.size()) break;
        // "-" is a scene on standard input; a "!command" argument is one whose
        // output is an octree.
        if (args[k].empty() || (args[k][0] == '-' && args[k] != "-")) CommandLineError(args[k]);
        cl.sceneFiles.push_back(args[k]);
    }
    if (cl.sceneFiles.empty()) ThrowUserError("missing octree argument");
    return cl;
}

std::string FormatDefaults(const RtraceOptions& o) {
    std::string s;
    if (o.immediateIrradiance) s += "-I+\t\t\t\t# immediate irradiance on\n";
    Appendf(s, "-n %-2d\t\t\t\t# number of rendering processes\n", o.processes);
    Appendf(s, "-x %-9d\t\t\t# %s\n", o.xResolution,
            o.yResolution && o.xResolution ? "x resolution" : "flush interval");
    Appendf(s, "-y %-9d\t\t\t# y resolution\n", o.yResolution);
    s += o.limitDistance ? "-ld+\t\t\t\t# limit distance on\n" : "-ld-\t\t\t\t# limit distance off\n";
    s += o.header ? "-h+\t\t\t\t# output header\n" : "-h-\t\t\t\t# no header\n";
    Appendf(s, "-f%c%c\t\t\t\t# format input/output = %s/%s\n", o.inputFormat, o.outputFormat,
            FormatName(o.inputFormat), FormatName(o.outputFormat));
    Appendf(s, "-o%-9s\t\t\t# output", o.outputSpec.c_str());
    for (char c : o.outputSpec) s += OutputLetterName(c);
    s += '\n';
    s += o.warnings ? "-w+\t\t\t\t# warning messages on\n" : "-w-\t\t\t\t# warning messages off\n";
    // print_rdefaults()
    const ShadingOptions& sh = o.shading;
    const AmbientOptions& am = o.ambient;
    s += o.irradianceAtHit ? "-i+\t\t\t\t# irradiance calculation on\n"
                           : "-i-\t\t\t\t# irradiance calculation off\n";
    s += sh.uncorrelated ? "-u+\t\t\t\t# uncorrelated Monte Carlo sampling\n"
                         : "-u-\t\t\t\t# correlated quasi-Monte Carlo sampling\n";
    s += sh.backfaceVisible ? "-bv+\t\t\t\t# back face visibility on\n"
                            : "-bv-\t\t\t\t# back face visibility off\n";
    Appendf(s, "-dt %f\t\t\t# direct threshold\n", sh.direct.threshold);
    Appendf(s, "-dc %f\t\t\t# direct certainty\n", sh.direct.certainty);
    Appendf(s, "-dj %f\t\t\t# direct jitter\n", sh.direct.jitter);
    Appendf(s, "-ds %f\t\t\t# direct sampling\n", sh.direct.sampling);
    Appendf(s, "-dr %-9d\t\t\t# direct relays\n", sh.direct.relays);
    Appendf(s, "-dp %-9d\t\t\t# direct pretest density\n", sh.direct.pretest);
    s += sh.direct.sourcesVisible ? "-dv+\t\t\t\t# direct visibility on\n"
                                  : "-dv-\t\t\t\t# direct visibility off\n";
    Appendf(s, "-ss %f\t\t\t# specular sampling\n", sh.specular.sampling);
    Appendf(s, "-st %f\t\t\t# specular threshold\n", sh.specular.threshold);
    Appendf(s, "-av %f %f %f\t# ambient value\n", am.value.r, am.value.g, am.value.b);
    Appendf(s, "-aw %-9d\t\t\t# ambient value weight\n", am.valueWeight);
    Appendf(s, "-ab %-9d\t\t\t# ambient bounces\n", am.bounces);
    Appendf(s, "-aa %f\t\t\t# ambient accuracy\n", am.accuracy);
    Appendf(s, "-ar %-9d\t\t\t# ambient resolution\n", am.resolution);
    Appendf(s, "-ad %-9d\t\t\t# ambient divisions\n", am.divisions);
    Appendf(s, "-as %-9d\t\t\t# ambient super-samples\n", am.superSamples);
    const MediumOptions& me = sh.medium;
    Appendf(s, "-me %.2e %.2e %.2e\t# mist extinction coefficient\n", me.extinction.r,
            me.extinction.g, me.extinction.b);
    Appendf(s, "-ma %f %f %f\t# mist scattering albedo\n", me.albedo.r, me.albedo.g, me.albedo.b);
    Appendf(s, "-mg %f\t\t\t# mist scattering eccentricity\n", me.eccentricity);
    Appendf(s, "-ms %f\t\t\t# mist sampling distance\n", me.samplingDistance);
    Appendf(s, "-lr %-9d\t\t\t# limit reflection%s\n", sh.limits.reflections,
            sh.limits.reflections <= 0 ? " (Russian roulette)" : "");
    Appendf(s, "-lw %.2e\t\t\t# limit weight\n", sh.limits.weight);
    Appendf(s, "-am %.1f\t\t\t\t# max photon search radius\n", o.photonMaxRadius);
    return s;
}

}  // namespace rt
