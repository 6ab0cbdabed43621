#pragma once
// Writing many text rows fast: rows formatted in blocks on every thread
// (std::to_chars into a string per block, no stream call per number), then
// written in order, a batch of blocks at a time (memory: a few blocks per
// thread, not the whole file). The bytes are those of writing each row in
// turn, whatever the thread count. In a process forked after OpenMP ran (its
// runtime is not fork-safe), call set_num_threads(1) first, as
// run_in_child_process does.
#include <algorithm>
#include <charconv>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "dgwarp/core/parallel_for.hpp"

namespace dgwarp {

/// Appends write_number's text of `value` to `s`.
inline void append_number(std::string& s, double value) {
    char buf[32];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
    s.append(buf, end);
}
inline void append_number(std::string& s, long long value) {
    char buf[24];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
    s.append(buf, end);
}

/// Writes rows 0 .. rows-1 to `out`: row(i, text) appends row i's text.
template <class Row>
void write_rows(std::ostream& out, std::int64_t rows, const Row& row) {
    constexpr std::int64_t block = 16384;
    const std::int64_t batch = block * 4 * std::max(1, num_threads());
    std::vector<std::string> texts;
    for (std::int64_t start = 0; start < rows; start += batch) {
        const std::int64_t end = std::min(rows, start + batch);
        texts.assign(static_cast<std::size_t>((end - start + block - 1) / block), std::string());
        parallel_for(
            static_cast<std::int64_t>(texts.size()),
            [&](std::int64_t b) {
                std::string& text = texts[static_cast<std::size_t>(b)];
                const std::int64_t first = start + b * block, last = std::min(end, first + block);
                text.reserve(static_cast<std::size_t>(last - first) * 48);
                for (std::int64_t i = first; i < last; ++i) row(i, text);
            },
            1);
        for (const std::string& text : texts) out.write(text.data(), static_cast<std::streamsize>(text.size()));
    }
}

}  // namespace dgwarp
