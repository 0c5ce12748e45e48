// SPDX-License-Identifier: MIT
#include "ambfiles/shared_file.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <arpa/inet.h>
#include <fcntl.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <thread>

#include "ambfiles/record_codec.h"
#include "core/error.h"
#include "tests/ambfiles/test_util.h"

namespace rt {
namespace {

using testing::DataPath;
using testing::ReadBytes;
using testing::TempDir;

// ---------------------------------------------------------------------------------
// An independent reader written from radiance-notes.md §5 alone (it shares no code
// with ambfiles/): checks that what SharedAmbientFile writes is a Radiance file.
struct SpecRecord {
    int lvl;
    double weight, pos[3], rad[2], gpos[2], gdir[2], val[3];
    std::uint32_t ndir, udir, corral;
    bool valid;
};

struct SpecFile {
    bool ok = false;
    std::size_t recordsAt = 0;
    std::size_t trailing = 0;  // bytes after the last whole record
    std::vector<SpecRecord> records;
};

double SpecFloat(const std::uint8_t* p) {
    std::int32_t m;
    std::uint32_t be;
    std::memcpy(&be, p, 4);
    const std::uint32_t host = ntohl(be);
    std::memcpy(&m, &host, 4);
    const auto e = static_cast<std::int8_t>(p[4]);
    if (m == 0) return 0;
    return std::ldexp((m + (m > 0 ? 0.5 : -0.5)) / 2147483647.0, e);
}

std::uint32_t SpecU32(const std::uint8_t* p) {
    std::uint32_t be;
    std::memcpy(&be, p, 4);
    return ntohl(be);
}

SpecFile SpecRead(const std::vector<std::uint8_t>& f) {
    SpecFile out;
    const std::string text(f.begin(), f.end());
    if (text.rfind("#?", 0) != 0) return out;
    const std::size_t blank = text.find("\n\n");
    if (blank == std::string::npos || blank + 4 > f.size()) return out;
    if (f[blank + 2] != 0x02 || f[blank + 3] != 0x2F) return out;  // 559
    out.ok = true;
    out.recordsAt = blank + 4;
    std::size_t p = out.recordsAt;
    for (; f.size() - p >= 67; p += 67) {
        const std::uint8_t* r = &f[p];
        SpecRecord s{};
        s.lvl = r[0];
        s.weight = static_cast<float>(SpecFloat(r + 1));
        for (int i = 0; i < 3; ++i) s.pos[i] = static_cast<float>(SpecFloat(r + 6 + 5 * i));
        s.ndir = SpecU32(r + 21);
        s.udir = SpecU32(r + 25);
        for (int i = 0; i < 3; ++i) {
            s.val[i] = r[32] == 0 ? 0.0 : (r[29 + i] + 0.5) * std::ldexp(1.0, r[32] - 136);
        }
        for (int i = 0; i < 2; ++i) {
            s.rad[i] = static_cast<float>(SpecFloat(r + 33 + 5 * i));
            s.gpos[i] = static_cast<float>(SpecFloat(r + 43 + 5 * i));
            s.gdir[i] = static_cast<float>(SpecFloat(r + 53 + 5 * i));
        }
        s.corral = SpecU32(r + 63);
        auto in = [](double x) { return x >= -1e10 && x <= 1e10; };
        s.valid = in(s.pos[0]) && in(s.pos[1]) && in(s.pos[2]) && s.ndir != 0 && s.udir != 0 &&
                  s.weight > 0 && s.weight <= 1 && s.rad[0] > 0 && s.rad[0] < 1e10 &&
                  s.rad[1] > 0 && s.rad[1] < 1e10 && s.val[0] >= 0 && s.val[0] < 1e10 &&
                  s.val[1] >= 0 && s.val[1] < 1e10 && s.val[2] >= 0 && s.val[2] < 1e10 &&
                  in(s.gpos[0]) && in(s.gpos[1]) && in(s.gdir[0]) && in(s.gdir[1]);
        out.records.push_back(s);
    }
    out.trailing = f.size() - p;
    return out;
}

// Spec decode of a direction code (§5.5 table), for the independent check.
void SpecDir(std::uint32_t c, double v[3]) {
    const double k = 11584.5;
    const double d1 = ((c >> 5) & 0x1fff) / k, d2 = ((c >> 18) & 0x1fff) / k;
    const double d3 = std::sqrt(1 - d1 * d1 - d2 * d2);
    const bool f2z = c & 0x10, f1x = c & 0x08;
    if (!f2z && !f1x) { v[0] = d2; v[1] = d1; v[2] = d3; }
    if (!f2z && f1x) { v[0] = d1; v[1] = d2; v[2] = d3; }
    if (f2z && !f1x) { v[0] = d3; v[1] = d1; v[2] = d2; }
    if (f2z && f1x) { v[0] = d1; v[1] = d3; v[2] = d2; }
    for (int i = 0; i < 3; ++i) {
        if (c & (1u << i)) v[i] = -v[i];
    }
}

// ---------------------------------------------------------------------------------

AmbientHeaderParams Params() {
    AmbientHeaderParams p;
    p.bounces = 1;
    p.octreeName = "test.oct";
    p.software = "lazyrad ambfiles_test";
    return p;
}

/// A valid record that carries an id in its position (x = writer, y = sequence).
AmbientRecord Tagged(int writer, int seq) {
    AmbientRecord r;
    r.position = {static_cast<double>(writer), static_cast<double>(seq), 0.25};
    r.normal = Normalize(Vec3(0.1 * writer, -0.3, 1));
    r.uAxis = Normalize(Cross(Vec3(1, 0, 0), r.normal));
    r.value = Rgb(0.25, 0.5, 0.125 + 0.001 * seq);
    r.radius[0] = 0.5;
    r.radius[1] = 0.75;
    r.posGradient[0] = -0.125;
    r.dirGradient[1] = 0.5;
    r.level = writer % 3;
    r.weight = 0.5;
    r.corral = static_cast<std::uint32_t>(seq);
    return r;
}

std::int64_t IdOf(const AmbientRecord& r) {
    return static_cast<std::int64_t>(r.position.x) * 1000000 + static_cast<std::int64_t>(r.position.y);
}

struct Warnings {
    std::vector<std::string> messages;
    WarningSink Sink() {
        return [this](const std::string& m) { messages.push_back(m); };
    }
};

std::int64_t SizeOf(const std::string& path) {
    struct stat st {};
    return stat(path.c_str(), &st) == 0 ? static_cast<std::int64_t>(st.st_size) : -1;
}

TEST(SharedAmbientFile, NewFileGetsHeaderAndRecordsRoundTrip) {
    TempDir dir;
    const std::string path = dir.File("new.amb");
    Warnings w;
    std::vector<AmbientRecord> ours;
    {
        SharedAmbientFile f(path, Params(), w.Sink());
        EXPECT_TRUE(f.LoadAll().empty());
        const std::string header = FormatAmbientHeader(Params());
        EXPECT_EQ(SizeOf(path), static_cast<std::int64_t>(header.size()));
        for (int i = 0; i < 5; ++i) ours.push_back(Tagged(1, i));
        EXPECT_TRUE(f.Sync(ours).empty());  // never our own records back
        EXPECT_TRUE(f.Sync({}).empty());
        EXPECT_EQ(f.EndOffset(), SizeOf(path));
    }
    EXPECT_TRUE(w.messages.empty());
    SharedAmbientFile again(path, Params(), w.Sink());
    const auto loaded = again.LoadAll();
    ASSERT_EQ(loaded.size(), ours.size());
    for (std::size_t i = 0; i < ours.size(); ++i) {
        EXPECT_EQ(loaded[i], *DecodeRecord(EncodeRecord(ours[i])));
    }
}

TEST(SharedAmbientFile, IndependentReaderAcceptsWhatWeWrite) {
    TempDir dir;
    const std::string path = dir.File("spec.amb");
    std::vector<AmbientRecord> ours;
    for (int i = 0; i < 40; ++i) ours.push_back(Tagged(3, i));
    {
        SharedAmbientFile f(path, Params(), {});
        (void)f.LoadAll();
        (void)f.Sync(ours);
    }
    const SpecFile spec = SpecRead(ReadBytes(path));
    ASSERT_TRUE(spec.ok);
    EXPECT_EQ(spec.trailing, 0u);
    ASSERT_EQ(spec.records.size(), ours.size());
    for (std::size_t i = 0; i < ours.size(); ++i) {
        const SpecRecord& s = spec.records[i];
        const AmbientRecord& r = ours[i];
        EXPECT_TRUE(s.valid);
        EXPECT_EQ(s.lvl, r.level);
        EXPECT_EQ(s.weight, 0.5);
        for (int k = 0; k < 3; ++k) EXPECT_EQ(s.pos[k], static_cast<float>(r.position[k]));
        double n[3], u[3];
        SpecDir(s.ndir, n);
        SpecDir(s.udir, u);
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(n[k], r.normal[k], 2e-4);
            EXPECT_NEAR(u[k], r.uAxis[k], 2e-4);
            // 8-bit mantissa relative to the largest channel (0.5 here).
            EXPECT_NEAR(s.val[k], r.value[k], Intens(r.value) / 128);
        }
        EXPECT_EQ(s.rad[0], 0.5);
        EXPECT_EQ(s.rad[1], 0.75);
        EXPECT_EQ(s.gpos[0], -0.125);
        EXPECT_EQ(s.gdir[1], 0.5);
        EXPECT_EQ(s.corral, r.corral);
    }
}

TEST(SharedAmbientFile, LoadsRadianceFileAndAppendsToIt) {
    TempDir dir;
    const std::string path = dir.File("cornell.amb");
    testing::WriteBytes(path, ReadBytes(DataPath("cornell_radiance54.amb")));
    Warnings w;
    SharedAmbientFile f(path, Params(), w.Sink());
    EXPECT_EQ(f.LoadAll().size(), testing::kRadianceRecordCount);
    (void)f.Sync(std::vector<AmbientRecord>{Tagged(0, 1), Tagged(0, 2)});
    EXPECT_TRUE(w.messages.empty());
    const SpecFile spec = SpecRead(ReadBytes(path));
    EXPECT_EQ(spec.records.size(), testing::kRadianceRecordCount + 2);
    EXPECT_EQ(spec.trailing, 0u);
}

TEST(SharedAmbientFile, TwoHandlesSeeEachOthersRecordsAtSync) {
    TempDir dir;
    const std::string path = dir.File("two.amb");
    SharedAmbientFile a(path, Params(), {});
    SharedAmbientFile b(path, Params(), {});
    EXPECT_TRUE(a.LoadAll().empty());
    EXPECT_TRUE(b.LoadAll().empty());
    EXPECT_TRUE(a.Sync(std::vector<AmbientRecord>{Tagged(1, 0), Tagged(1, 1)}).empty());
    const auto seenByB = b.Sync(std::vector<AmbientRecord>{Tagged(2, 0)});
    ASSERT_EQ(seenByB.size(), 2u);
    EXPECT_EQ(IdOf(seenByB[1]), 1000001);
    const auto seenByA = a.Sync({});
    ASSERT_EQ(seenByA.size(), 1u);
    EXPECT_EQ(IdOf(seenByA[0]), 2000000);
}

TEST(SharedAmbientFile, TruncatedTailIsCutWithWarningAndAppendingContinues) {
    TempDir dir;
    const std::string path = dir.File("tail.amb");
    testing::WriteBytes(path, ReadBytes(DataPath("bad_truncated_tail.amb")));
    Warnings w;
    SharedAmbientFile f(path, Params(), w.Sink());
    const auto loaded = f.LoadAll();
    EXPECT_EQ(loaded.size(), testing::kRadianceRecordCount - 1);
    const std::int64_t boundary = 219 + 3428 * 67;  // 229895
    ASSERT_EQ(w.messages.size(), 1u);
    EXPECT_NE(w.messages[0].find("byte 229895"), std::string::npos) << w.messages[0];
    EXPECT_NE(w.messages[0].find(path), std::string::npos) << w.messages[0];
    EXPECT_EQ(SizeOf(path), boundary);
    (void)f.Sync(std::vector<AmbientRecord>{Tagged(4, 0), Tagged(4, 1), Tagged(4, 2)});
    const SpecFile spec = SpecRead(ReadBytes(path));
    EXPECT_EQ(spec.trailing, 0u);
    ASSERT_EQ(spec.records.size(), 3431u);
    for (const SpecRecord& s : spec.records) EXPECT_TRUE(s.valid);
    Warnings w2;
    SharedAmbientFile g(path, Params(), w2.Sink());
    EXPECT_EQ(g.LoadAll().size(), 3431u);
    EXPECT_TRUE(w2.messages.empty());
}

TEST(SharedAmbientFile, GarbageRecordStopsReadingAndNothingIsAppended) {
    TempDir dir;
    const std::string path = dir.File("garbage.amb");
    const auto original = ReadBytes(DataPath("bad_garbage_record.amb"));
    testing::WriteBytes(path, original);
    Warnings w;
    SharedAmbientFile f(path, Params(), w.Sink());
    EXPECT_EQ(f.LoadAll().size(), 100u);
    ASSERT_EQ(w.messages.size(), 2u);
    EXPECT_NE(w.messages[0].find("byte 6919"), std::string::npos) << w.messages[0];
    EXPECT_NE(w.messages[1].find("not appending"), std::string::npos) << w.messages[1];
    EXPECT_TRUE(f.AppendsDisabled());
    EXPECT_TRUE(f.Sync(std::vector<AmbientRecord>{Tagged(5, 0)}).empty());
    EXPECT_EQ(w.messages.size(), 2u);  // warned once
    EXPECT_EQ(ReadBytes(path), original);
}

// ----- issue 18: records another program removes are appended again -----

std::vector<AmbientRecord> Batch(int writer, int first, int count) {
    std::vector<AmbientRecord> batch;
    for (int i = 0; i < count; ++i) batch.push_back(Tagged(writer, first + i));
    return batch;
}

/// Ids of the records in the file, in file order; every record must be valid
/// and the file must end on a record boundary.
std::vector<std::int64_t> IdsInFile(const std::string& path) {
    const SpecFile spec = SpecRead(ReadBytes(path));
    EXPECT_TRUE(spec.ok);
    EXPECT_EQ(spec.trailing, 0u);
    std::vector<std::int64_t> ids;
    for (const SpecRecord& r : spec.records) {
        EXPECT_TRUE(r.valid);
        ids.push_back(static_cast<std::int64_t>(r.pos[0]) * 1000000 +
                      static_cast<std::int64_t>(r.pos[1]));
    }
    return ids;
}

std::multiset<std::int64_t> IdsOf(std::initializer_list<std::vector<AmbientRecord>> batches) {
    std::multiset<std::int64_t> ids;
    for (const auto& b : batches) {
        for (const auto& r : b) ids.insert(IdOf(r));
    }
    return ids;
}

void CutTo(const std::string& path, std::int64_t bytes) {
    ASSERT_EQ(truncate(path.c_str(), static_cast<off_t>(bytes)), 0);
}

/// A file cut between two syncs (here 30 bytes into the 10th record from its end):
/// the next sync appends the cut records again, its own and those it had read,
/// says so once, and counts them. Before the fix it stopped appending instead.
TEST(SharedAmbientFile, RecordsCutByAnotherProgramAreAppendedAgain) {
    TempDir dir;
    const std::string path = dir.File("cut.amb");
    Warnings wa;
    SharedAmbientFile a(path, Params(), wa.Sink());
    (void)a.LoadAll();
    const auto a1 = Batch(1, 0, 8), b1 = Batch(2, 0, 6), a2 = Batch(1, 8, 1);
    (void)a.Sync(a1);
    {
        SharedAmbientFile b(path, Params(), {});
        (void)b.LoadAll();
        (void)b.Sync(b1);
    }
    EXPECT_EQ(a.Sync({}).size(), b1.size());  // a has read b's records
    const std::int64_t full = SizeOf(path);
    CutTo(path, full - 10 * static_cast<std::int64_t>(kRecordBytes) + 30);
    (void)a.Sync(a2);
    const auto ids = IdsInFile(path);
    EXPECT_EQ(std::multiset<std::int64_t>(ids.begin(), ids.end()), IdsOf({a1, b1, a2}));
    EXPECT_EQ(a.RestoredRecords(), 10u);
    EXPECT_FALSE(a.AppendsDisabled());
    ASSERT_EQ(wa.messages.size(), 2u);  // the partial record, then the put-back
    EXPECT_NE(wa.messages[0].find("removed partial ambient record"), std::string::npos);
    EXPECT_NE(wa.messages[1].find("10 ambient values already saved were removed"),
              std::string::npos)
        << wa.messages[1];
    // A second cut is put back too, and only counted.
    CutTo(path, SizeOf(path) - 3 * static_cast<std::int64_t>(kRecordBytes));
    (void)a.Sync({});
    EXPECT_EQ(a.RestoredRecords(), 13u);
    EXPECT_EQ(wa.messages.size(), 2u);
    EXPECT_EQ(IdsInFile(path).size(), a1.size() + b1.size() + a2.size());
}

/// Radiance's fault: a start-up read without the lock sees our append half
/// done, cuts the "torn" tail and appends its own records over ours, so the
/// file does not even shrink. Both processes that knew the cut records notice;
/// the records come back exactly once, and nobody is handed them as new.
TEST(SharedAmbientFile, RecordsWrittenOverAfterACutComeBackOnce) {
    TempDir dir;
    const std::string path = dir.File("overwritten.amb");
    SharedAmbientFile a(path, Params(), {});
    SharedAmbientFile b(path, Params(), {});
    (void)a.LoadAll();
    (void)b.LoadAll();
    const auto a1 = Batch(1, 0, 5), b1 = Batch(2, 0, 5), c1 = Batch(3, 0, 12);
    (void)a.Sync(a1);
    (void)b.Sync(b1);       // b read a1
    (void)a.Sync({});       // a read b1
    const std::int64_t cut = SizeOf(path) - 7 * static_cast<std::int64_t>(kRecordBytes);
    CutTo(path, cut);       // 2 of a1 and all of b1 gone...
    {
        SharedAmbientFile c(path, Params(), {});  // ...and written over
        (void)c.LoadAll();
        (void)c.Sync(c1);
    }
    ASSERT_GT(SizeOf(path), cut + 7 * static_cast<std::int64_t>(kRecordBytes));
    EXPECT_EQ(a.Sync({}).size(), c1.size());  // c's records are new to a
    EXPECT_EQ(a.RestoredRecords(), 7u);
    const auto fromB = b.Sync({});
    EXPECT_EQ(fromB.size(), c1.size());  // a's put-back copies are not news to b
    EXPECT_EQ(b.RestoredRecords(), 0u);  // a already put them back
    const auto ids = IdsInFile(path);
    EXPECT_EQ(std::multiset<std::int64_t>(ids.begin(), ids.end()), IdsOf({a1, b1, c1}));
}

/// A file emptied to zero bytes gets its header and every known record back;
/// one cut inside its header is left alone, as before.
TEST(SharedAmbientFile, EmptiedFileIsRebuiltButACutHeaderIsLeftAlone) {
    TempDir dir;
    const std::string path = dir.File("emptied.amb");
    SharedAmbientFile a(path, Params(), {});
    (void)a.LoadAll();
    const auto a1 = Batch(1, 0, 4);
    (void)a.Sync(a1);
    const auto header = ReadBytes(path);
    CutTo(path, 0);
    (void)a.Sync({});
    EXPECT_EQ(IdsInFile(path).size(), a1.size());
    EXPECT_EQ(a.RestoredRecords(), a1.size());
    EXPECT_EQ(ReadBytes(path), header);

    Warnings w;
    SharedAmbientFile b(path, Params(), w.Sink());
    (void)b.LoadAll();
    CutTo(path, 10);
    EXPECT_TRUE(b.Sync(Batch(2, 0, 1)).empty());
    EXPECT_TRUE(b.AppendsDisabled());
    EXPECT_EQ(SizeOf(path), 10);
    ASSERT_EQ(w.messages.size(), 1u);
    EXPECT_NE(w.messages[0].find("shrank below its"), std::string::npos) << w.messages[0];
}

TEST(SharedAmbientFile, NonAmbientFileIsRefusedAndLeftByteIdentical) {
    TempDir dir;
    const std::string path = dir.File("notes.txt");
    const std::string text = "shopping list\n\neggs\n";
    testing::WriteBytes(path, {text.begin(), text.end()});
    try {
        SharedAmbientFile f(path, Params(), {});
        FAIL() << "accepted a text file";
    } catch (const Error& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find(path), std::string::npos) << msg;
        EXPECT_NE(msg.find("not a Radiance ambient file"), std::string::npos) << msg;
        EXPECT_EQ(msg.find('\n'), std::string::npos);
        EXPECT_EQ(e.ExitCode(), 1);
    }
    const auto after = ReadBytes(path);
    EXPECT_EQ(std::string(after.begin(), after.end()), text);
    // A pre-5.0 ambient file (magic 557) is refused the same way.
    auto old = ReadBytes(DataPath("cornell_radiance54.amb"));
    old[218] = 0x2D;
    testing::WriteBytes(path, old);
    EXPECT_THROW(SharedAmbientFile(path, Params(), {}), Error);
    EXPECT_EQ(ReadBytes(path), old);
}

