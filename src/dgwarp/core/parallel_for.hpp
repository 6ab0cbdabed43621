#pragma once
// The one parallel-loop helper of the project (OpenMP underneath). Algorithms
// call parallel_for and never use OpenMP directly, so there are no #ifdef forks
// in their bodies. Iterations are split statically: with a per-index body that
// writes only its own outputs, results never depend on the thread count.
#include <cstdint>

namespace dgwarp {

/// Loops shorter than this run on the calling thread (by default): starting a
/// parallel region costs microseconds, and far more when other processes hold
/// the cores (OpenMP threads then wait for a core), which dwarfs a short loop.
inline constexpr std::int64_t parallel_grain = 4096;

/// Number of threads parallel_for uses (OpenMP's current setting; 1 without OpenMP).
int num_threads();

/// The cores this process may run on (OpenMP's count, which honours the CPU
/// affinity mask; at least 1).
int available_cores();

/// The most threads set_num_threads sets: 4 × available_cores(), and at least 64. More threads than cores never make a loop faster (a
/// few times more can check that results do not depend on the thread count);
/// tens of thousands make OpenMP fail to start them, which ends the program.
int max_threads();

/// Sets the number of threads for later parallel_for calls: n clamped to
/// [1, max_threads()].
void set_num_threads(int n);

/// Calls body(i) for every i in [0, n), in parallel. body must only write data
/// owned by index i. Exceptions thrown by body are rethrown (the first one).
/// Loops shorter than `grain` run on the calling thread: the default suits a
/// cheap body (one node); pass 1 when each index is a block of real work.
template <class Body>
void parallel_for(std::int64_t n, Body&& body, std::int64_t grain = parallel_grain);

/// Calls body(begin, end) on contiguous chunks covering [0, n), one chunk per
/// thread at most; useful when each chunk needs scratch space.
template <class Body>
void parallel_for_chunks(std::int64_t n, Body&& body);

/// Calls body(begin, end) on blocks of `block` indices covering [0, n),
/// handed to the threads as they become free: for loops whose cost per index
/// varies along the range (one contiguous chunk per thread would leave one
/// thread waiting). With a body that writes only its own indices, results do
/// not depend on the thread count. One thread, or one block: a single call.
template <class Body>
void parallel_for_blocks(std::int64_t n, std::int64_t block, Body&& body);
/// Calls body(i, state) for every i in [0, n) on the threads, each followed,
/// on the same thread, by in_order(i, state) in the order of i (in_order(i)
/// starts once in_order(i - 1) has returned): for results made in parallel
/// and consumed in sequence, such as text formatted in blocks and written
/// out in turn, each block by the thread that formatted it (the bytes never
/// move to another core's cache). Each thread has a `State` of its own
/// (default-constructed; kept from index to index), which body fills and
/// in_order reads. Indices are handed out round-robin, one at a time. The
/// first exception is rethrown; after one, the calls still due are skipped.
template <class State, class Body, class InOrder>
void parallel_for_ordered(std::int64_t n, Body&& body, InOrder&& in_order);
/// Calls a() and b() at the same time, on two threads, when parallel_for may
/// use two or more; one after the other (a first) otherwise. For a serial
/// stage (a) and independent work that can be done beside it (b); a
/// parallel_for inside either runs on its own thread alone. Exceptions are
/// rethrown after both have finished (a's first).
template <class A, class B>
void run_concurrently(A&& a, B&& b);
/// Calls a() here, with every thread for its loops, and b() at the same
/// time on a thread of its own whose loops run on it alone: for a stage
/// that is mostly serial (a) and independent work (b) that fills the cores
/// its serial parts leave idle, without taking a()'s parallel parts to one
/// thread as run_concurrently does. With one thread, a() then b().
/// Exceptions are rethrown after both have finished (a's first).
template <class A, class B>
void run_beside(A&& a, B&& b);

}  // namespace dgwarp

#include "dgwarp/core/parallel_for_impl.hpp"
