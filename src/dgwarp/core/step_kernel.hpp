#pragma once
// Per-node step kernels compiled twice: DG-IDW's and DG-harmonic's steps
// (methods/*_step_kernel.inc) are included once as the project is compiled
// (SSE2, the x86-64 baseline) and once under `#pragma GCC target("avx2")`,
// and the step takes the AVX2 copy where the processor has it. The copies
// add up a node's corner data two (SSE2) or four (AVX2) components at a time
// with GCC's vector extensions, each component with the multiplications and
// additions of the scalar loop in the same order; AVX2 alone has no fused
// multiply-add, so both copies give the same bits (tests compare them).
// The baseline methods' kernels use DGWARP_SIMD_CLONES (simd_clones.hpp)
// instead: their loops vectorise by themselves, these gather per node.

namespace dgwarp {

/// Which compiled copy of a step kernel runs: `automatic` takes the AVX2
/// copy where the processor has AVX2; `baseline` always the SSE2 one (for
/// the tests that compare the two).
enum class StepKernel { automatic, baseline };

/// Whether this processor has AVX2 (false off x86-64).
bool cpu_has_avx2();

/// The instruction set a copy of a kernel is compiled for (its template argument).
enum class Isa { sse2, avx2 };

/// Two and four doubles in one register (GCC and Clang vector extensions).
using Pair = double __attribute__((vector_size(16)));
using Quad = double __attribute__((vector_size(32)));

}  // namespace dgwarp