TEST(SharedAmbientFile, EmptyFileGetsHeader) {
    TempDir dir;
    const std::string path = dir.File("touched.amb");
    testing::WriteBytes(path, {});
    SharedAmbientFile f(path, Params(), {});
    EXPECT_TRUE(f.LoadAll().empty());
    EXPECT_TRUE(SpecRead(ReadBytes(path)).ok);
}

TEST(SharedAmbientFile, SpecialFilesAreRefusedByKind) {
    TempDir dir;
    const std::string fifo = dir.File("pipe.amb");
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    const std::string link = dir.File("null.amb");
    ASSERT_EQ(symlink("/dev/null", link.c_str()), 0);
    const std::string folder = dir.File("folder.amb");
    ASSERT_EQ(mkdir(folder.c_str(), 0700), 0);
    for (const auto& [path, kind] : {std::pair{std::string("/dev/null"), "a character device"},
                                     std::pair{link, "a character device"},
                                     std::pair{fifo, "a FIFO"},
                                     std::pair{folder, "a directory"}}) {
        try {
            SharedAmbientFile f(path, Params(), {});
            FAIL() << "accepted " << path;
        } catch (const Error& e) {
            EXPECT_EQ(std::string(e.what()),
                      "\"" + path + "\": ambient file is " + kind + ", not a regular file");
            EXPECT_EQ(e.ExitCode(), 1);
        }
    }
}

