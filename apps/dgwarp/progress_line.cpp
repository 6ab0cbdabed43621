#include "progress_line.hpp"

#include <unistd.h>

#include <cstdio>

namespace dgwarp::cli {

ProgressLine::ProgressLine(bool enabled) : active_(enabled && ::isatty(STDERR_FILENO) == 1) {}

ProgressLine::~ProgressLine() { clear(); }

void ProgressLine::show(const std::string& line) {
    if (!active_) return;
    std::string text = "\r" + line;
    if (line.size() < shown_) text += std::string(shown_ - line.size(), ' ') + "\r" + line;
    std::fputs(text.c_str(), stderr);
    std::fflush(stderr);
    shown_ = line.size();
}

void ProgressLine::phase(const std::string& text) { show(text + "..."); }

void ProgressLine::step(const std::string& text, std::size_t done, std::size_t total) {
    show(text + "  " + std::to_string(done) + "/" + std::to_string(total));
}

void ProgressLine::clear() {
    if (!active_ || shown_ == 0) return;
    std::fputs(("\r" + std::string(shown_, ' ') + "\r").c_str(), stderr);
    std::fflush(stderr);
    shown_ = 0;
}

}  // namespace dgwarp::cli
