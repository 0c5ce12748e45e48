// SPDX-License-Identifier: MIT
//
// Small, fast, seedable random number generator (PCG32, O'Neill 2014) held by
// value: every Renderer owns one and reseeds it per input ray, so results do
// not depend on scheduling (no global state, unlike Radiance's drand48()).
#pragma once

#include <cstdint>

namespace rt {

class Rng {
public:
    explicit Rng(std::uint64_t seed = 0x853c49e6748fea9bULL, std::uint64_t stream = 0) {
        Seed(seed, stream);
    }

    void Seed(std::uint64_t seed, std::uint64_t stream = 0) {
        state_ = 0;
        inc_ = (stream << 1u) | 1u;
        Next();
        state_ += seed;
        Next();
    }

    std::uint32_t Next() {
        std::uint64_t old = state_;
        state_ = old * 6364136223846793005ULL + inc_;
        auto xorshifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        auto rot = static_cast<std::uint32_t>(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((~rot + 1u) & 31u));
    }

    /// Uniform in [0, 1) with 53 random bits.
    double Uniform() {
        std::uint64_t hi = Next() >> 5;   // 27 bits
        std::uint64_t lo = Next() >> 6;   // 26 bits
        return static_cast<double>((hi << 26) | lo) * (1.0 / 9007199254740992.0);
    }

private:
    std::uint64_t state_ = 0;
    std::uint64_t inc_ = 1;
};

/// Mixes two 64-bit values into a well-distributed seed (splitmix64 finaliser).
/// MixSeed(z, 0) is splitmix64's output for state z: a hash of one value.
inline std::uint64_t MixSeed(std::uint64_t a, std::uint64_t b) {
    std::uint64_t z = a + 0x9e3779b97f4a7c15ULL * (b + 1);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

}  // namespace rt
