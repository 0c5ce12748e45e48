// SPDX-License-Identifier: MIT
#include "ambfiles/shared_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <functional>
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
        if (fd_ < 0) {
            const bool exists = access(path_.c_str(), F_OK) == 0;
            ThrowSys(exists ? "cannot open ambient file" : "cannot create ambient file", err);
        }
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
      ownerPid_(o.ownerPid_) {}

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
    const std::int64_t startPos = lastPos_;
    const std::int64_t flen = FileSize(fd_);
    if (flen < 0) ThrowSys("cannot stat ambient file", errno);
    if (flen < lastPos_) {
        appendsDisabled_ = true;
        Warn(FileLoc{path_, 0, flen}.ToString() + ": ambient file shrank below the " +
             std::to_string(lastPos_) + " bytes already read (changed by another program?); "
             "no more values will be saved to it");
        return foreign;
    }

    // Read what others appended since our last visit.
    std::vector<std::uint8_t> in(static_cast<std::size_t>(flen - lastPos_));
    const ssize_t got = ReadAt(fd_, in.data(), in.size(), lastPos_);
    if (got < 0) ThrowSys("cannot read ambient file", errno);
    in.resize(static_cast<std::size_t>(got));
    std::size_t used = 0;
    bool corrupt = false;
    while (in.size() - used >= kRecordBytes) {
        const std::span<const std::uint8_t, kRecordBytes> rec(in.data() + used, kRecordBytes);
        auto r = DecodeRecord(rec);
        if (!r) {
            corrupt = true;
            break;
        }
        foreign.push_back(*r);
        used += kRecordBytes;
    }
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
    if (lastPos_ != flen && !readOnly_) {
        // A partial record: a writer died or ran out of space mid-write. Appends are
        // whole records under this lock, so nobody is still writing it.
        if (ftruncate(fd_, static_cast<off_t>(lastPos_)) != 0) {
            lastPos_ = startPos;
            ThrowSys("cannot truncate damaged ambient file", errno);
        }
        Warn(FileLoc{path_, 0, lastPos_}.ToString() + ": removed partial ambient record (" +
             std::to_string(flen - lastPos_) + " bytes) at end of file");
    }

    if (!out.empty()) {
        if (const int err = WriteAt(fd_, out.data(), out.size(), lastPos_); err != 0) {
            // Leave only whole records behind, then report.
            const bool cleaned = ftruncate(fd_, static_cast<off_t>(lastPos_)) == 0;
            lastPos_ = startPos;  // a retry re-reads the foreign records too
            throw Error(Error::Kind::System,
                        "cannot write ambient file " + Quoted(path_) + ": " + std::strerror(err) +
                            (cleaned ? " (partial append removed; the file holds whole records)"
                                     : " (and could not remove the partial append)"));
        }
        lastPos_ += static_cast<std::int64_t>(out.size());
    }
    return foreign;
}

}  // namespace rt
