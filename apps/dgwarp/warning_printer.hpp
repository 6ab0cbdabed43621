#pragma once
// Warnings on standard error, each printed once. The motion's check warns
// about every frame of a frame list, and resolving each frame warns again;
// a step warning can repeat in every frame of a series: only the first of
// equal texts is printed. The JSON reports keep every warning where it arose.
#include <set>
#include <string>

namespace dgwarp::cli {

class WarningPrinter {
public:
    /// enabled: false prints nothing (--quiet, --json).
    explicit WarningPrinter(bool enabled) : enabled_(enabled) {}

    /// Prints "warning: <where><text>" unless `text` was printed before.
    void print(const std::string& text, const std::string& where = "");

private:
    bool enabled_;
    std::set<std::string> printed_;
};

}  // namespace dgwarp::cli
