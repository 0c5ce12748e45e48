// SPDX-License-Identifier: MIT
//
// An ambient file shared by any number of processes (ours and real Radiance's),
// replacing the file half of Radiance's ambient.c (setambient, initambfile,
// ambsync, aflock; radiance-notes.md §5.7). Every exchange is one critical
// section under an fcntl write lock on the whole file:
//   lock → read what others appended since our last read → append ours in one
//   write of whole records → remember the new end → unlock.
// Records become visible to other processes only at their next sync; Radiance
// syncs every kSyncInterval new records and at exit, and callers should too.
//
//   SharedAmbientFile file(path, headerParams, warn);
//   for (auto& r : file.LoadAll()) cache.Insert(r);
//   ... every kSyncInterval new records and at exit:
//   for (auto& r : file.Sync(newRecords)) cache.Insert(r);
//
// Damage policy (documented in the README):
//  * A partial last record (length not on a record boundary) is cut off, under
//    the lock, with a warning naming the byte offset; appending continues there.
//  * A record failing Radiance's validity checks stops reading with a warning
//    naming its byte offset, and from then on this object appends nothing to the
//    file (one warning); records after the damage may be another process's good
//    data, so we neither overwrite them (as Radiance does) nor bury them.
//  * An empty (0-byte) existing file gets our header, under the lock, instead of
//    Radiance's fatal "bad ambient file": it is what `touch` or a creator that
//    has not written its header yet leaves behind.
//  * An existing file that is not an ambient file is refused (rt::Error) and
//    never written to.
//  * A file we may not write is loaded read-only with a warning, as Radiance does.
//  * A SIGKILL between syncs loses only the unsynced records. A SIGKILL inside the
//    write(2) itself can stop a multi-page write at a page boundary (Linux checks
//    for fatal signals between pages), leaving a torn last record; the next sync by
//    anyone (ours, or Radiance's ambsync) cuts or overwrites it.
//  * Records we synced or read that another program removed are appended again.
//    Real Radiance loads the file at start-up without its lock, so it can see a
//    record we are still writing as a torn tail, cut it off, and then append its
//    own records over ours. Each sync checks (one 67-byte read) that the last
//    record we know is still where we left it; if not, it finds the longest
//    intact prefix (binary search: a cut keeps everything before it) and appends
//    the records after it again, from our copy of every byte we know (67 bytes a
//    record, beside the caller's cache), saying so once on stderr. Records
//    another process already put back are not duplicated. A file emptied to zero
//    bytes gets its header back; one cut inside its header is left alone.
//
// Not thread-safe: one object per thread, or a mutex around it. The destructor
// does not sync (as Radiance's ambdone()); call Sync() first. After fork() call
// ReopenAfterFork() in the child. With the classic-lock fallback (kernels without
// OFD locks) two objects for the same file in one process do not exclude each
// other, and closing one drops the other's lock.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <sys/types.h>
#include <vector>

#include "ambfiles/header.h"
#include "ambient/record.h"
#include "core/diagnostics.h"

namespace rt {

class SharedAmbientFile {
public:
    /// Radiance's AMBFLUSH = BUFSIZ/67 on glibc: new records between syncs.
    static constexpr int kSyncInterval = 122;

    /// Opens `path` read/write (read-only if not writable), creating it with a header
    /// made from `headerParams` if absent or empty. Throws rt::Error (System) when the
    /// file cannot be opened, created or locked, (User) when it is not an ambient file.
    /// `warn` receives one-line warnings; it may be empty.
    SharedAmbientFile(std::string path, const AmbientHeaderParams& headerParams,
                      WarningSink warn);
    ~SharedAmbientFile();
    SharedAmbientFile(SharedAmbientFile&& other) noexcept;
    SharedAmbientFile& operator=(SharedAmbientFile&& other) noexcept;
    SharedAmbientFile(const SharedAmbientFile&) = delete;
    SharedAmbientFile& operator=(const SharedAmbientFile&) = delete;

    /// Every valid record now in the file (from the header on), for the first load.
    /// Equivalent to Sync({}) on a freshly opened file.
    [[nodiscard]] std::vector<AmbientRecord> LoadAll();

    /// Appends `ours` and returns the records other processes appended since our last
    /// LoadAll/Sync (never our own). Records that would not survive a round trip
    /// through the format (IsStorable) are skipped with a warning. Read-only or
    /// damaged files: returns what can be read, writes nothing. On a write error
    /// (ENOSPC, EDQUOT, EFBIG, EIO...) the partial append is truncated away, the
    /// file keeps only whole records, and rt::Error (System) names the file; the
    /// object is unchanged, so the call may be retried.
    [[nodiscard]] std::vector<AmbientRecord> Sync(std::span<const AmbientRecord> ours);

    /// After fork(): give the child its own open file description. OFD locks belong to
    /// the open file description, so parent and child sharing one would not exclude
    /// each other. Keeps the read position (the child knows what the parent knew).
    void ReopenAfterFork();

    /// Records synced or read earlier that another program removed from the
    /// file and this object appended again (for rtrace -t's summary).
    std::size_t RestoredRecords() const { return restored_; }

    /// Fault injection for the stress test. `keepBytes(n)` is asked before an
    /// append of n bytes and returns how many of them reach the file; the rest
    /// fail as a full disk does (ENOSPC), and that path removes the partial
    /// record. `afterShortWrite`, if set, runs between the short write and the
    /// clean-up with the lock held, so a test can SIGKILL the process there and
    /// leave a torn record for the next sync to cut.
    struct WriteFaults {
        std::function<std::size_t(std::size_t)> keepBytes;
        std::function<void()> afterShortWrite;
    };
    void InjectWriteFaults(WriteFaults faults) { faults_ = std::move(faults); }

    const std::string& Path() const { return path_; }
    bool ReadOnly() const { return readOnly_; }
    /// True after damage was found: nothing more will be appended.
    bool AppendsDisabled() const { return appendsDisabled_; }
    /// Byte offset up to which the file has been read and validated.
    std::int64_t EndOffset() const { return lastPos_; }

private:
    void Lock(short type);
    void Unlock();
    void Warn(const std::string& message) const;
    [[noreturn]] void ThrowSys(const std::string& what, int err) const;
    std::vector<AmbientRecord> Exchange(std::span<const AmbientRecord> ours);
    bool StillHolds(std::int64_t recordEnd, std::int64_t flen) const;
    std::int64_t IntactPrefix(std::int64_t flen) const;

    std::string path_;
    WarningSink warn_;
    int fd_ = -1;
    bool readOnly_ = false;
    bool appendsDisabled_ = false;
    std::int64_t recordsStart_ = 0;  // offset of the first record
    std::int64_t lastPos_ = 0;       // everything before this has been read by us
    pid_t ownerPid_ = 0;             // process that opened fd_ (see ReopenAfterFork)
    /// Every byte of the file before lastPos_, header included, as we read or
    /// wrote it: what is appended again if another program removes it.
    std::vector<std::uint8_t> known_;
    /// Removed records not yet appended again (kept across a failed write).
    std::vector<std::uint8_t> pendingRestore_;
    std::size_t restored_ = 0;
    bool warnedRestore_ = false;
    WriteFaults faults_;
};

}  // namespace rt
