#pragma once
// A one-line progress display on the terminal (standard error): the phase
// being worked on and, when known, how far it is. Silent when standard error
// is not a terminal or when the user asked for --quiet / --json, so scripts
// and logs never see it. The only progress code of the project.
#include <string>

namespace dgwarp::cli {

class ProgressLine {
public:
    /// enabled: false forces silence (e.g. --quiet); otherwise the line shows
    /// only when standard error is a terminal.
    explicit ProgressLine(bool enabled);
    ~ProgressLine();
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    /// Shows "phase..." (replacing the previous phase).
    void phase(const std::string& text);
    /// Shows "phase  done/total" (e.g. frames).
    void step(const std::string& text, std::size_t done, std::size_t total);
    /// Clears the line (also done by the destructor).
    void clear();

private:
    void show(const std::string& line);
    bool active_;
    std::size_t shown_ = 0;  // characters on the line now
};

}  // namespace dgwarp::cli
