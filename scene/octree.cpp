// SPDX-License-Identifier: MIT
#include "scene/octree.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "core/error.h"
#include "core/portable.h"
#include "scene/object_types.h"

namespace rt {
namespace {

// 283 + sizeof(OBJECT): the octree magic number (OCTMAGIC in Radiance).
constexpr long long kOctreeMagicBase = 283;
constexpr int kMaxObjectSize = 8;  // readers accept object indices of 1 to 8 bytes
constexpr int kEndOfObjects = 0xFF;  // type byte after a frozen octree's last object

/// Reads the binary part with Radiance's portio conventions, keeping the byte
/// offset for error messages.
class OctreeReader {
public:
    OctreeReader(std::istream& in, const std::string& name, long long offset)
        : in_(in), name_(name), offset_(offset) {}

    [[noreturn]] void Fail(const std::string& what) const { Fail(offset_, what); }
    [[noreturn]] void Fail(long long at, const std::string& what) const {
        ThrowUserError(FileLoc{name_, 0, at}, what);
    }

    int Byte(const char* what) {
        const int c = in_.get();
        if (c == std::char_traits<char>::eof()) Fail("truncated octree (reading " + std::string(what) + ")");
        ++offset_;
        return c;
    }

    long long Int(int nbytes, const char* what) {
        std::uint8_t b[kMaxObjectSize];
        for (int i = 0; i < nbytes; ++i) b[i] = static_cast<std::uint8_t>(Byte(what));
        return GetPortableInt(b, static_cast<std::size_t>(nbytes));
    }

    double Real(const char* what) {
        std::uint8_t b[kPortableFloatBytes];
        for (auto& x : b) x = static_cast<std::uint8_t>(Byte(what));
        return GetPortableFloat(b);
    }

    std::string String(const char* what) {
        std::string s;
        for (int c = Byte(what); c != 0; c = Byte(what)) s.push_back(static_cast<char>(c));
        return s;
    }

    /// A header line up to '\n' (without it); false at the end of the stream.
    bool Line(std::string& line) {
        line.clear();
        for (;;) {
            const int c = in_.get();
            if (c == std::char_traits<char>::eof()) return !line.empty();
            ++offset_;
            if (c == '\n') return true;
            line.push_back(static_cast<char>(c));
        }
    }

