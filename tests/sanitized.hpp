// Whether this test executable is built with AddressSanitizer or ThreadSanitizer (the core's
// HULLKIT_SANITIZED, native/src/hull/sanitizer_build.hpp). Those builds run about ten times slower
// and look for memory errors, undefined behaviour and races, not for wrong answers: the heaviest
// tests run a share of their cases there (the same code paths, fewer or smaller inputs), and the
// plain build checks every answer.
#pragma once

#include "hull/sanitizer_build.hpp"

namespace hullkit_test {

#ifdef HULLKIT_SANITIZED
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif

}  // namespace hullkit_test
