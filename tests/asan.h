#pragma once
// GRANOTA_TEST_ASAN is defined when the tests are built with AddressSanitizer (the sanitize
// preset; GCC says __SANITIZE_ADDRESS__, clang __has_feature). Address-space limits
// (`ulimit -v`) do not work there — ASan's shadow memory reserves terabytes of address
// space — so the tests that use them leave the limit out and keep their assertions.
#if defined(__SANITIZE_ADDRESS__)
#define GRANOTA_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define GRANOTA_TEST_ASAN 1
#endif
#endif
