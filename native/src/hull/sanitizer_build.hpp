// HULLKIT_SANITIZED is defined when this translation unit is built with AddressSanitizer or
// ThreadSanitizer (GCC's and clang's spellings): large_array.hpp then maps no memory by hand, and
// the tests (tests/sanitized.hpp) run a share of their heaviest cases.
#pragma once

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define HULLKIT_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define HULLKIT_SANITIZED 1
#endif
#endif
