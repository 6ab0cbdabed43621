#include "progress_line.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace dgwarp::cli {

ProgressLine::ProgressLine(bool enabled) : active_(enabled && ::isatty(STDERR_FILENO) == 1) {}

ProgressLine::~ProgressLine() { clear(); }

void ProgressLine::show(const std::string& line) {
    if (!active_ || line == line_) return;
    std::string text = "\r" + line;
    if (line.size() < shown_) text += std::string(shown_ - line.size(), ' ') + "\r" + line;
    std::fputs(text.c_str(), stderr);
    std::fflush(stderr);
    shown_ = line.size();
    line_ = line;
}

void ProgressLine::phase(const std::string& text) {
    std::lock_guard lock(mutex_);
    show(text + "...");
}

void ProgressLine::fraction(const std::string& text, double f) {
    if (!active_) return;
    const int percent = static_cast<int>(std::floor(100 * std::clamp(f, 0.0, 1.0)));
    std::lock_guard lock(mutex_);
    show(text + "  " + std::to_string(percent) + "%");
}

ProgressFn ProgressLine::reporter(const std::string& text) {
    if (!active_) return {};
    return [this, text](double f) { fraction(text, f); };
}

void ProgressLine::clear() {
    std::lock_guard lock(mutex_);
    if (!active_ || shown_ == 0) return;
    std::fputs(("\r" + std::string(shown_, ' ') + "\r").c_str(), stderr);
    std::fflush(stderr);
    shown_ = 0;
    line_.clear();
}

}  // namespace dgwarp::cli
