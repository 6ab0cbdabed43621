#pragma once
#include <algorithm>
#include <exception>
#include <mutex>

namespace dgwarp {

template <class Body>
void parallel_for(std::int64_t n, Body&& body) {
    std::exception_ptr error;
    std::mutex error_mutex;
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < n; ++i) {
        try {
            body(i);
        } catch (...) {
            std::lock_guard lock(error_mutex);
            if (!error) error = std::current_exception();
        }
    }
    if (error) std::rethrow_exception(error);
}

template <class Body>
void parallel_for_chunks(std::int64_t n, Body&& body) {
    const std::int64_t chunks = n <= 0 ? 0 : std::min<std::int64_t>(num_threads(), n);
    parallel_for(chunks, [&](std::int64_t c) {
        body(n * c / chunks, n * (c + 1) / chunks);
    });
}

}  // namespace dgwarp
