// SPDX-License-Identifier: MIT
//
// RT_CHECK for broken invariants (programmer errors, not user errors): prints
// the failed condition and its place, then aborts. RT_DCHECK is compiled out in
// release builds.
#pragma once

#include <cstdio>
#include <cstdlib>

#define RT_CHECK(cond)                                                              \
    do {                                                                            \
        if (!(cond)) {                                                              \
            std::fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
            std::abort();                                                           \
        }                                                                           \
    } while (false)

#ifdef NDEBUG
#define RT_DCHECK(cond) \
    do {                \
    } while (false)
#else
#define RT_DCHECK(cond) RT_CHECK(cond)
#endif
