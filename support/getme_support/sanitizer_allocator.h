#pragma once

// Whether a sanitizer's allocator serves malloc in this build (AddressSanitizer and
// ThreadSanitizer replace it): then glibc's heap counts say nothing and mallopt's settings do not
// apply. GCC defines __SANITIZE_ADDRESS__ / __SANITIZE_THREAD__; clang answers __has_feature.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define GETME_SANITIZER_ALLOCATOR 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define GETME_SANITIZER_ALLOCATOR 1
#endif
#endif

namespace getme {

#if defined(GETME_SANITIZER_ALLOCATOR)
inline constexpr bool kSanitizerAllocator = true;
#else
inline constexpr bool kSanitizerAllocator = false;
#endif

}  // namespace getme
