#pragma once
// DYNANAV_GLIBC_HEAP is 1 where glibc's heap figures (mallinfo2, malloc_trim) describe this
// process's allocations: with glibc, and not under AddressSanitizer, whose own allocator serves
// malloc. Tests of resident or heap memory skip elsewhere.
#include <cstdlib>  // defines __GLIBC__ where glibc is the C library

#if defined(__SANITIZE_ADDRESS__)
#define DYNANAV_SANITIZED_HEAP 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define DYNANAV_SANITIZED_HEAP 1
#endif
#endif

#if defined(__GLIBC__) && !defined(DYNANAV_SANITIZED_HEAP)
#define DYNANAV_GLIBC_HEAP 1
#else
#define DYNANAV_GLIBC_HEAP 0
#endif
