// flowsurf — typed errors (public: include/flowsurf/errors.h). Library code throws them;
// front ends catch them once in main() and map each type to a distinct exit code
// (apps/flowsurf/exit_codes.h). And the invariant check for what input cannot cause.
#pragma once

#include <flowsurf/errors.h>

// Invariant check: prints both sides and aborts. Never for user input.
#define FLOWSURF_CHECK(cond)                                                          \
    do {                                                                              \
        if (!(cond)) ::flowsurf::detail::checkFailed(#cond, __FILE__, __LINE__);      \
    } while (0)

namespace flowsurf::detail {
[[noreturn]] void checkFailed(const char* expr, const char* file, int line);
}
