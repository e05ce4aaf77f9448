// Whether this test executable is built with AddressSanitizer or ThreadSanitizer (GCC's and clang's
// spellings). Those builds run about ten times slower and look for memory errors, undefined
// behaviour and races, not for wrong answers: the heaviest tests run a share of their cases there
// (the same code paths, fewer or smaller inputs), and the plain build checks every answer.
#pragma once

namespace hullkit_test {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

}  // namespace hullkit_test
