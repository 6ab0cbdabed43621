#pragma once
// Whether the command's operator new (large_blocks.cpp) is in the program:
// not under the sanitizers, which replace operator new themselves, and on
// Linux only. DGWARP_LARGE_BLOCKS is 1 where it is, 0 elsewhere; the check
// program (tests/apps/large_blocks_check.cpp) reads it too.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define DGWARP_NO_LARGE_BLOCKS 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define DGWARP_NO_LARGE_BLOCKS 1
#endif
#endif

#if defined(__linux__) && !defined(DGWARP_NO_LARGE_BLOCKS)
#define DGWARP_LARGE_BLOCKS 1
#else
#define DGWARP_LARGE_BLOCKS 0
#endif
