// write_rows: rows formatted in blocks on every thread and written by a
// thread of their own, batch after batch: the bytes of writing each row in
// turn, whatever the thread count and however many batches.
#include "dgwarp/io/text_rows.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <sstream>
#include <string>

#include "dgwarp/core/parallel_for.hpp"

using namespace dgwarp;

namespace {

double row_value(std::int64_t i) { return std::sin(0.001 * static_cast<double>(i)) * std::pow(10.0, static_cast<double>(i % 40 - 20)); }

/// Row i as the slow, obvious code writes it.
std::string expected_row(std::int64_t i) {
    char buf[64];
    std::string s;
    s += std::to_string(i);
    s += '\t';
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, row_value(i));
    s.append(buf, end);
    s += (i % 7 == 0 ? " (seventh)" : "");
    s += '\n';
    return s;
}

}  // namespace

TEST(TextRows, ManyBatchesOnOneTwoAndThreeThreadsWriteTheRowsInTurn) {
    const std::int64_t rows = 300'001;  // more than two batches of 16384 x 4 x 3 rows, and a partial one
    std::string expected;
    for (std::int64_t i = 0; i < rows; ++i) expected += expected_row(i);
    const int before = num_threads();
    for (int threads : {1, 2, 3}) {
        set_num_threads(threads);
        std::ostringstream out;
        write_rows(out, rows, [](std::int64_t i, RowText& text) {
            append_number(text, static_cast<long long>(i));
            text += '\t';
            append_number(text, row_value(i));
            if (i % 7 == 0) text += " (seventh)";
            text.push_back('\n');
        });
        EXPECT_EQ(out.str(), expected) << threads << " threads";
    }
    set_num_threads(before);
}

TEST(TextRows, NoRowsWriteNothingAndAnErrorInARowReachesTheCaller) {
    std::ostringstream out;
    write_rows(out, 0, [](std::int64_t, RowText& text) { text += 'x'; });
    EXPECT_TRUE(out.str().empty());
    EXPECT_THROW(write_rows(out, 200'000,
                            [](std::int64_t i, RowText& text) {
                                if (i == 150'000) throw std::runtime_error("row 150000");
                                text += 'x';
                            }),
                 std::runtime_error);
}