    long long offset() const { return offset_; }

private:
    std::istream& in_;
    const std::string& name_;
    long long offset_ = 0;
};

double ParseCubeNumber(OctreeReader& r, const char* what) {
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

void ReadHeader(OctreeReader& r, OctreeFile& oct, bool firstLineRead) {
    std::string line;
    if (!firstLineRead && (!r.Line(line) || line != "#?RADIANCE")) {
        r.Fail(0, "not a Radiance octree (no #?RADIANCE header)");
    }
    bool format = false;
    for (;;) {
        const long long at = r.offset();
        if (!r.Line(line)) r.Fail("truncated octree header");
        if (line.empty()) break;
        if (line.rfind("FORMAT=", 0) == 0) {
            if (line != "FORMAT=Radiance_octree") {
                r.Fail(at, "not a Radiance octree (" + line + ")");
            }
            format = true;
            continue;
        }
        oct.headerLines.push_back(line);
    }
    if (!format) r.Fail("not a Radiance octree (no FORMAT=Radiance_octree in the header)");
}

/// Walks the tree in pre-order without recursion (a corrupt file may nest
/// interior nodes arbitrarily deep), collecting the leaves' object indices.
void ReadTree(OctreeReader& r, OctreeFile& oct, int objsize) {
    constexpr std::size_t kCompactSlack = 1 << 20;
    std::size_t compactAt = kCompactSlack;
    long long pending = 1;
    while (pending > 0) {
        --pending;
        const long long at = r.offset();
        switch (r.Byte("octree node")) {
            case 0: break;  // empty
            case 1: {
                const long long n = r.Int(objsize, "leaf size");
                if (n < 0 || n > oct.objectCount) r.Fail(at, "bad leaf size " + std::to_string(n));
                for (long long k = 0; k < n; ++k) {
                    const long long index = r.Int(objsize, "leaf object");
                    if (index < 0 || index >= oct.objectCount) {
                        r.Fail(r.offset() - objsize, "leaf object " + std::to_string(index) +
                                                         " out of range (" +
                                                         std::to_string(oct.objectCount) +
                                                         " objects)");
                    }
                    oct.leafObjects.push_back(index);
                    if (oct.leafObjects.size() >= compactAt) {
                        // Each object sits in many leaves: keep the list to the
                        // unique indices so its memory follows the object count.
                        std::sort(oct.leafObjects.begin(), oct.leafObjects.end());
                        oct.leafObjects.erase(
                            std::unique(oct.leafObjects.begin(), oct.leafObjects.end()),
                            oct.leafObjects.end());
                        compactAt = 2 * oct.leafObjects.size() + kCompactSlack;
                    }
                }
                break;
            }
            case 2: pending += 8; break;
            default: r.Fail(at, "bad octree node type");
        }
    }
    std::sort(oct.leafObjects.begin(), oct.leafObjects.end());
    oct.leafObjects.erase(std::unique(oct.leafObjects.begin(), oct.leafObjects.end()),
                          oct.leafObjects.end());
}

void ReadFrozenScene(OctreeReader& r, OctreeFile& oct, int objsize, const std::string& name) {
    std::vector<std::string> types;
    for (std::string t = r.String("type name"); !t.empty(); t = r.String("type name")) {
        types.push_back(std::move(t));
    }
    for (;;) {
        const long long at = r.offset();
        const int type = r.Byte("object type");
        if (type == kEndOfObjects) break;
        if (type >= static_cast<int>(types.size())) {
            r.Fail(at, "bad object type index " + std::to_string(type));
        }
        SceneObject o;
        o.loc = FileLoc{name, 0, at};
        o.type = types[type];
        const long long self = static_cast<long long>(oct.objects.size());
        if (self >= oct.objectCount) r.Fail(at, "more objects than the octree's count");
        const long long mod = r.Int(objsize, "modifier index");
        if (mod == -1) {
            o.modifier = "void";
        } else if (mod < 0 || mod >= self) {
            r.Fail(at, "bad modifier index " + std::to_string(mod));
        } else {
            o.modifier = oct.objects[mod].name;
        }
        o.name = r.String("identifier");
        const long long ns = r.Int(2, "string argument count");
        if (ns < 0) r.Fail(at, "bad string argument count");
        for (long long k = 0; k < ns; ++k) o.sargs.push_back(r.String("string argument"));
        const long long nr = r.Int(2, "real argument count");
        if (nr < 0) r.Fail(at, "bad real argument count");
        for (long long k = 0; k < nr; ++k) o.rargs.push_back(r.Real("real argument"));
        oct.objects.push_back(std::move(o));
    }
    if (static_cast<long long>(oct.objects.size()) != oct.objectCount) {
        r.Fail("the octree holds " + std::to_string(oct.objects.size()) + " objects, its count says " +
               std::to_string(oct.objectCount));
    }
}

}  // namespace

bool LooksLikeOctree(std::istream& in) {
    const auto start = in.tellg();
    std::string line;
    bool octree = false;
    if (std::getline(in, line) && line == "#?RADIANCE") {
        // Header lines are short text; stop at the blank line or after a bound.
        for (int k = 0; k < 4096 && std::getline(in, line) && !line.empty(); ++k) {
            if (line.rfind("FORMAT=", 0) == 0) {
                octree = line == "FORMAT=Radiance_octree";
                break;
            }
        }
    }
    in.clear();
    in.seekg(start);
    return octree;
}

OctreeFile ReadOctree(std::istream& in, const std::string& name, bool firstLineRead) {
    OctreeReader r(in, name, firstLineRead ? sizeof("#?RADIANCE") : 0);
    OctreeFile oct;
    ReadHeader(r, oct, firstLineRead);
    const long long magicAt = r.offset();
    const long long magic = r.Int(2, "magic number");
    const long long objsize = magic - kOctreeMagicBase;
    if (objsize < 1 || objsize > kMaxObjectSize) r.Fail(magicAt, "bad octree magic number " + std::to_string(magic));
    const int size = static_cast<int>(objsize);
    oct.cubeOrigin.x = ParseCubeNumber(r, "cube origin");
    oct.cubeOrigin.y = ParseCubeNumber(r, "cube origin");
    oct.cubeOrigin.z = ParseCubeNumber(r, "cube origin");
    const long long sizeAt = r.offset();
    oct.cubeSize = ParseCubeNumber(r, "cube size");
    if (!(oct.cubeSize > 0)) r.Fail(sizeAt, "bad cube size");
    for (std::string f = r.String("scene file name"); !f.empty(); f = r.String("scene file name")) {
        oct.sceneFiles.push_back(std::move(f));
    }
    const long long countAt = r.offset();
    oct.objectCount = r.Int(size, "object count");
    if (oct.objectCount < 0) r.Fail(countAt, "bad object count");
    ReadTree(r, oct, size);
    if (oct.frozen()) ReadFrozenScene(r, oct, size, name);
    return oct;
}

void CheckOctreeObjects(const OctreeFile& octree, const std::vector<SceneObject>& objects,
                        const std::string& name) {
    if (static_cast<long long>(objects.size()) != octree.objectCount) {
        ThrowUserError(name + ": bad object count; octree stale? (" +
                       std::to_string(objects.size()) + " objects in its scene files, " +
                       std::to_string(octree.objectCount) + " in the octree)");
    }
    for (const long long index : octree.leafObjects) {
        if (!IsSurfaceObjectType(objects[index].type)) {
            ThrowUserError(name + ": modifier in tree; octree stale? (object " +
                           std::to_string(index) + ", \"" + objects[index].name + "\")");
        }
    }
}

}  // namespace rt
