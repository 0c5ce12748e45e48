// SPDX-License-Identifier: MIT
#include "ambfiles/shared_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <functional>
#include <set>
#include <string_view>
#include <utility>

#include "ambfiles/record_codec.h"
#include "core/error.h"

namespace rt {
namespace {

std::string Quoted(const std::string& path) { return "\"" + path + "\""; }

// pread() until `n` bytes or EOF; returns the count, or -1 with errno set.
ssize_t ReadAt(int fd, std::uint8_t* buf, std::size_t n, std::int64_t offset) {
    std::size_t done = 0;
    while (done < n) {
        const ssize_t got = pread(fd, buf + done, n - done, static_cast<off_t>(offset + done));
        if (got < 0) {
            if (errno == EINTR) continue;
            return -1;
        }
        if (got == 0) break;
        done += static_cast<std::size_t>(got);
    }
    return static_cast<ssize_t>(done);
}

// pwrite() all of `buf`, resuming after EINTR and short writes; 0 or an errno value.
int WriteAt(int fd, const std::uint8_t* buf, std::size_t n, std::int64_t offset) {
    std::size_t done = 0;
    while (done < n) {
        const ssize_t put = pwrite(fd, buf + done, n - done, static_cast<off_t>(offset + done));
        if (put < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        if (put == 0) return EIO;  // cannot happen for regular files; avoid spinning
        done += static_cast<std::size_t>(put);
    }
    return 0;
}

std::int64_t FileSize(int fd) {
    struct stat st {};
    if (fstat(fd, &st) != 0) return -1;
    return static_cast<std::int64_t>(st.st_size);
}

// Releases the lock on every exit path, exceptions included.
class LockGuard {
public:
    explicit LockGuard(std::function<void()> unlock) : unlock_(std::move(unlock)) {}
    ~LockGuard() {
        if (unlock_) unlock_();
    }
    LockGuard(const LockGuard&) = delete;
    LockGuard& operator=(const LockGuard&) = delete;

private:
    std::function<void()> unlock_;
};

/// What a non-regular file is, for the error message.
std::string FileKind(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISSOCK(mode)) return "a socket";
    return "a special file";
}

}  // namespace

SharedAmbientFile::SharedAmbientFile(std::string path, const AmbientHeaderParams& headerParams,
                                     WarningSink warn)
    : path_(std::move(path)), warn_(std::move(warn)) {
    // Only a regular file can hold records: /dev/null swallows them, a FIFO
    // would block the first read forever, a directory cannot be written.
    // Checked before opening (which would block on some special files) and
    // again on the descriptor, in case the path changed in between.
    if (struct stat st{}; stat(path_.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
        ThrowUserError(Quoted(path_) + ": ambient file is " + FileKind(st.st_mode) +
                       ", not a regular file");
    }
    fd_ = open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NONBLOCK, 0666);
    if (fd_ < 0) {
        const int err = errno;
        // Not writable, but it exists: load it read-only, as Radiance does.
        if (err == EACCES || err == EROFS || err == EPERM) {
            fd_ = open(path_.c_str(), O_RDONLY | O_CLOEXEC);
            readOnly_ = fd_ >= 0;
        }
        // Radiance's words whether or not the file exists; the system's
        // reason (no such folder, permission denied) tells which.
        if (fd_ < 0) ThrowSys("cannot open ambient file", err);
    }
    ownerPid_ = getpid();
    if (struct stat st{}; fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
        const std::string kind = FileKind(st.st_mode);
        close(fd_);
        fd_ = -1;
        ThrowUserError(Quoted(path_) + ": ambient file is " + kind + ", not a regular file");
    }
    // O_NONBLOCK only kept open() from waiting on a special file.
    fcntl(fd_, F_SETFL, fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
    try {
        Lock(readOnly_ ? F_RDLCK : F_WRLCK);
        LockGuard guard([this] { Unlock(); });
        const std::int64_t size = FileSize(fd_);
        if (size < 0) ThrowSys("cannot stat ambient file", errno);
        if (size == 0) {
            if (readOnly_) {
                ThrowUserError(Quoted(path_) + ": bad ambient file (empty and not writable)");
            }
            // Empty: new, touched, or a creator that has not written its header yet (it
            // would find our header under the lock). Radiance calls this fatal.
            const std::string header = FormatAmbientHeader(headerParams);
            const int err = WriteAt(fd_, reinterpret_cast<const std::uint8_t*>(header.data()),
                                    header.size(), 0);
            if (err != 0) {
                if (ftruncate(fd_, 0) != 0) { /* keep the first error */ }
                ThrowSys("cannot write header to ambient file", err);
            }
            recordsStart_ = static_cast<std::int64_t>(header.size());
            known_.assign(header.begin(), header.end());
        } else {
            // Read until the header parses; headers are short, files may be huge.
            std::vector<std::uint8_t> head;
            std::size_t want = 4096;
            HeaderParse parse;
            for (;;) {
                want = std::min<std::size_t>(want, static_cast<std::size_t>(size));
                head.resize(want);
                const ssize_t got = ReadAt(fd_, head.data(), want, 0);
                if (got < 0) ThrowSys("cannot read ambient file", errno);
                head.resize(static_cast<std::size_t>(got));
                parse = ParseAmbientHeader(head);
                if (parse.header || head.size() < want || want >= static_cast<std::size_t>(size)) {
                    break;
                }
                want *= 4;
            }
            if (!parse.header) {
                ThrowUserError(Quoted(path_) + ": not a Radiance ambient file (" + parse.problem +
                               "); refusing to use it");
            }
            recordsStart_ = static_cast<std::int64_t>(parse.header->recordsOffset);
            known_.assign(head.begin(), head.begin() + static_cast<std::ptrdiff_t>(recordsStart_));
        }
        lastPos_ = recordsStart_;
    } catch (...) {
        close(fd_);
        fd_ = -1;
        throw;
    }
}

SharedAmbientFile::~SharedAmbientFile() {
    if (fd_ >= 0) close(fd_);
}

SharedAmbientFile::SharedAmbientFile(SharedAmbientFile&& o) noexcept
    : path_(std::move(o.path_)),
      warn_(std::move(o.warn_)),
      fd_(std::exchange(o.fd_, -1)),
      readOnly_(o.readOnly_),
      appendsDisabled_(o.appendsDisabled_),
      recordsStart_(o.recordsStart_),
      lastPos_(o.lastPos_),
      ownerPid_(o.ownerPid_),
      known_(std::move(o.known_)),
      pendingRestore_(std::move(o.pendingRestore_)),
      restored_(o.restored_),
      warnedRestore_(o.warnedRestore_),
      faults_(std::move(o.faults_)) {}

SharedAmbientFile& SharedAmbientFile::operator=(SharedAmbientFile&& o) noexcept {
    if (this != &o) {
        if (fd_ >= 0) close(fd_);
        path_ = std::move(o.path_);
        warn_ = std::move(o.warn_);
        fd_ = std::exchange(o.fd_, -1);
        readOnly_ = o.readOnly_;
        appendsDisabled_ = o.appendsDisabled_;
        recordsStart_ = o.recordsStart_;
        lastPos_ = o.lastPos_;
        ownerPid_ = o.ownerPid_;
        known_ = std::move(o.known_);
        pendingRestore_ = std::move(o.pendingRestore_);
        restored_ = o.restored_;
        warnedRestore_ = o.warnedRestore_;
        faults_ = std::move(o.faults_);
    }
    return *this;
}

void SharedAmbientFile::Warn(const std::string& message) const {
    if (warn_) warn_(message);
}

void SharedAmbientFile::ThrowSys(const std::string& what, int err) const {
    throw Error(Error::Kind::System, what + " " + Quoted(path_) + ": " + std::strerror(err));
}

// Whole-file fcntl record locks, blocking, retried on EINTR. Open-file-description
// (OFD) locks where the kernel has them: they are owned by our descriptor, so they
// survive other code closing another descriptor of the same file. Classic POSIX
// locks (the fallback) are owned by the process and are dropped when ANY descriptor
// of the file is closed by this process, which is why this class reads and writes
// through its single descriptor and never opens a second one while locked. Both
// kinds conflict with each other on Linux, hence with real Radiance's F_SETLKW.
void SharedAmbientFile::Lock(short type) {
    struct flock fl {};
    fl.l_type = type;
    fl.l_whence = SEEK_SET;
    fl.l_start = 0;
    fl.l_len = 0;  // to the end of the file, however long it grows
#ifdef F_OFD_SETLKW
    int rc;
    do {
        rc = fcntl(fd_, F_OFD_SETLKW, &fl);
    } while (rc == -1 && errno == EINTR);
    if (rc == 0) return;
    if (errno != EINVAL) ThrowSys("cannot lock ambient file", errno);
    fl.l_pid = 0;  // kernel without OFD locks: fall through to classic locks
#endif
    int rc2;
    do {
        rc2 = fcntl(fd_, F_SETLKW, &fl);
    } while (rc2 == -1 && errno == EINTR);
    if (rc2 != 0) ThrowSys("cannot lock ambient file", errno);
}

void SharedAmbientFile::Unlock() {
    struct flock fl {};
    fl.l_type = F_UNLCK;
    fl.l_whence = SEEK_SET;
#ifdef F_OFD_SETLK
    if (fcntl(fd_, F_OFD_SETLK, &fl) == 0) return;
    fl = {};
    fl.l_type = F_UNLCK;
    fl.l_whence = SEEK_SET;
#endif
    // Unlocking cannot usefully fail here; closing the descriptor would release it.
    (void)fcntl(fd_, F_SETLK, &fl);
}

std::vector<AmbientRecord> SharedAmbientFile::LoadAll() {
    std::vector<AmbientRecord> records = Exchange({});
    if (readOnly_) {
        Warn("loaded " + std::to_string(records.size()) + " values from read-only ambient file " +
             Quoted(path_) + "; new values will not be saved");
    }
    return records;
}

std::vector<AmbientRecord> SharedAmbientFile::Sync(std::span<const AmbientRecord> ours) {
    return Exchange(ours);
}

void SharedAmbientFile::ReopenAfterFork() {
    const int fd = open(path_.c_str(), (readOnly_ ? O_RDONLY : O_RDWR) | O_CLOEXEC);
    if (fd < 0) ThrowSys("cannot reopen ambient file", errno);
    // The inherited descriptor's OFD lock (if any) belongs to the parent too; closing
    // our copy does not release it while the parent holds its copy.
    close(fd_);
    fd_ = fd;
    ownerPid_ = getpid();
}

// True when the 67 bytes before `recordEnd` are still the record we know there.
bool SharedAmbientFile::StillHolds(std::int64_t recordEnd, std::int64_t flen) const {
    if (recordEnd > flen) return false;
    std::uint8_t buf[kRecordBytes];
    const std::int64_t at = recordEnd - static_cast<std::int64_t>(kRecordBytes);
    if (ReadAt(fd_, buf, kRecordBytes, at) != static_cast<ssize_t>(kRecordBytes)) return false;
    return std::memcmp(buf, known_.data() + at, kRecordBytes) == 0;
}

// How much of what we know the file still holds: lastPos_ when nothing was
// removed, a record boundary when records were cut off (and possibly written
// over), 0 when the file was emptied, -1 when it was cut inside the header.
std::int64_t SharedAmbientFile::IntactPrefix(std::int64_t flen) const {
    if (flen < recordsStart_) return flen == 0 ? 0 : -1;
    const auto rec = static_cast<std::int64_t>(kRecordBytes);
    const std::int64_t known = (lastPos_ - recordsStart_) / rec;
    if (known == 0 || StillHolds(lastPos_, flen)) return lastPos_;
    // Record k ends at recordsStart_ + (k+1)·67. A cut keeps everything before
    // it, so the intact records form a prefix: find the first one that is not.
    std::int64_t lo = 0, hi = known - 1;  // the answer is in [lo, hi]; record hi is not intact
    while (lo < hi) {
        const std::int64_t mid = lo + (hi - lo) / 2;
        if (StillHolds(recordsStart_ + (mid + 1) * rec, flen)) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    return recordsStart_ + lo * rec;
}

std::vector<AmbientRecord> SharedAmbientFile::Exchange(std::span<const AmbientRecord> ours) {
    if (fd_ < 0) throw Error(Error::Kind::Internal, "ambient file used after move");
    if (getpid() != ownerPid_) {
        throw Error(Error::Kind::Internal,
                    "ambient file " + Quoted(path_) + " used after fork without ReopenAfterFork()");
    }
    std::vector<AmbientRecord> foreign;
    if (appendsDisabled_) return foreign;  // cannot read past the damage either

    // Encode outside the lock to keep the critical section short.
    std::vector<std::uint8_t> out;
    if (!readOnly_) {
        out.reserve(ours.size() * kRecordBytes);
        std::size_t skipped = 0;
        for (const AmbientRecord& r : ours) {
            const RecordBytes bytes = EncodeRecord(r);
            if (!DecodeRecord(bytes)) {
                ++skipped;
                continue;
            }
            out.insert(out.end(), bytes.begin(), bytes.end());
        }
        if (skipped > 0) {
            Warn(std::to_string(skipped) + " ambient values outside the file format's limits not "
                 "saved to " + Quoted(path_));
        }
    }

    Lock(readOnly_ ? F_RDLCK : F_WRLCK);
    LockGuard guard([this] { Unlock(); });
    const std::int64_t flen = FileSize(fd_);
    if (flen < 0) ThrowSys("cannot stat ambient file", errno);

    // Has another program removed what we know (see the header)?
    const std::int64_t intact = IntactPrefix(flen);
    if (intact < 0) {
        appendsDisabled_ = true;
        Warn(FileLoc{path_, 0, flen}.ToString() + ": ambient file shrank below its " +
             std::to_string(recordsStart_) + "-byte header (changed by another program?); "
             "no more values will be saved to it");
        return foreign;
    }
    if (intact < lastPos_) {
        const auto from = known_.begin() + static_cast<std::ptrdiff_t>(intact);
        pendingRestore_.insert(pendingRestore_.end(), from, known_.end());
        known_.erase(from, known_.end());
        lastPos_ = intact;
    }
    const std::int64_t startPos = lastPos_;

    // Read what others appended since our last visit.
    std::vector<std::uint8_t> in(static_cast<std::size_t>(flen - lastPos_));
    const ssize_t got = ReadAt(fd_, in.data(), in.size(), lastPos_);
    if (got < 0) ThrowSys("cannot read ambient file", errno);
    in.resize(static_cast<std::size_t>(got));

    // Removed records another process has already put back are neither
    // appended again nor handed to the caller, who has them.
    std::set<std::string_view> toRestore;
    const auto recordAt = [](const std::vector<std::uint8_t>& bytes, std::size_t at) {
        return std::string_view(reinterpret_cast<const char*>(bytes.data()) + at, kRecordBytes);
    };
    std::size_t headerBytes = 0;  // of pendingRestore_: a file cut to zero lost its header
    if (!pendingRestore_.empty() && startPos == 0) {
        headerBytes = static_cast<std::size_t>(recordsStart_);
    }
    for (std::size_t at = headerBytes; at + kRecordBytes <= pendingRestore_.size();
         at += kRecordBytes) {
        toRestore.insert(recordAt(pendingRestore_, at));
    }

    std::size_t used = 0;
    bool corrupt = false;
    while (in.size() - used >= kRecordBytes) {
        const std::span<const std::uint8_t, kRecordBytes> rec(in.data() + used, kRecordBytes);
        auto r = DecodeRecord(rec);
        if (!r) {
            corrupt = true;
            break;
        }
        if (toRestore.erase(recordAt(in, used)) == 0) foreign.push_back(*r);
        used += kRecordBytes;
    }
    known_.insert(known_.end(), in.begin(), in.begin() + static_cast<std::ptrdiff_t>(used));
    lastPos_ += static_cast<std::int64_t>(used);

    if (corrupt) {
        const std::int64_t after = (flen - lastPos_) / static_cast<std::int64_t>(kRecordBytes) - 1;
        appendsDisabled_ = true;
        Warn(FileLoc{path_, 0, lastPos_}.ToString() +
             ": corrupt ambient record; reading stopped (" + std::to_string(after) +
             " record slots after it ignored)");
        if (!readOnly_) {
            Warn("not appending to damaged ambient file " + Quoted(path_) +
                 " for the rest of this run; new values stay in memory");
        }
        return foreign;
    }
    if (readOnly_) {
        pendingRestore_.clear();  // cannot put them back; the cache still has them
        return foreign;
    }
    if (lastPos_ != flen) {
        // A partial record: a writer died or ran out of space mid-write. Appends are
        // whole records under this lock, so nobody is still writing it.
        if (ftruncate(fd_, static_cast<off_t>(lastPos_)) != 0) {
            known_.resize(static_cast<std::size_t>(startPos));
            lastPos_ = startPos;
            ThrowSys("cannot truncate damaged ambient file", errno);
        }
        Warn(FileLoc{path_, 0, lastPos_}.ToString() + ": removed partial ambient record (" +
             std::to_string(flen - lastPos_) + " bytes) at end of file");
    }

    // What to append: the removed records nobody has put back (and the header,
    // if the file was cut to nothing), then ours.
    std::vector<std::uint8_t> restore(pendingRestore_.begin(),
                                      pendingRestore_.begin() +
                                          static_cast<std::ptrdiff_t>(headerBytes));
    std::size_t restoredNow = 0;
    for (std::size_t at = headerBytes; at + kRecordBytes <= pendingRestore_.size();
         at += kRecordBytes) {
        if (toRestore.count(recordAt(pendingRestore_, at)) == 0) continue;
        restore.insert(restore.end(), pendingRestore_.begin() + static_cast<std::ptrdiff_t>(at),
                       pendingRestore_.begin() + static_cast<std::ptrdiff_t>(at + kRecordBytes));
        ++restoredNow;
    }
    if (!restore.empty()) out.insert(out.begin(), restore.begin(), restore.end());

    if (!out.empty()) {
        std::size_t keep = out.size();
        if (faults_.keepBytes) keep = std::min(keep, faults_.keepBytes(out.size()));
        int err = WriteAt(fd_, out.data(), keep, lastPos_);
        if (err == 0 && keep < out.size()) {
            if (faults_.afterShortWrite) faults_.afterShortWrite();
            err = ENOSPC;
        }
        if (err != 0) {
            // Leave only whole records behind, then report.
            const bool cleaned = ftruncate(fd_, static_cast<off_t>(lastPos_)) == 0;
            known_.resize(static_cast<std::size_t>(startPos));
            lastPos_ = startPos;  // a retry re-reads the foreign records too
            throw Error(Error::Kind::System,
                        "cannot write ambient file " + Quoted(path_) + ": " + std::strerror(err) +
                            (cleaned ? " (partial append removed; the file holds whole records)"
                                     : " (and could not remove the partial append)"));
        }
        known_.insert(known_.end(), out.begin(), out.end());
        lastPos_ += static_cast<std::int64_t>(out.size());
    }
    pendingRestore_.clear();
    if (restoredNow > 0) {
        restored_ += restoredNow;
        if (!warnedRestore_) {
            warnedRestore_ = true;
            Warn(Quoted(path_) + ": " + std::to_string(restoredNow) +
                 " ambient values already saved were removed by another program; appended "
                 "them again (further cases are only counted)");
        }
    }
    return foreign;
}

}  // namespace rt
