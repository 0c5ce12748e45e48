// SPDX-License-Identifier: MIT
//
// Internal to scene/: what Radiance's two binary scene formats share, octree
// files (.oct, octree.h) and mesh files (.rtm, mesh_file.h). Both start with a
// text header, then use portio's big-endian integers and 5-byte reals
// (radiance-notes.md §5.3), %.12g cube strings, the same pre-order tree and
// the frozen-scene object section (radiance-notes.md §2.2 items 3, 6, 7;
// Radiance's readoct.c, readmesh.c, readobj.c). Every failure is an rt::Error
// "name: byte N: ..." naming the offset where the bad item starts.
#pragma once

#include <istream>
#include <string>
#include <utility>
#include <vector>

#include "core/function_ref.h"
#include "scene/scene.h"

namespace rt::detail {

inline constexpr int kMaxObjectSize = 8;  // readers accept object indices of 1 to 8 bytes

/// Lists of a file's objects are sized once from its object count: growing
/// them copies them over and over into fresh memory, and a large scene's
/// start-up is mostly first touches of memory. The count is the file's own
/// claim, so at most this many are reserved (address space: pages are
/// touched as objects arrive).
inline constexpr long long kMaxReservedObjects = 1LL << 22;

/// Reads with Radiance's portio conventions, counting bytes from the start of
/// the file for error messages. End of input inside an item is an error
/// "<truncated> (reading <what>)".
class RadianceBinaryReader {
public:
    /// `name` must outlive the reader. `offset` is the byte offset of the
    /// stream's current position in the file.
    RadianceBinaryReader(std::istream& in, const std::string& name, long long offset,
                         std::string truncated)
        : buf_(in.rdbuf()), name_(name), offset_(offset), truncated_(std::move(truncated)) {}

    [[noreturn]] void Fail(const std::string& what) const { Fail(offset_, what); }
    [[noreturn]] void Fail(long long at, const std::string& what) const;

    /// Inline: a frozen octree's reading is a call per byte (13 MB for a
    /// 110 000-polygon model), the end of input the rare case.
    int Byte(const char* what) {
        const int c = buf_->sbumpc();
        if (c == std::char_traits<char>::eof()) [[unlikely]] FailTruncated(what);
        ++offset_;
        return c;
    }
    /// getint(): `nbytes` (1..8) big-endian bytes, the first sign-extended.
    long long Int(int nbytes, const char* what);
    /// The same bytes as an unsigned number (mesh coordinates are uint32).
    unsigned long long Unsigned(int nbytes, const char* what);
    /// getflt(): a 5-byte portable real.
    double Real(const char* what);
    /// Bytes up to a NUL, without it.
    std::string String(const char* what);
    /// A header line up to '\n' (without it); false at the end of the stream.
    bool Line(std::string& line);

    long long offset() const { return offset_; }
    const std::string& name() const { return name_; }

private:
    [[noreturn]] void FailTruncated(const char* what) const;
    // Read through the stream's buffer: istream::get() builds a sentry per
    // byte, which made it most of a frozen octree's reading time.
    std::streambuf* buf_;
    const std::string& name_;
    long long offset_ = 0;
    std::string truncated_;
};

/// The information header after "#?RADIANCE": its lines up to the blank one.
struct RadianceHeader {
    std::vector<std::string> lines;  // without the FORMAT line
    std::string format;              // the value after "FORMAT=", "" if absent
    long long formatOffset = -1;     // byte offset of the FORMAT line
};

/// Reads the header through its blank line. Without `firstLineRead` the first
/// line must be "#?RADIANCE", else Fail(0, notRadiance + " (no #?RADIANCE
/// header)"). With `requiredFormat` a FORMAT line must be present and name it,
/// else notRadiance + " (FORMAT=...)" at that line or " (no FORMAT=... in the
/// header)"; without, any FORMAT (or none) is accepted. End of input before the
/// blank line fails with `truncatedHeader`.
RadianceHeader ReadRadianceHeader(RadianceBinaryReader& r, bool firstLineRead,
                                  const char* requiredFormat, const std::string& notRadiance,
                                  const std::string& truncatedHeader);

/// One of the four cube strings (%.12g): a finite number or Fail at its start.
double ReadCubeNumber(RadianceBinaryReader& r, const char* what);

struct LeafEntry {
    long long index;   // what the leaf lists: an object index or a mesh triangle ID
    long long offset;  // byte offset of its first listing in the file
};

/// Walks a pre-order tree (node byte 0 empty, 1 leaf with an objsize-byte
/// count and that many objsize-byte entries, 2 interior with 8 children)
/// without recursion, since a corrupt file may nest interior nodes
/// arbitrarily deep. Returns every listed entry once, ascending, with the
/// offset of its first listing. With `bound` >= 0 entries must lie in
/// [0, bound) and leaf sizes may not exceed it ("leaf object N out of range (M
/// objects)"); with `bound` < 0 entries must only be non-negative, and the
/// caller checks them against what they name.
std::vector<LeafEntry> ReadTreeLeaves(RadianceBinaryReader& r, int objsize, long long bound);

/// The frozen-scene object section: the type names up to an empty string,
/// then objects (type byte, objsize-byte modifier index among the objects of
/// this section before it, -1 = void, identifier, string and real arguments)
/// up to the type byte 0xFF. Appends to `objects` (which must start empty:
/// modifier indices count from its first element); each object's loc is
/// `name` and the byte offset of its type byte. With `maxObjects` >= 0 more
/// objects than that are an error.
void ReadObjectSection(RadianceBinaryReader& r, int objsize, long long maxObjects,
                       std::vector<SceneObject>& objects);

/// The same section, each object handed to `onObject` as soon as it is read
/// (which may take its strings) instead of being kept. Returns every object's
/// identifier, in order.
std::vector<std::string> ReadObjectSection(RadianceBinaryReader& r, int objsize,
                                           long long maxObjects,
                                           FunctionRef<void(SceneObject&)> onObject);

}  // namespace rt::detail
