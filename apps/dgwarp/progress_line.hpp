#pragma once
// A one-line progress display on the terminal (standard error): the phase
// being worked on and, when known, how far it is. Silent when standard error
// is not a terminal or when the user asked for --quiet / --json, so scripts
// and logs never see it. The only progress code of the project.
#include <mutex>
#include <string>

#include "dgwarp/core/progress.hpp"

namespace dgwarp::cli {

class ProgressLine {
public:
    /// enabled: false forces silence (e.g. --quiet); otherwise the line shows
    /// only when standard error is a terminal.
    explicit ProgressLine(bool enabled);
    ~ProgressLine();
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    /// Whether anything is shown (enabled and standard error is a terminal).
    bool active() const { return active_; }

    /// Shows "phase..." (replacing the previous phase).
    void phase(const std::string& text);
    /// Shows "phase  42%" for a fraction f in [0, 1]; redraws only when the
    /// shown percentage (or the phase) changes. Thread-safe, like every member.
    void fraction(const std::string& text, double f);
    /// A ProgressFn for library calls that shows fraction(text, f); empty
    /// (so the library skips its reporting) when the line is not active.
    ProgressFn reporter(const std::string& text);
    /// Clears the line (also done by the destructor).
    void clear();

private:
    void show(const std::string& line);  // with mutex_ held
    bool active_;
    std::mutex mutex_;
    std::size_t shown_ = 0;  // characters on the line now
    std::string line_;       // the line shown now
};

}  // namespace dgwarp::cli
