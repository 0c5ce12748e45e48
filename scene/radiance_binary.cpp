// SPDX-License-Identifier: MIT
#include "scene/radiance_binary.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "core/error.h"
#include "core/portable.h"

namespace rt::detail {
namespace {

constexpr int kEndOfObjects = 0xFF;  // type byte after the section's last object

}  // namespace

void RadianceBinaryReader::Fail(long long at, const std::string& what) const {
    ThrowUserError(FileLoc{name_, 0, at}, what);
}

void RadianceBinaryReader::FailTruncated(const char* what) const {
    Fail(truncated_ + " (reading " + std::string(what) + ")");
}

long long RadianceBinaryReader::Int(int nbytes, const char* what) {
    std::uint8_t b[kMaxObjectSize];
    for (int i = 0; i < nbytes; ++i) b[i] = static_cast<std::uint8_t>(Byte(what));
    return GetPortableInt(b, static_cast<std::size_t>(nbytes));
}

unsigned long long RadianceBinaryReader::Unsigned(int nbytes, const char* what) {
    unsigned long long v = 0;
    for (int i = 0; i < nbytes; ++i) v = v << 8 | static_cast<unsigned>(Byte(what));
    return v;
}

double RadianceBinaryReader::Real(const char* what) {
    std::uint8_t b[kPortableFloatBytes];
    for (auto& x : b) x = static_cast<std::uint8_t>(Byte(what));
    return GetPortableFloat(b);
}

std::string RadianceBinaryReader::String(const char* what) {
    std::string s;
    for (int c = Byte(what); c != 0; c = Byte(what)) s.push_back(static_cast<char>(c));
    return s;
}

bool RadianceBinaryReader::Line(std::string& line) {
    line.clear();
    for (;;) {
        const int c = buf_->sbumpc();
        if (c == std::char_traits<char>::eof()) return !line.empty();
        ++offset_;
        if (c == '\n') return true;
        line.push_back(static_cast<char>(c));
    }
}

RadianceHeader ReadRadianceHeader(RadianceBinaryReader& r, bool firstLineRead,
                                  const char* requiredFormat, const std::string& notRadiance,
                                  const std::string& truncatedHeader) {
    RadianceHeader header;
    std::string line;
    if (!firstLineRead && (!r.Line(line) || line != "#?RADIANCE")) {
        r.Fail(0, notRadiance + " (no #?RADIANCE header)");
    }
    for (;;) {
        const long long at = r.offset();
        if (!r.Line(line)) r.Fail(truncatedHeader);
        if (line.empty()) break;
        if (line.rfind("FORMAT=", 0) == 0) {
            header.format = line.substr(sizeof("FORMAT=") - 1);
            header.formatOffset = at;
            if (requiredFormat != nullptr && header.format != requiredFormat) {
                r.Fail(at, notRadiance + " (" + line + ")");
            }
            continue;
        }
        header.lines.push_back(line);
    }
    if (requiredFormat != nullptr && header.formatOffset < 0) {
        r.Fail(notRadiance + " (no FORMAT=" + requiredFormat + " in the header)");
    }
    return header;
}

double ReadCubeNumber(RadianceBinaryReader& r, const char* what) {
    const long long at = r.offset();
    const std::string s = r.String(what);
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size() || errno == ERANGE || !std::isfinite(v)) {
        r.Fail(at, "bad " + std::string(what) + " '" + s + "'");
    }
    return v;
}

