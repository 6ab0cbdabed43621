#pragma once
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

namespace dgwarp {


namespace detail {

// Keeps the first exception thrown by the bodies of a parallel loop, to
// rethrow it after the loop (exceptions must not leave an OpenMP region).
class FirstError {
public:
    template <class F>
    void run(F&& f) {
        try {
            f();
        } catch (...) {
            std::lock_guard lock(mutex_);
            if (!error_) error_ = std::current_exception();
        }
    }
    void rethrow() const {
        if (error_) std::rethrow_exception(error_);
    }

private:
    std::exception_ptr error_;
    std::mutex mutex_;
};

// body(i) for i in [0, n) in one OpenMP region, iterations split statically;
// the first exception is rethrown after the region.
template <class Body>
void parallel_region_for(std::int64_t n, Body&& body) {
    FirstError error;
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < n; ++i) error.run([&] { body(i); });
    error.rethrow();
}

// The same with blocks handed out to the threads as they finish (dynamic
// schedule), for bodies whose cost varies along the range.
template <class Body>
void parallel_region_for_dynamic(std::int64_t n, Body&& body) {
    FirstError error;
#pragma omp parallel for schedule(dynamic)
    for (std::int64_t i = 0; i < n; ++i) error.run([&] { body(i); });
    error.rethrow();
}

}  // namespace detail

template <class Body>
void parallel_for(std::int64_t n, Body&& body, std::int64_t grain) {
    if (n < grain || n < 2 || num_threads() == 1) {
        for (std::int64_t i = 0; i < n; ++i) body(i);
        return;
    }
    detail::parallel_region_for(n, body);
}

template <class Body>
void parallel_for_chunks(std::int64_t n, Body&& body) {
    if (n <= 0) return;
    const std::int64_t chunks = n < parallel_grain ? 1 : std::min<std::int64_t>(num_threads(), n);
    if (chunks == 1) return body(std::int64_t{0}, n);
    detail::parallel_region_for(chunks, [&](std::int64_t c) { body(n * c / chunks, n * (c + 1) / chunks); });
}

template <class Body>
void parallel_for_blocks(std::int64_t n, std::int64_t block, Body&& body) {
    if (n <= 0) return;
    block = std::max<std::int64_t>(block, 1);
    const std::int64_t blocks = (n + block - 1) / block;
    if (blocks == 1 || num_threads() == 1) return body(std::int64_t{0}, n);
    detail::parallel_region_for_dynamic(blocks, [&](std::int64_t b) { body(b * block, std::min(n, (b + 1) * block)); });
}

template <class State, class Body, class InOrder>
void parallel_for_ordered(std::int64_t n, Body&& body, InOrder&& in_order) {
    if (n < 2 || num_threads() == 1) {
        State state;
        for (std::int64_t i = 0; i < n; ++i) {
            body(i, state);
            in_order(i, state);
        }
        return;
    }
    detail::FirstError error;
    std::atomic<bool> failed{false};
    const auto guarded = [&](auto&& f) {
        if (failed.load(std::memory_order_relaxed)) return;
        bool ok = false;
        error.run([&] {
            f();
            ok = true;
        });
        if (!ok) failed.store(true, std::memory_order_relaxed);
    };
#pragma omp parallel
    {
        State state;
#pragma omp for ordered schedule(static, 1)
        for (std::int64_t i = 0; i < n; ++i) {
            guarded([&] { body(i, state); });
#pragma omp ordered
            guarded([&] { in_order(i, state); });
        }
    }
    error.rethrow();
}

template <class A, class B>
void run_concurrently(A&& a, B&& b) {
    detail::FirstError error_a, error_b;
    if (num_threads() < 2) {
        error_a.run(a);
        error_b.run(b);
    } else {
#pragma omp parallel for schedule(static, 1) num_threads(2)
        for (int task = 0; task < 2; ++task) {
            if (task == 0) error_a.run(a);
            else error_b.run(b);
        }
    }
    error_a.rethrow();
    error_b.rethrow();
}

template <class A, class B>
void run_beside(A&& a, B&& b) {
    detail::FirstError error_a, error_b;
    if (num_threads() < 2) {
        error_a.run(a);
        error_b.run(b);
    } else {
        std::thread beside([&] {
            set_num_threads(1);  // this thread's loops only (OpenMP's setting is per thread)
            error_b.run(b);
        });
        error_a.run(a);
        beside.join();
    }
    error_a.rethrow();
    error_b.rethrow();
}

}  // namespace dgwarp
