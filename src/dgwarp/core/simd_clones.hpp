#pragma once
// DGWARP_SIMD_CLONES on a function compiles it for AVX-512, AVX2 and the
// baseline x86-64 ISA (SSE2); the loader picks the best one the CPU has
// (GCC function multiversioning). The project builds without -march=native,
// so this is how a hot, vectorisable loop gets wide registers. GCC only: the
// kernels that use it are templates, and Clang (14, the fuzz build) does not
// multiversion function templates.
//
// Results do not depend on the clone as long as the file is compiled with
// -ffp-contract=off (no fused multiply-adds; see CMakeLists.txt): vector lanes
// then round every operation exactly as the scalar code does. Elsewhere
// (Clang, other compilers, other architectures) the macro is empty.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__has_attribute)
#if __has_attribute(target_clones)
#define DGWARP_SIMD_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#endif
#endif
#ifndef DGWARP_SIMD_CLONES
#define DGWARP_SIMD_CLONES
#endif