TEST(SharedAmbientFile, MissingDirectoryIsAClearError) {
    TempDir dir;
    const std::string path = dir.File("no/such/dir/a.amb");
    try {
        SharedAmbientFile f(path, Params(), {});
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("cannot open ambient file \"" + path +
                                             "\": No such file or directory"),
                  std::string::npos)
            << e.what();
        EXPECT_EQ(e.ExitCode(), 2);
    }
}

// Runs `body` in a child process; returns its exit status (or 128+signal).
template <typename F>
int InChild(F body) {
    const pid_t pid = fork();
    if (pid == 0) {
        int rc = 99;
        try {
            rc = body();
        } catch (const std::exception& e) {
            std::fprintf(stderr, "child: %s\n", e.what());
        }
        _exit(rc);
    }
    int st = 0;
    waitpid(pid, &st, 0);
    return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
}

// `original` is read by the caller: the check may run as "nobody", who need not
// be able to read the source tree (a clone under a 0700 directory, say).
template <typename Bytes>
void CheckReadOnlyDirectoryAndFile(const TempDir& dir, const std::string& existing,
                                   const Bytes& original) {
    try {
        SharedAmbientFile f(dir.File("new.amb"), Params(), {});
        ADD_FAILURE() << "created a file in a read-only directory";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("cannot open ambient file"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("Permission denied"), std::string::npos) << e.what();
        EXPECT_EQ(e.ExitCode(), 2);
    }
    // An existing read-only file is used read-only, as Radiance does.
    Warnings w;
    SharedAmbientFile f(existing, Params(), w.Sink());
    EXPECT_TRUE(f.ReadOnly());
    EXPECT_EQ(f.LoadAll().size(), testing::kRadianceRecordCount);
    ASSERT_EQ(w.messages.size(), 1u);
    EXPECT_NE(w.messages[0].find("read-only"), std::string::npos);
    EXPECT_TRUE(f.Sync(std::vector<AmbientRecord>{Tagged(1, 1)}).empty());
    EXPECT_EQ(ReadBytes(existing), original);
}

