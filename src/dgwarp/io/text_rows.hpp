#pragma once
// Writing many text rows fast: rows formatted in blocks on every thread
// (std::to_chars into a buffer per block, no stream call per number), then
// written in order, a batch of blocks at a time (memory: a few blocks per
// thread, not the whole file), each batch on a thread of its own while the
// next is formatted. The bytes are those of writing each row in
// turn, whatever the thread count. In a process forked after OpenMP ran (its
// runtime is not fork-safe), call set_num_threads(1) first, as
// run_in_child_process does.
#include <algorithm>
#include <charconv>
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "dgwarp/core/parallel_for.hpp"

namespace dgwarp {

/// A block of rows being formatted: numbers are written in place
/// (std::to_chars straight into the buffer, one capacity test per number),
/// not through a std::string append call per number. The buffer is kept
/// from block to block.
class RowText {
public:
    void clear() { at_ = 0; }
    std::string_view view() const { return {buffer_.data(), at_}; }
    /// Makes room for `n` more bytes.
    void reserve(std::size_t n) {
        if (buffer_.size() - at_ < n) buffer_.resize(std::max(buffer_.size() * 2, at_ + n));
    }
    void push_back(char c) {
        reserve(1);
        buffer_[at_++] = c;
    }
    RowText& operator+=(char c) {
        push_back(c);
        return *this;
    }
    RowText& operator+=(std::string_view s) {
        append(s);
        return *this;
    }
    void append(std::string_view s) {
        reserve(s.size());
        std::copy(s.begin(), s.end(), buffer_.data() + at_);
        at_ += s.size();
    }
    /// Writes a number: write_number's text (number_text.hpp), the shortest that reads back exactly.
    template <class Number>
    void append_number(Number value) {
        reserve(32);
        char* begin = buffer_.data() + at_;
        const auto [end, ec] = std::to_chars(begin, begin + 32, value);
        at_ += static_cast<std::size_t>(end - begin);
    }

private:
    std::string buffer_;
    std::size_t at_ = 0;
};

inline void append_number(RowText& s, double value) { s.append_number(value); }
inline void append_number(RowText& s, long long value) { s.append_number(value); }

/// Writes rows 0 .. rows-1 to `out`: row(i, text) appends row i's text to
/// `text` (a RowText). The rows are formatted in blocks on every thread,
/// a batch of blocks at a time; a batch is written to `out` on a thread of
/// its own while the next one is formatted.
template <class Row>
void write_rows(std::ostream& out, std::int64_t rows, const Row& row) {
    constexpr std::int64_t block = 16384;
    const std::int64_t batch = block * 4 * std::max(1, num_threads());
    const auto blocks_per_batch = static_cast<std::size_t>(batch / block);
    // Two sets of blocks: one formatted while the other is written.
    std::vector<RowText> formatting(blocks_per_batch), writing(blocks_per_batch);
    std::size_t written_count = 0;
    std::thread writer;
    const auto write_out = [&out, &writing, &written_count] {
        for (std::size_t b = 0; b < written_count; ++b) {
            const std::string_view text = writing[b].view();
            out.write(text.data(), static_cast<std::streamsize>(text.size()));
        }
    };
    try {
        for (std::int64_t start = 0; start < rows; start += batch) {
            const std::int64_t end = std::min(rows, start + batch);
            const auto count = static_cast<std::size_t>((end - start + block - 1) / block);
            parallel_for(
                static_cast<std::int64_t>(count),
                [&](std::int64_t b) {
                    RowText& text = formatting[static_cast<std::size_t>(b)];
                    text.clear();
                    const std::int64_t first = start + b * block, last = std::min(end, first + block);
                    text.reserve(static_cast<std::size_t>(last - first) * 48);
                    for (std::int64_t i = first; i < last; ++i) row(i, text);
                },
                1);
            if (writer.joinable()) writer.join();
            std::swap(formatting, writing);
            written_count = count;
            writer = std::thread(write_out);
        }
    } catch (...) {
        if (writer.joinable()) writer.join();
        throw;
    }
    if (writer.joinable()) writer.join();
}

}  // namespace dgwarp