std::vector<LeafEntry> ReadTreeLeaves(RadianceBinaryReader& r, int objsize, long long bound) {
    // Each entry sits in many leaves. With a bound, the first listing of each
    // is kept in a table indexed by the entry; its size is capped, since the
    // bound is the file's own claim, and above the cap the list below is used.
    // Without (or beyond the cap), the list is cut back to unique entries
    // whenever it has doubled, so its memory follows the number of distinct
    // entries, not the size of the tree.
    constexpr long long kMaxTable = 1LL << 20;
    constexpr std::size_t kCompactSlack = 1 << 20;
    const bool tabled = bound >= 0 && bound <= kMaxTable;
    std::vector<long long> firstAt(tabled ? static_cast<std::size_t>(bound) : 0, -1);
    std::vector<LeafEntry> leaves;
    const auto compact = [&leaves] {
        std::sort(leaves.begin(), leaves.end(), [](const LeafEntry& a, const LeafEntry& b) {
            return a.index != b.index ? a.index < b.index : a.offset < b.offset;
        });
        leaves.erase(std::unique(leaves.begin(), leaves.end(),
                                 [](const LeafEntry& a, const LeafEntry& b) {
                                     return a.index == b.index;
                                 }),
                     leaves.end());
    };
    std::size_t compactAt = kCompactSlack;
    long long pending = 1;
    while (pending > 0) {
        --pending;
        const long long at = r.offset();
        switch (r.Byte("octree node")) {
            case 0: break;  // empty
            case 1: {
                const long long n = r.Int(objsize, "leaf size");
                if (n < 0 || (bound >= 0 && n > bound)) {
                    r.Fail(at, "bad leaf size " + std::to_string(n));
                }
                for (long long k = 0; k < n; ++k) {
                    const long long entryAt = r.offset();
                    const long long index = r.Int(objsize, "leaf object");
                    if (index < 0 || (bound >= 0 && index >= bound)) {
                        r.Fail(entryAt, bound >= 0 ? "leaf object " + std::to_string(index) +
                                                         " out of range (" +
                                                         std::to_string(bound) + " objects)"
                                                   : "bad leaf entry " + std::to_string(index));
                    }
                    if (tabled) {
                        long long& first = firstAt[static_cast<std::size_t>(index)];
                        if (first < 0) first = entryAt;
                        continue;
                    }
                    leaves.push_back({index, entryAt});
                    if (leaves.size() >= compactAt) {
                        compact();
                        compactAt = 2 * leaves.size() + kCompactSlack;
                    }
                }
                break;
            }
            case 2: pending += 8; break;
            default: r.Fail(at, "bad octree node type");
        }
    }
    if (tabled) {
        for (std::size_t i = 0; i < firstAt.size(); ++i) {
            if (firstAt[i] >= 0) leaves.push_back({static_cast<long long>(i), firstAt[i]});
        }
        return leaves;
    }
    compact();
    return leaves;
}

std::vector<std::string> ReadObjectSection(RadianceBinaryReader& r, int objsize,
                                           long long maxObjects,
                                           FunctionRef<void(SceneObject&)> onObject) {
    std::vector<std::string> types;
    for (std::string t = r.String("type name"); !t.empty(); t = r.String("type name")) {
        types.push_back(std::move(t));
    }
    // Modifiers are named by index among the objects before them.
    std::vector<std::string> names;
    if (maxObjects > 0) names.reserve(static_cast<std::size_t>(std::min(maxObjects, kMaxReservedObjects)));
    for (;;) {
        const long long at = r.offset();
        const int type = r.Byte("object type");
        if (type == kEndOfObjects) break;
        if (type >= static_cast<int>(types.size())) {
            r.Fail(at, "bad object type index " + std::to_string(type));
        }
        SceneObject o;
        o.loc = FileLoc{r.name(), 0, at};
        o.type = types[type];
        const long long self = static_cast<long long>(names.size());
        if (maxObjects >= 0 && self >= maxObjects) r.Fail(at, "more objects than the octree's count");
        const long long mod = r.Int(objsize, "modifier index");
        if (mod == -1) {
            o.modifier = "void";
        } else if (mod < 0 || mod >= self) {
            r.Fail(at, "bad modifier index " + std::to_string(mod));
        } else {
            o.modifier = names[static_cast<std::size_t>(mod)];
        }
        o.name = r.String("identifier");
        const long long ns = r.Int(2, "string argument count");
        if (ns < 0) r.Fail(at, "bad string argument count");
        for (long long k = 0; k < ns; ++k) o.sargs.push_back(r.String("string argument"));
        const long long nr = r.Int(2, "real argument count");
        if (nr < 0) r.Fail(at, "bad real argument count");
        o.rargs.reserve(static_cast<std::size_t>(nr));
        for (long long k = 0; k < nr; ++k) o.rargs.push_back(r.Real("real argument"));
        names.push_back(o.name);
        onObject(o);
    }
    return names;
}

void ReadObjectSection(RadianceBinaryReader& r, int objsize, long long maxObjects,
                       std::vector<SceneObject>& objects) {
    if (maxObjects > 0) {
        objects.reserve(static_cast<std::size_t>(std::min(maxObjects, kMaxReservedObjects)));
    }
    ReadObjectSection(r, objsize, maxObjects,
                      [&objects](SceneObject& o) { objects.push_back(std::move(o)); });
}

}  // namespace rt::detail