TEST(SharedAmbientFile, ReadOnlyDirectoryAndFile) {
    TempDir dir;
    const std::string existing = dir.File("frozen.amb");
    const auto original = ReadBytes(DataPath("cornell_radiance54.amb"));
    testing::WriteBytes(existing, original);
    ASSERT_EQ(chmod(existing.c_str(), 0444), 0);
    ASSERT_EQ(chmod(dir.Path().c_str(), 0555), 0);
    if (geteuid() != 0) {
        CheckReadOnlyDirectoryAndFile(dir, existing, original);
    } else {
        // Root ignores permissions: run the check as "nobody" in a child process.
        const int rc = InChild([&] {
            if (setgid(65534) != 0 || setuid(65534) != 0) return 77;
            CheckReadOnlyDirectoryAndFile(dir, existing, original);
            return ::testing::Test::HasFailure() ? 1 : 0;
        });
        if (rc == 77) GTEST_SKIP() << "cannot drop root privileges";
        EXPECT_EQ(rc, 0);
    }
    chmod(dir.Path().c_str(), 0755);
}

TEST(SharedAmbientFile, UnstorableRecordsAreSkippedWithWarning) {
    TempDir dir;
    const std::string path = dir.File("skip.amb");
    Warnings w;
    SharedAmbientFile f(path, Params(), w.Sink());
    (void)f.LoadAll();
    AmbientRecord bad = Tagged(1, 0);
    bad.radius[0] = 0;
    (void)f.Sync(std::vector<AmbientRecord>{Tagged(1, 1), bad, Tagged(1, 2)});
    ASSERT_EQ(w.messages.size(), 1u);
    EXPECT_EQ(SpecRead(ReadBytes(path)).records.size(), 2u);
}

