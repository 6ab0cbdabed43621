#pragma once
// The DG-IDW paper's figures (Tables 1-10 and section 6), which `dgwarp
// bench` prints beside its own.
#include <array>
#include <optional>
#include <string>

#include "dgwarp/methods/method.hpp"

namespace dgwarp {

/// One method's figures in the paper; unset = not given.
struct PaperFigures {
    std::optional<double> mean, min, seconds;
    bool failed = false;   // the paper's "-": no valid mesh
    bool not_run = false;  // the paper's "-" in Table 9: too costly to run
};

/// The paper's values for one case, size and motion.
struct PaperEntry {
    std::string tables;                   // "Tables 1-3"
    std::array<PaperFigures, 4> methods;  // in all_methods order: dg-idw, dgm, idw, rbf
    std::optional<double> original_mean, original_min;
};

/// The paper's figures of `method` in `entry` (unset for a method the paper did not run, e.g. dg-harmonic).
PaperFigures paper_figures(const PaperEntry& entry, Method method);

/// The paper's entry for (case, size, motion) of cases/paper_cases.hpp, or nullopt.
std::optional<PaperEntry> paper_entry(const std::string& case_name, int size, const std::string& motion);

}  // namespace dgwarp
