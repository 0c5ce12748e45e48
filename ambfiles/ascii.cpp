// SPDX-License-Identifier: MIT
#include "ambfiles/ascii.h"

#include <cctype>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <optional>

namespace rt {
namespace {

void Append(std::string& out, const char* fmt, ...) __attribute__((format(printf, 2, 3)));
void Append(std::string& out, const char* fmt, ...) {
    char buf[512];
    va_list args;
    va_start(args, fmt);
    const int n = std::vsnprintf(buf, sizeof buf, fmt, args);
    va_end(args);
    if (n > 0) out.append(buf, static_cast<std::size_t>(n) < sizeof buf ? n : sizeof buf - 1);
}

// White-space separated words, consumed in order (fscanf's view of the input).
class Words {
public:
    explicit Words(std::string_view text) : text_(text) {}

    std::optional<std::string_view> Next() {
        while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) {
            ++pos_;
        }
        if (pos_ == text_.size()) return std::nullopt;
        const std::size_t start = pos_;
        while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) {
            ++pos_;
        }
        return text_.substr(start, pos_ - start);
    }

    // A number filling the whole word; strtod/strtoul accept what %f / %u / %X do.
    std::optional<double> Real() {
        auto w = Next();
        if (!w) return std::nullopt;
        const std::string s(*w);
        char* end = nullptr;
        const double v = std::strtod(s.c_str(), &end);
        if (end == s.c_str() || *end != '\0') return std::nullopt;
        return v;
    }
    std::optional<float> Float() {
        auto v = Real();
        if (!v) return std::nullopt;
        return static_cast<float>(*v);
    }
    std::optional<unsigned long> Unsigned(int base) {
        auto w = Next();
        if (!w) return std::nullopt;
        const std::string s(*w);
        char* end = nullptr;
        const unsigned long v = std::strtoul(s.c_str(), &end, base);
        if (end == s.c_str() || *end != '\0') return std::nullopt;
        return v;
    }
    std::optional<long> Int() {
        auto w = Next();
        if (!w) return std::nullopt;
        const std::string s(*w);
        char* end = nullptr;
        const long v = std::strtol(s.c_str(), &end, 10);
        if (end == s.c_str() || *end != '\0') return std::nullopt;
        return v;
    }

private:
    std::string_view text_;
    std::size_t pos_ = 0;
};

std::optional<AmbientRecord> ParseOne(Words& in, bool labelled) {
    auto label = [&] { return !labelled || in.Next().has_value(); };
    AmbientRecord r;
    if (!label()) return std::nullopt;
    for (int i = 0; i < 3; ++i) {
        auto v = in.Float();
        if (!v) return std::nullopt;
        r.position[i] = *v;
    }
    for (Vec3* dir : {&r.normal, &r.uAxis}) {
        if (!label()) return std::nullopt;
        for (int i = 0; i < 3; ++i) {
            auto v = in.Real();  // FVECT is double in Radiance
            if (!v) return std::nullopt;
            (*dir)[i] = *v;
        }
    }
    if (!label()) return std::nullopt;
    auto lvl = in.Int();
    auto weight = in.Float();
    auto rad0 = in.Float();
    auto rad1 = in.Float();
    if (!lvl || !weight || !rad0 || !rad1) return std::nullopt;
    r.level = static_cast<int>(*lvl);
    r.weight = *weight;
    r.radius[0] = *rad0;
    r.radius[1] = *rad1;
    if (!label()) return std::nullopt;
    for (int i = 0; i < 3; ++i) {
        auto v = in.Float();
        if (!v) return std::nullopt;
        r.value[i] = *v;
    }
    for (double* grad : {r.posGradient, r.dirGradient}) {
        if (!label()) return std::nullopt;
        for (int i = 0; i < 2; ++i) {
            auto v = in.Float();
            if (!v) return std::nullopt;
            grad[i] = *v;
        }
    }
    if (!label()) return std::nullopt;
    auto corral = in.Unsigned(labelled ? 16 : 10);  // printed %8X / %u
    if (!corral) return std::nullopt;
    r.corral = static_cast<std::uint32_t>(*corral);
    return r;
}

}  // namespace

std::string FormatAmbientText(const AmbientRecord& r, AmbientTextLayout layout) {
    std::string s;
    const Vec3& p = r.position;
    const Vec3& n = r.normal;
    const Vec3& u = r.uAxis;
    if (layout == AmbientTextLayout::DataOnly) {
        Append(s, "%f\t%f\t%f\t", p.x, p.y, p.z);
        Append(s, "%f\t%f\t%f\t", n.x, n.y, n.z);
        Append(s, "%f\t%f\t%f\t", u.x, u.y, u.z);
        Append(s, "%d\t%f\t%f\t%f\t", r.level, r.weight, r.radius[0], r.radius[1]);
        Append(s, "%e\t%e\t%e\t", r.value.r, r.value.g, r.value.b);
        Append(s, "%f\t%f\t", r.posGradient[0], r.posGradient[1]);
        Append(s, "%f\t%f\t", r.dirGradient[0], r.dirGradient[1]);
        Append(s, "%u\n", r.corral);
    } else {
        Append(s, "Position:\t%f\t%f\t%f\n", p.x, p.y, p.z);
        Append(s, "Normal:\t\t%f\t%f\t%f\n", n.x, n.y, n.z);
        Append(s, "Uvector:\t%f\t%f\t%f\n", u.x, u.y, u.z);
        Append(s, "Lvl,Wt,UVrad:\t%d\t\t%f\t%f\t%f\n", r.level, r.weight, r.radius[0],
               r.radius[1]);
        Append(s, "Value:\t\t%e\t%e\t%e\n", r.value.r, r.value.g, r.value.b);
        Append(s, "Pos.Grad:\t%f\t%f\n", r.posGradient[0], r.posGradient[1]);
        Append(s, "Dir.Grad:\t%f\t%f\n", r.dirGradient[0], r.dirGradient[1]);
        Append(s, "Corral:\t\t%8X\n\n", r.corral);
    }
    return s;
}

std::vector<AmbientRecord> ParseAmbientText(std::string_view text, AmbientTextLayout layout) {
    std::vector<AmbientRecord> records;
    Words in(text);
    while (auto r = ParseOne(in, layout == AmbientTextLayout::Labelled)) records.push_back(*r);
    return records;
}

}  // namespace rt