TEST(SharedAmbientFile, WriteErrorLeavesOnlyWholeRecordsAndNamesFile) {
    TempDir dir;
    const std::string path = dir.File("full.amb");
    {
        SharedAmbientFile f(path, Params(), {});
        (void)f.LoadAll();
        (void)f.Sync(std::vector<AmbientRecord>{Tagged(1, 0)});
    }
    const std::int64_t before = SizeOf(path);
    // RLIMIT_FSIZE makes the kernel accept part of our write and then fail with
    // EFBIG: the same partial-write path as a disk filling up (ENOSPC).
    const int rc = InChild([&] {
        signal(SIGXFSZ, SIG_IGN);
        SharedAmbientFile f(path, Params(), {});
        (void)f.LoadAll();
        const rlim_t limit = static_cast<rlim_t>(before + 100);
        const struct rlimit lim{limit, limit};
        if (setrlimit(RLIMIT_FSIZE, &lim) != 0) return 10;
        std::vector<AmbientRecord> batch;
        for (int i = 0; i < 10; ++i) batch.push_back(Tagged(2, i));
        try {
            (void)f.Sync(batch);
        } catch (const Error& e) {
            const std::string msg = e.what();
            if (msg.find(path) == std::string::npos) return 11;
            if (msg.find("File too large") == std::string::npos) return 12;
            if (e.ExitCode() != 2) return 13;
            return SizeOf(path) == before ? 0 : 14;
        }
        return 15;
    });
    EXPECT_EQ(rc, 0);
    EXPECT_EQ(SizeOf(path), before);
    Warnings w;
    SharedAmbientFile g(path, Params(), w.Sink());
    EXPECT_EQ(g.LoadAll().size(), 1u);
    EXPECT_TRUE(w.messages.empty());
}

