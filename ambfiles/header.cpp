// SPDX-License-Identifier: MIT
#include "ambfiles/header.h"

#include <cctype>
#include <cstdio>
#include <string_view>

#include "core/portable.h"
#include "ambfiles/record_codec.h"

namespace rt {
namespace {

// printf("%g") / ("%d") as Radiance's fprintf does.
std::string G(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

std::string DateLine(const char* label, const std::tm& t) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s %04d:%02d:%02d %02d:%02d:%02d\n", label, t.tm_year + 1900,
                  t.tm_mon + 1, t.tm_mday, t.tm_hour, t.tm_min, t.tm_sec);
    return buf;
}

}  // namespace

// formatval(): "FORMAT=" then optional spaces, then the value up to white space.
std::optional<std::string> HeaderFormatValue(std::string_view line) {
    constexpr std::string_view kTag = "FORMAT=";
    if (line.substr(0, kTag.size()) != kTag) return std::nullopt;
    std::size_t i = kTag.size();
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    std::size_t j = i;
    while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j]))) ++j;
    if (i == j) return std::nullopt;  // "FORMAT=" with nothing after it is not a format line
    return std::string(line.substr(i, j - i));
}

std::string FormatAmbientHeader(const AmbientHeaderParams& p) {
    std::string s = "#?RADIANCE\n";
    s += p.programName + " -av " + G(p.ambientValue.r) + " " + G(p.ambientValue.g) + " " +
         G(p.ambientValue.b) + " -aw " + std::to_string(p.valueWeight) + " -ab " +
         std::to_string(p.bounces) + " -aa " + G(p.accuracy) + " ";
    s += "-ad " + std::to_string(p.divisions) + " -as " + std::to_string(p.superSamples) +
         " -ar " + std::to_string(p.resolution) + " ";
    s += p.octreeName + "\n";
    s += "SOFTWARE= " + p.software + "\n";
    if (p.captureTime) {
        std::tm local{}, gmt{};
        if (localtime_r(&*p.captureTime, &local)) s += DateLine("CAPDATE=", local);
        if (gmtime_r(&*p.captureTime, &gmt)) s += DateLine("GMT=", gmt);
    }
    s += "FORMAT=" + std::string(kAmbientFormat) + "\n\n";
    std::uint8_t magic[kAmbientMagicBytes];
    PutPortableInt(kAmbientMagic, kAmbientMagicBytes, magic);
    s.append(reinterpret_cast<const char*>(magic), kAmbientMagicBytes);
    return s;
}

HeaderParse ParseAmbientHeader(std::span<const std::uint8_t> bytes) {
    HeaderParse result;
    if (bytes.empty()) {
        result.problem = "empty file";
        return result;
    }
    if (bytes.size() < 2 || bytes[0] != '#' || bytes[1] != '?') {
        result.problem = "no Radiance header (file does not start with \"#?\")";
        return result;
    }
    ParsedAmbientHeader header;
    std::size_t pos = 0;
    for (;;) {
        std::size_t end = pos;
        while (end < bytes.size() && bytes[end] != '\n') ++end;
        if (end == bytes.size()) {
            result.problem = "header not terminated by a blank line";
            return result;
        }
        std::string_view line(reinterpret_cast<const char*>(bytes.data()) + pos, end - pos);
        pos = end + 1;
        if (line.empty() || line == "\r") break;  // end of header
        if (auto fmt = HeaderFormatValue(line)) {
            if (*fmt != kAmbientFormat) {
                result.problem = "FORMAT=" + *fmt + " is not " + std::string(kAmbientFormat);
                return result;
            }
            header.format = *fmt;
        }
        header.lines.emplace_back(line);
    }
    if (bytes.size() - pos < kAmbientMagicBytes) {
        result.problem = "missing magic number after the header";
        return result;
    }
    if (GetPortableInt(&bytes[pos], kAmbientMagicBytes) != kAmbientMagic) {
        result.problem = "wrong magic number " +
                         std::to_string(GetPortableInt(&bytes[pos], kAmbientMagicBytes)) +
                         " (Radiance 5 ambient files have " + std::to_string(kAmbientMagic) +
                         "; 557 is the pre-5.0 format)";
        return result;
    }
    header.recordsOffset = pos + kAmbientMagicBytes;
    result.header = std::move(header);
    return result;
}

}  // namespace rt
