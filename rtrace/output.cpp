// SPDX-License-Identifier: MIT
#include "rtrace/output.h"

#include <charconv>
#include <cmath>
#include <cstring>

#include "core/conventions.h"
#include "core/error.h"
#include "core/quote.h"

namespace rt {
namespace {

// Output is handed to the stream in pieces of about this size.
constexpr std::size_t kDrainBytes = 1 << 16;

enum class FieldKind { Vector3, Scalar, Pair, String, Tilde, Unknown };

struct LetterInfo {
    FieldKind kind;
    bool needsShading;  // Radiance clears castonly for these
};

LetterInfo Letter(char c) {
    switch (c) {
        case 'o': case 'd': case 'p': case 'N':
            return {FieldKind::Vector3, false};
        case 'v': case 'V': case 'W': case 'n': case 'r': case 'x':
            return {FieldKind::Vector3, true};
        case 'w': case 'L':
            return {FieldKind::Scalar, false};
        case 'l': case 'R': case 'X':
            return {FieldKind::Scalar, true};
        case 'c':
            return {FieldKind::Pair, false};
        case 's': case 'm': case 'M':
            return {FieldKind::String, false};
        case '~':
            return {FieldKind::Tilde, false};
    }
    return {FieldKind::Unknown, false};
}

int Components(FieldKind k) {
    switch (k) {
        case FieldKind::Vector3: return 3;
        case FieldKind::Scalar: return 1;
        case FieldKind::Pair: return 2;
        case FieldKind::String: return 1;  // Radiance counts a string as one component
        default: return 0;
    }
}

std::string FormatTime(const std::tm& t) {
    char buf[64];
    std::strftime(buf, sizeof buf, "%Y:%m:%d %H:%M:%S", &t);
    return buf;
}

}  // namespace

OutputSpec ParseOutputSpec(const RtraceOptions& options, const WarningSink& warn) {
    const std::string& vs = options.outputSpec;
    if (vs.empty()) ThrowUserError("empty output specification");
    const bool irradiance = options.shading.irradiance != IrradianceMode::Off;
    const AmbientOptions& amb = options.ambient;
    const bool accuracyWarning =
        amb.bounces > 0 && (amb.accuracy > kFtiny || amb.superSamples > 0);

    OutputSpec spec;
    std::string* table = &spec.fields;
    int components = 0;
    for (std::size_t i = 0; i < vs.size(); ++i) {
        char c = vs[i];
        if (c == 't' || c == 'T') {
            // Radiance follows shadow rays for any T, a trailing one too
            // (-ovtLT traces them); a trailing t/T adds nothing else.
            if (c == 'T') spec.traceShadows = true;
            if (i + 1 == vs.size()) break;
            // Each t/T starts the trace list again (rtrace.c's setrtoutput()):
            // -ovtLtm traces m alone.
            table = &spec.traceFields;
            table->clear();
            spec.trace = true;
            spec.castOnly = false;
            continue;
        }
        LetterInfo info = Letter(c);
        if (info.kind == FieldKind::Unknown)
            ThrowUserError(std::string("unrecognized output option '") + c + "'");
        *table += c;
        components += Components(info.kind);
        if (info.needsShading) spec.castOnly = false;
        if ((c == 'V' || c == 'W') && accuracyWarning)
            warn(std::string("-ot") + c + " accuracy depends on -aa 0 -as 0");
    }
    if (!spec.trace) spec.traceShadows = false;
    // Radiance counts the components of every letter, the trace list's
    // included, and gives no NCOMP when trace lines have fields: -ovtt has
    // NCOMP=3, and -ovtLtt, whose second t empties the list, NCOMP=4.
    spec.components = spec.traceFields.empty() ? components : 0;
    if (irradiance && spec.castOnly) ThrowUserError("-I+ and -i+ options require some value output");
    for (char c : spec.fields) {
        if (c == 'V' || c == 'W') warn("-oVW options require trace mode");
        if (irradiance && std::strchr("rRxX", c))
            warn("-orRxX options incompatible with -I+ and -i+");
    }
    // Last, as Radiance checks it in rtrace() after setrtoutput() has
    // refused unknown letters and given its warnings.
    if (options.outputFormat == 'c' && (vs.size() != 1 || std::strchr("vrx", vs[0]) == nullptr))
        ThrowUserError("color format only with -ov, -or, -ox");
    return spec;
}

RecordWriter::RecordWriter(char format, std::ostream& out) : format_(format), out_(out) {
    buffer_.reserve(kDrainBytes + 4096);
}

RecordWriter::~RecordWriter() { Drain(); }

void RecordWriter::Drain() {
    if (buffer_.empty()) return;
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
}

bool RecordWriter::Flush() {
    Drain();
    out_.flush();
    return static_cast<bool>(out_);
}

void RecordWriter::WriteText(std::string_view text) {
    buffer_ += text;
    if (buffer_.size() >= kDrainBytes) Drain();
}

void RecordWriter::PutReals(std::span<const double> values) {
    switch (format_) {
        case 'f':
            for (double v : values) {
                float f = static_cast<float>(v);
                buffer_.append(reinterpret_cast<const char*>(&f), sizeof f);
            }
            break;
        case 'd':
            for (double v : values) buffer_.append(reinterpret_cast<const char*>(&v), sizeof v);
            break;
        default: {
            // printf("%e\t") for each value; to_chars gives the same digits
            // without locale or stdio overhead.
            char buf[64];
            for (double v : values) {
                auto res = std::to_chars(buf, buf + sizeof buf - 1, v, std::chars_format::scientific, 6);
                *res.ptr++ = '\t';
                buffer_.append(buf, res.ptr);
            }
        }
    }
}

void RecordWriter::PutRgb(const Rgb& c) {
    if (format_ == 'c') {
        auto px = EncodeRgbe(c);
        buffer_.append(reinterpret_cast<const char*>(px.data()), px.size());
        return;
    }
    const double v[3] = {c.r, c.g, c.b};
    PutReals(v);
}

void RecordWriter::PutString(std::string_view s) {
    buffer_ += s;
    buffer_ += '\t';
}

void RecordWriter::WriteFields(std::string_view letters, const RayResult& r) {
    auto vec = [this](const Vec3& v) {
        const double a[3] = {v.x, v.y, v.z};
        PutReals(a);
    };
    auto scalar = [this](double v) { PutReals(std::span<const double>(&v, 1)); };
    for (char c : letters) {
        switch (c) {
            case 'o': vec(r.origin); break;
            case 'd': vec(r.direction); break;
            case 'v': PutRgb(r.value); break;
            case 'V': PutRgb(r.contribution); break;
            case 'W': PutRgb(r.coefficient); break;
            case 'r': PutRgb(r.mirrored); break;
            case 'x': PutRgb(r.value - r.mirrored); break;
            case 'w': scalar(r.weight); break;
            case 'l': scalar(r.EffectiveLength()); break;
            case 'L': scalar(r.firstLength); break;
            case 'R': scalar(r.mirrorLength); break;
            case 'X': scalar(r.unmirroredLength); break;
            case 'c': {
                const double uv[2] = {r.u, r.v};
                PutReals(uv);
                break;
            }
            case 'p': vec(r.point); break;
            case 'n': vec(r.normal); break;
            case 'N': vec(r.geometricNormal); break;
            case 's': PutString(r.surfaceName); break;
            case 'm': PutString(r.modifierName); break;
            case 'M': PutString(r.materialName); break;
            case '~': buffer_ += "~\t"; break;
            default: break;  // ParseOutputSpec admits nothing else
        }
    }
}

void RecordWriter::WriteRecord(std::string_view letters, const RayResult& r) {
    if (letters.empty()) return;  // printvals() prints nothing, not even "\n"
    WriteFields(letters, r);
    if (format_ == 'a') buffer_ += '\n';
    if (buffer_.size() >= kDrainBytes) Drain();
}

void RecordWriter::WriteTraceRecord(std::string_view letters, const RayResult& r) {
    if (letters.empty()) return;
    buffer_.append(static_cast<std::size_t>(std::max(r.depth, 0)), '\t');
    WriteFields(letters, r);
    if (format_ == 'a') buffer_ += '\n';
    if (buffer_.size() >= kDrainBytes) Drain();
}

std::string FormatHeader(std::span<const std::string> commandLine, const OutputSpec& spec,
                         char outputFormat, std::time_t now,
                         std::span<const std::string> sceneHeader) {
    std::string h = "#?RADIANCE\n";
    for (const std::string& line : sceneHeader) {
        h += line;
        h += '\n';
    }
    h += QuoteWords(commandLine);
    h += '\n';
    h += "SOFTWARE= ";
    h += kVersionString;
    h += '\n';
    std::tm local{}, utc{};
    localtime_r(&now, &local);
    gmtime_r(&now, &utc);
    h += "CAPDATE= " + FormatTime(local) + "\n";
    h += "GMT= " + FormatTime(utc) + "\n";
    if (spec.components > 0) h += "NCOMP=" + std::to_string(spec.components) + "\n";
    if (outputFormat == 'f' || outputFormat == 'd') {
        const std::uint16_t probe = 1;
        std::uint8_t first = 0;
        std::memcpy(&first, &probe, 1);
        h += first ? "BigEndian=0\n" : "BigEndian=1\n";
    }
    h += "FORMAT=";
    h += FormatName(outputFormat);
    h += "\n\n";
    return h;
}

std::string FormatResolution(int x, int y) {
    return "-Y " + std::to_string(y) + " +X " + std::to_string(x) + "\n";
}

}  // namespace rt