TEST(SharedAmbientFile, UseAfterForkNeedsReopen) {
    TempDir dir;
    SharedAmbientFile f(dir.File("fork.amb"), Params(), {});
    (void)f.LoadAll();
    EXPECT_EQ(InChild([&] {
                  try {
                      (void)f.Sync(std::vector<AmbientRecord>{Tagged(1, 0)});
                      return 1;
                  } catch (const Error&) {
                  }
                  f.ReopenAfterFork();
                  (void)f.Sync(std::vector<AmbientRecord>{Tagged(1, 0)});
                  return 0;
              }),
              0);
    ASSERT_EQ(f.Sync({}).size(), 1u);
}

// Real Radiance locks with classic fcntl(F_SETLKW) locks; ours must wait for them.
TEST(SharedAmbientFile, WaitsForARadianceStyleClassicLock) {
    TempDir dir;
    const std::string path = dir.File("interop.amb");
    SharedAmbientFile f(path, Params(), {});
    (void)f.LoadAll();
    int ready[2];
    ASSERT_EQ(pipe(ready), 0);
    const pid_t holder = fork();
    if (holder == 0) {
        const int fd = open(path.c_str(), O_RDWR);
        struct flock fl {};
        fl.l_type = F_WRLCK;
        fl.l_whence = SEEK_SET;
        if (fd < 0 || fcntl(fd, F_SETLKW, &fl) != 0) _exit(1);
        const char c = 'x';
        if (write(ready[1], &c, 1) != 1) _exit(2);
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        _exit(0);  // process exit releases the lock
    }
    char c;
    ASSERT_EQ(read(ready[0], &c, 1), 1);
    const auto start = std::chrono::steady_clock::now();
    (void)f.Sync(std::vector<AmbientRecord>{Tagged(1, 0)});
    const auto waited = std::chrono::steady_clock::now() - start;
    EXPECT_GE(waited, std::chrono::milliseconds(200));
    int st = 0;
    waitpid(holder, &st, 0);
    EXPECT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 0);
    close(ready[0]);
    close(ready[1]);
}

