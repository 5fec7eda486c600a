#pragma once

// Whether this test program runs under AddressSanitizer (the sanitizer build of scripts/test.sh,
// a clang Debug build with ASan and UBSan, several times slower than Release): soak counts and
// CPU-time guards are sized for it. GCC says so with __SANITIZE_ADDRESS__, clang 14 by a feature.
namespace m350::test {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
#else
inline constexpr bool kSanitized = false;
#endif

} // namespace m350::test
