// SPDX-License-Identifier: MIT
//
// Per-evaluation state of the function language: the value cache and its
// clock, the per-ray quantities, the modifier's real arguments, the math-error
// flag and the recursion guard. One Context per thread; a Program is shared
// read-only. This replaces calcomp's globals (eclock, errno, the ray and
// object pointers of Radiance's src/rt/func.c).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostics.h"

namespace rt::cal {

class Program;
class Evaluator;
class Parser;

/// The per-ray quantities `$1 … $N` (rtrace's are listed in cal/ray_variables.h).
/// Called at most once per channel and evaluation, because the names bound to
/// channels (Dx = $1, …) are cached variables.
class ChannelSource {
  public:
    virtual ~ChannelSource() = default;
    /// Value of channel n, 1 <= n <= Options::channelCount.
    virtual double Channel(int n) const = 0;
};

/// Radiance's math-error classes (errno EDOM / ERANGE in calcomp).
enum class MathError : std::uint8_t { None, Domain, Range };

class Context {
  public:
    explicit Context(const Program& program);

    /// Starts a new evaluation: every `=` variable is recomputed on its next
    /// use (Radiance advances its clock per (modifier, ray) pair). Also clears
    /// the math-error flag.
    void NextEvaluation() {
        ++clock_;
        calls_ = 0;
        mathError_ = MathError::None;
        errorText_.clear();
        errorWhat_.clear();
    }

    /// Where `$n` reads from. nullptr: reading a channel is an error. The source
    /// must outlive the evaluations that use it.
    void SetChannels(const ChannelSource* source) { channels_ = source; }

    /// The modifier's real arguments for arg(n) / A1…, and how to name the
    /// modifier in errors, e.g. `brightfunc "skyfunc"`. The span must outlive
    /// the evaluations that use it.
    void SetArguments(std::span<const double> args, std::string_view owner) {
        args_ = args;
        argsOwner_ = owner;
    }

    /// Receives calcomp's run-time messages ("Division by zero", "sqrt: domain
    /// error", "x: assigned non-constant value"). Unset: they are dropped (the
    /// math-error flag is still set).
    void SetWarnings(WarningSink sink) { warnings_ = std::move(sink); }

    /// At most `calls` function calls and variable computations per
    /// evaluation, then an rt::Error: a guard against exponential recursion
    /// in untrusted input (Radiance has none). Unlimited by default.
    void SetCallLimit(std::uint64_t calls) { callLimit_ = calls; }

    /// Set when a math error happened since NextEvaluation(); rtrace then
    /// skips the modifier for this ray (radiance-functions.md §11.3).
    MathError mathError() const { return mathError_; }
    /// The first math error's message, e.g. "sqrt: domain error".
    const std::string& mathErrorText() const { return errorText_; }

  private:
    friend class Evaluator;
    friend class Parser;
    friend class Program;

    // Cached value of one `=` or `:` variable slot. tick == kFrozen for a `:`
    // variable once computed; otherwise valid while tick == clock_.
    struct CacheEntry {
        double value = 0.0;
        std::uint64_t tick = 0;
    };
    static constexpr std::uint64_t kFrozen = ~std::uint64_t{0};

    std::vector<CacheEntry> cache_;  // indexed by slot
    std::uint64_t generation_ = 0;   // Program generation the cache belongs to
    std::uint64_t clock_ = 1;
    const ChannelSource* channels_ = nullptr;
    std::span<const double> args_;
    std::string argsOwner_;
    WarningSink warnings_;
    MathError mathError_ = MathError::None;
    std::string errorText_;
    std::string errorWhat_;  // first math error while folding, without its place
    // Recursion guard: the evaluation fails before the C stack goes below this
    // address (set by the outermost evaluation), and past kMaxDepth nested calls.
    const char* stackLimit_ = nullptr;
    int depth_ = 0;
    std::uint64_t calls_ = 0;
    std::uint64_t callLimit_ = ~std::uint64_t{0};
    // Parse-time folding: channels and arg() are errors, `:` values freeze
    // into the Program.
    bool folding_ = false;
};

}  // namespace rt::cal