/// A child holding Radiance's classic write lock for 300 ms, as during an append.
class ClassicLockHolder {
public:
    explicit ClassicLockHolder(const std::string& path) {
        if (pipe(ready_) != 0) std::abort();
        pid_ = fork();
        if (pid_ == 0) {
            const int fd = open(path.c_str(), O_RDWR);
            struct flock fl {};
            fl.l_type = F_WRLCK;
            fl.l_whence = SEEK_SET;
            if (fd < 0 || fcntl(fd, F_SETLKW, &fl) != 0) _exit(1);
            const char c = 'x';
            if (write(ready_[1], &c, 1) != 1) _exit(2);
            std::this_thread::sleep_for(std::chrono::milliseconds(300));
            _exit(0);
        }
        char c;
        if (read(ready_[0], &c, 1) != 1) std::abort();
    }
    ~ClassicLockHolder() {
        int st = 0;
        waitpid(pid_, &st, 0);
        close(ready_[0]);
        close(ready_[1]);
    }
    ClassicLockHolder(const ClassicLockHolder&) = delete;
    ClassicLockHolder& operator=(const ClassicLockHolder&) = delete;

private:
    pid_t pid_ = -1;
    int ready_[2] = {-1, -1};
};

/// Issue 18: Radiance loads the file at start-up without its lock and can cut
/// records another process is appending. lazyrad's start-up (open, header,
/// first load) waits for a writer's lock, writable or read-only.
TEST(SharedAmbientFile, StartUpReadsWaitForTheWritersLock) {
    TempDir dir;
    const std::string path = dir.File("startup.amb");
    {
        SharedAmbientFile create(path, Params(), {});
        (void)create.Sync(Batch(1, 0, 3));
    }
    for (const bool readOnly : {false, true}) {
        ASSERT_EQ(chmod(path.c_str(), readOnly ? 0444 : 0644), 0);
        if (readOnly && geteuid() == 0) continue;  // root writes anyway
        {
            SharedAmbientFile f(path, Params(), {});
            const ClassicLockHolder holder(path);
            const auto start = std::chrono::steady_clock::now();
            EXPECT_EQ(f.LoadAll().size(), 3u);
            EXPECT_GE(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(200))
                << "LoadAll, read-only " << readOnly;
        }
        const ClassicLockHolder holder(path);
        const auto start = std::chrono::steady_clock::now();
        SharedAmbientFile f(path, Params(), {});
        EXPECT_GE(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(200))
            << "open, read-only " << readOnly;
    }
    ASSERT_EQ(chmod(path.c_str(), 0644), 0);
}

TEST(SharedAmbientFile, EightProcessesAppendConcurrently) {
    TempDir dir;
    const std::string path = dir.File("shared.amb");
    { SharedAmbientFile create(path, Params(), {}); }
    constexpr int kProcs = 8, kSyncs = 6;
    auto batchSize = [](int proc, int sync) { return 1 + (proc * 37 + sync * 53) % 150; };
    std::vector<pid_t> pids;
    for (int p = 0; p < kProcs; ++p) {
        const pid_t pid = fork();
        if (pid == 0) {
            int rc = 0;
            try {
                Warnings w;
                SharedAmbientFile f(path, Params(), w.Sink());
                std::set<std::int64_t> seen;
                for (const auto& r : f.LoadAll()) seen.insert(IdOf(r));
                int seq = 0;
                for (int s = 0; s < kSyncs; ++s) {
                    std::vector<AmbientRecord> batch;
                    for (int i = 0; i < batchSize(p, s); ++i) batch.push_back(Tagged(p + 1, seq++));
                    for (const auto& r : f.Sync(batch)) {
                        if (!seen.insert(IdOf(r)).second) rc = 3;  // seen twice
                    }
                    for (const auto& r : batch) seen.insert(IdOf(r));
                    std::this_thread::sleep_for(std::chrono::microseconds(200 * ((p + s) % 4)));
                }
                if (!w.messages.empty()) rc = 4;
                std::ofstream out(dir.File("seen." + std::to_string(p)));
                out << f.EndOffset() << "\n";
                for (auto id : seen) out << id << "\n";
            } catch (const std::exception& e) {
                std::fprintf(stderr, "child %d: %s\n", p, e.what());
                rc = 2;
            }
            _exit(rc);
        }
        pids.push_back(pid);
    }
    for (pid_t pid : pids) {
        int st = 0;
        ASSERT_EQ(waitpid(pid, &st, 0), pid);
        EXPECT_TRUE(WIFEXITED(st) && WEXITSTATUS(st) == 0) << st;
    }
    const SpecFile spec = SpecRead(ReadBytes(path));
    ASSERT_TRUE(spec.ok);
    EXPECT_EQ(spec.trailing, 0u);
    std::size_t expected = 0;
    for (int p = 0; p < kProcs; ++p) {
        for (int s = 0; s < kSyncs; ++s) expected += static_cast<std::size_t>(batchSize(p, s));
    }
    ASSERT_EQ(spec.records.size(), expected);
    std::map<std::int64_t, std::size_t> offsetOf;  // id -> byte offset of its record
    for (std::size_t i = 0; i < spec.records.size(); ++i) {
        const SpecRecord& s = spec.records[i];
        EXPECT_TRUE(s.valid);
        const std::int64_t id =
            static_cast<std::int64_t>(s.pos[0]) * 1000000 + static_cast<std::int64_t>(s.pos[1]);
        EXPECT_TRUE(offsetOf.emplace(id, spec.recordsAt + i * 67).second) << "duplicate " << id;
    }
    // Each process saw every record that lies before the end of its own last append.
    for (int p = 0; p < kProcs; ++p) {
        std::ifstream in(dir.File("seen." + std::to_string(p)));
        std::size_t end = 0;
        in >> end;
        std::set<std::int64_t> seen;
        for (std::int64_t id; in >> id;) seen.insert(id);
        std::size_t mustHaveSeen = 0;
        for (const auto& [id, off] : offsetOf) {
            if (off < end) {
                ++mustHaveSeen;
                EXPECT_TRUE(seen.count(id)) << "process " << p << " missed " << id;
            }
        }
        EXPECT_EQ(seen.size(), mustHaveSeen) << "process " << p;
    }
    Warnings w;
    SharedAmbientFile check(path, Params(), w.Sink());
    EXPECT_EQ(check.LoadAll().size(), expected);
    EXPECT_TRUE(w.messages.empty());
}

