// SPDX-License-Identifier: MIT
#include "tests/ambfiles/stress.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <span>
#include <thread>
#include <vector>

#include "ambfiles/record_codec.h"
#include "ambfiles/shared_file.h"
#include "core/error.h"

namespace rt::testing {
namespace {

// Log entries: a record id (>= 0) once its Sync() returned, or an event.
constexpr std::int64_t kEventTornTailCut = -1;
constexpr std::int64_t kEventFullDisk = -2;
constexpr std::int64_t kEventDyingInShortWrite = -3;

/// Exit status of a writer that hit an unexpected error.
constexpr int kWriterFailed = 3;

std::int64_t IdFor(int writer, int seq) { return std::int64_t{writer} * 1000000 + seq; }

/// A valid record whose position carries its id (x = writer, y = sequence).
AmbientRecord Tagged(int writer, int seq) {
    AmbientRecord r;
    r.position = {static_cast<double>(writer), static_cast<double>(seq), 0.5};
    r.normal = Normalize(Vec3(0.01 * (writer % 50), 0.3, 1));
    r.uAxis = Normalize(Cross(Vec3(1, 0, 0), r.normal));
    r.value = Rgb(0.25, 0.5, 0.125);
    r.radius[0] = r.radius[1] = 0.5;
    r.level = writer % 4;
    r.weight = 0.5;
    r.corral = static_cast<std::uint32_t>(seq);
    return r;
}

std::int64_t IdOf(const AmbientRecord& r) {
    return IdFor(static_cast<int>(r.position.x), static_cast<int>(r.position.y));
}

std::string LogPath(const StressConfig& c, int writer) {
    return c.directory + "/writer." + std::to_string(writer) + ".log";
}

std::string FilePath(const StressConfig& c) { return c.directory + "/stress.amb"; }

/// Writers with certain faults (StressConfig::certainFaultsEvery).
bool HasCertainFault(const StressConfig& c, int writer) {
    return c.certainFaultsEvery > 0 && writer % c.certainFaultsEvery == 0;
}
bool CertainFaultIsDeath(const StressConfig& c, int writer) {
    return HasCertainFault(c, writer) && (writer / c.certainFaultsEvery) % 2 == 1;
}

AmbientHeaderParams Params() {
    AmbientHeaderParams p;
    p.bounces = 1;
    p.octreeName = "stress.oct";
    p.software = "lazyrad ambient-file stress test";
    return p;
}

/// One writer process; never returns.
[[noreturn]] void Writer(const StressConfig& c, int writer) {
    int rc = 0;
    try {
        const int log = open(LogPath(c, writer).c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
        if (log < 0) _exit(kWriterFailed);
        auto note = [log](const std::vector<std::int64_t>& entries) {
            const auto bytes = entries.size() * sizeof(std::int64_t);
            if (write(log, entries.data(), bytes) != static_cast<ssize_t>(bytes)) {
                _exit(kWriterFailed);
            }
        };
        std::mt19937_64 rng(c.seed * 7919 + static_cast<std::uint64_t>(writer));
        std::uniform_real_distribution<double> uniform(0, 1);
        SharedAmbientFile file(FilePath(c), Params(), [&](const std::string& w) {
            if (w.find("removed partial ambient record") != std::string::npos) {
                note({kEventTornTailCut});
            }
        });
        SharedAmbientFile::WriteFaults faults;
        bool dieInShortWrite = false;
        bool certainFaultDue = HasCertainFault(c, writer);
        faults.keepBytes = [&](std::size_t n) -> std::size_t {
            if (certainFaultDue) {
                certainFaultDue = false;
                dieInShortWrite = CertainFaultIsDeath(c, writer);
                return n / 2;
            }
            if (uniform(rng) >= c.shortWriteChance) return n;
            dieInShortWrite = uniform(rng) < 0.5;
            return static_cast<std::size_t>(uniform(rng) * static_cast<double>(n));
        };
        faults.afterShortWrite = [&] {
            if (!dieInShortWrite) return;
            note({kEventDyingInShortWrite});
            raise(SIGKILL);
        };
        file.InjectWriteFaults(faults);
        (void)file.LoadAll();
        std::vector<AmbientRecord> unsynced;
        int seq = 0, synced = 0;
        while (synced < c.recordsPerWriter) {
            const int batch = 1 + static_cast<int>(uniform(rng) * SharedAmbientFile::kSyncInterval);
            for (int i = 0; i < batch && seq < c.recordsPerWriter; ++i) {
                unsynced.push_back(Tagged(writer, seq++));
            }
            try {
                (void)file.Sync(unsynced);
            } catch (const Error&) {
                note({kEventFullDisk});  // the records stay unsynced and are retried
                continue;
            }
            std::vector<std::int64_t> ids;
            for (const AmbientRecord& r : unsynced) ids.push_back(IdOf(r));
            note(ids);
            synced += static_cast<int>(unsynced.size());
            unsynced.clear();
            std::this_thread::sleep_for(std::chrono::microseconds(
                static_cast<int>(uniform(rng) * 2000)));
        }
        close(log);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "writer %d: %s\n", writer, e.what());
        rc = kWriterFailed;
    }
    _exit(rc);
}

}  // namespace

std::string StressResult::ToString() const {
    char buf[640];
    std::snprintf(buf, sizeof buf,
                  "%d writers (%d SIGKILLed by the driver, %d died inside a short write, %d "
                  "short writes failed as a full disk, %d other failures); %zu records synced, "
                  "%zu in the file; missing %zu, invalid %zu, duplicated %zu, trailing bytes "
                  "%zu; %zu torn tails cut; %.1f s",
                  writers, killedByDriver, diedInShortWrite, fullDiskErrors, otherFailures,
                  syncedRecords, recordsInFile, missing, invalid, duplicates, trailingBytes,
                  tornTailsCut, seconds);
    return buf;
}

StressResult RunAmbientFileStress(const StressConfig& c) {
    const auto start = std::chrono::steady_clock::now();
    StressResult result;
    { SharedAmbientFile create(FilePath(c), Params(), {}); }

    std::mt19937_64 rng(c.seed);
    std::uniform_real_distribution<double> uniform(0, 1);
    std::set<pid_t> running;
    std::set<pid_t> spared;  // never SIGKILLed by the driver
    std::set<pid_t> killed;
    int started = 0;
    auto reap = [&](bool block) {
        for (;;) {
            int st = 0;
            const pid_t pid = waitpid(-1, &st, block ? 0 : WNOHANG);
            if (pid <= 0) return;
            running.erase(pid);
            spared.erase(pid);
            const bool ours = killed.erase(pid) > 0;
            if (WIFEXITED(st) && WEXITSTATUS(st) != 0) ++result.otherFailures;
            if (WIFSIGNALED(st) && WTERMSIG(st) != SIGKILL) ++result.otherFailures;
            if (WIFSIGNALED(st) && WTERMSIG(st) == SIGKILL && ours) ++result.killedByDriver;
            if (block) return;
        }
    };
    constexpr double kTickSeconds = 0.001;
    while (started < c.totalWriters || !running.empty()) {
        while (started < c.totalWriters && static_cast<int>(running.size()) < c.concurrentWriters) {
            std::fflush(nullptr);
            const pid_t pid = fork();
            if (pid < 0) throw Error(Error::Kind::System, "stress test: fork failed");
            if (pid == 0) Writer(c, started);
            running.insert(pid);
            if (HasCertainFault(c, started)) spared.insert(pid);
            ++started;
        }
        std::this_thread::sleep_for(std::chrono::duration<double>(kTickSeconds));
        if (!running.empty() && uniform(rng) < c.killsPerSecond * kTickSeconds) {
            auto it = running.begin();
            std::advance(it, static_cast<long>(uniform(rng) * static_cast<double>(running.size())));
            if (!spared.contains(*it) && killed.insert(*it).second) kill(*it, SIGKILL);
        }
        reap(false);
    }
    result.writers = started;

    // The final sync: cuts a torn tail the last writer to die may have left.
    std::size_t tornTails = 0;
    {
        SharedAmbientFile last(FilePath(c), Params(), [&](const std::string& w) {
            if (w.find("removed partial ambient record") != std::string::npos) ++tornTails;
        });
        (void)last.LoadAll();
        (void)last.Sync({});
    }
    result.tornTailsCut += tornTails;

    // What the writers logged.
    std::set<std::int64_t> synced;
    for (int w = 0; w < started; ++w) {
        std::ifstream in(LogPath(c, w), std::ios::binary);
        for (std::int64_t v; in.read(reinterpret_cast<char*>(&v), sizeof v);) {
            if (v >= 0) synced.insert(v);
            if (v == kEventFullDisk) ++result.fullDiskErrors;
            if (v == kEventDyingInShortWrite) ++result.diedInShortWrite;
            if (v == kEventTornTailCut) ++result.tornTailsCut;
        }
    }
    result.syncedRecords = synced.size();

    // What the file holds, slot by slot.
    std::ifstream in(FilePath(c), std::ios::binary);
    const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in),
                                          std::istreambuf_iterator<char>()};
    const HeaderParse header = ParseAmbientHeader(bytes);
    if (!header.header) {
        result.invalid = 1;
        return result;
    }
    std::map<std::int64_t, int> count;
    std::size_t at = header.header->recordsOffset;
    for (; at + kRecordBytes <= bytes.size(); at += kRecordBytes) {
        const auto r = DecodeRecord(
            std::span<const std::uint8_t, kRecordBytes>(bytes.data() + at, kRecordBytes));
        if (!r) {
            ++result.invalid;
            continue;
        }
        ++result.recordsInFile;
        if (++count[IdOf(*r)] == 2) ++result.duplicates;
    }
    result.trailingBytes = bytes.size() - at;
    for (const std::int64_t id : synced) result.missing += count.count(id) == 0;
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace rt::testing
