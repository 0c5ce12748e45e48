// SPDX-License-Identifier: MIT
#include "core/portable.h"

#include <cmath>

namespace rt {

void PutPortableInt(std::int64_t value, std::size_t nbytes, std::uint8_t* out) {
    const auto u = static_cast<std::uint64_t>(value);  // two's complement bits
    for (std::size_t i = 0; i < nbytes; ++i) {
        out[i] = static_cast<std::uint8_t>(u >> (8 * (nbytes - 1 - i)));
    }
}

std::int64_t GetPortableInt(const std::uint8_t* in, std::size_t nbytes) {
    // Sign-extend the first byte, then shift the rest in (unsigned arithmetic, so no UB
    // on the shifts of negative values).
    std::uint64_t r = (in[0] & 0x80) ? (~std::uint64_t{0} << 8) | in[0] : in[0];
    for (std::size_t i = 1; i < nbytes; ++i) r = (r << 8) | in[i];
    return static_cast<std::int64_t>(r);
}

void PutPortableFloat(double f, std::uint8_t* out) {
    constexpr double kMantissaScale = 2147483647.0;  // 0x7fffffff
    std::int64_t m = 0;
    int e = 0;
    if (std::isnan(f)) {
        m = 0x7fffffff;
        e = 127;
    } else if (std::isinf(f)) {
        m = f > 0 ? 0x7fffffff : -0x7fffffff;
        e = 127;
    } else {
        // |frexp| < 1, so the product fits in 32 bits; the cast truncates toward zero
        // exactly as C's assignment to long does in putflt().
        m = static_cast<std::int64_t>(std::frexp(f, &e) * kMantissaScale);
        if (e > 127) {
            m = m > 0 ? 0x7fffffff : -0x7fffffff;
            e = 127;
        } else if (e < -128) {
            m = 0;
            e = 0;
        }
    }
    PutPortableInt(m, 4, out);
    PutPortableInt(e, 1, out + 4);
}

double GetPortableFloat(const std::uint8_t* in) {
    const std::int64_t l = GetPortableInt(in, 4);
    if (l == 0) return 0.0;  // the exponent byte is ignored, as getflt() does
    // Multiply by the reciprocal (not divide) to round exactly as getflt() does.
    const double d = (static_cast<double>(l) + (l > 0 ? 0.5 : -0.5)) * (1.0 / 2147483647.0);
    return std::ldexp(d, static_cast<int>(GetPortableInt(in + 4, 1)));
}

}  // namespace rt