// A writer killed between syncs (holding unsynced records) leaves whole records only.
TEST(SharedAmbientFile, SigkillBetweenSyncsLosesOnlyUnsyncedRecords) {
    TempDir dir;
    const std::string path = dir.File("killed.amb");
    { SharedAmbientFile create(path, Params(), {}); }
    for (int round = 0; round < 4; ++round) {
        const int rc = InChild([&] {
            SharedAmbientFile f(path, Params(), {});
            (void)f.LoadAll();
            std::vector<AmbientRecord> batch;
            for (int i = 0; i < SharedAmbientFile::kSyncInterval; ++i) {
                batch.push_back(Tagged(20 + round, i));
            }
            (void)f.Sync(batch);
            std::vector<AmbientRecord> unsynced{Tagged(20 + round, 1000)};
            raise(SIGKILL);
            return 0;
        });
        EXPECT_EQ(rc, 128 + SIGKILL);
        const SpecFile spec = SpecRead(ReadBytes(path));
        ASSERT_TRUE(spec.ok);
        EXPECT_EQ(spec.trailing, 0u);
        EXPECT_EQ(spec.records.size(),
                  static_cast<std::size_t>((round + 1) * SharedAmbientFile::kSyncInterval));
        for (const SpecRecord& s : spec.records) ASSERT_TRUE(s.valid);
    }
    Warnings w;
    SharedAmbientFile check(path, Params(), w.Sink());
    EXPECT_EQ(check.LoadAll().size(), 4u * SharedAmbientFile::kSyncInterval);
    EXPECT_TRUE(w.messages.empty());
}

// A writer killed at an arbitrary moment, usually inside its write(2): Linux may stop
// a multi-page write at a page boundary on SIGKILL, so the file can end in a torn
// record. Every whole record is still valid, and the next sync cuts the torn tail
// (with a warning) and appends after it: nothing but the dying writer's batch is lost.
TEST(SharedAmbientFile, SigkillMidWriteLeavesAtMostATornTailThatTheNextSyncRepairs) {
    TempDir dir;
    const std::string path = dir.File("killed.amb");
    { SharedAmbientFile create(path, Params(), {}); }
    for (int round = 0; round < 6; ++round) {
        const pid_t steady = fork();
        if (steady == 0) {
            SharedAmbientFile f(path, Params(), {});
            (void)f.LoadAll();
            for (int seq = 0;; ++seq) {
                std::vector<AmbientRecord> batch;
                for (int i = 0; i < SharedAmbientFile::kSyncInterval; ++i) {
                    batch.push_back(Tagged(10 + round, seq * 1000 + i));
                }
                (void)f.Sync(batch);
            }
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2 + 3 * round));
        kill(steady, SIGKILL);
        int st = 0;
        waitpid(steady, &st, 0);
        EXPECT_TRUE(WIFSIGNALED(st));

        const SpecFile before = SpecRead(ReadBytes(path));
        ASSERT_TRUE(before.ok);
        EXPECT_LT(before.trailing, kRecordBytes);
        for (const SpecRecord& s : before.records) ASSERT_TRUE(s.valid);
        Warnings w;
        SharedAmbientFile next(path, Params(), w.Sink());
        EXPECT_EQ(next.LoadAll().size(), before.records.size());
        EXPECT_EQ(w.messages.size(), before.trailing > 0 ? 1u : 0u);
        (void)next.Sync(std::vector<AmbientRecord>{Tagged(30, round)});
        const SpecFile after = SpecRead(ReadBytes(path));
        EXPECT_EQ(after.trailing, 0u);
        EXPECT_EQ(after.records.size(), before.records.size() + 1);
    }
}

}  // namespace
}  // namespace rt
