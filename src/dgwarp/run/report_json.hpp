#pragma once
// A run's reports as JSON objects (docs/JSON.md): one definition for the
// CLI's --json reports and the Python package's report dictionaries.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dgwarp/core/warning.hpp"
#include "dgwarp/methods/dg_harmonic_guard.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "dgwarp/repair/untangle.hpp"
#include "dgwarp/run/deform_frame.hpp"

namespace dgwarp {

/// JSON schema version of every --json report (docs/JSON.md); bumped on incompatible changes.
inline constexpr int json_schema_version = 2;

/// {"cells", "min", "mean", "inverted", "worst_cell", "histogram": {"edges", "counts"}}
nlohmann::json quality_json(const QualitySummary& q);
/// {"min", "mean", "worst_cell"}
nlohmann::json ratio_json(const RatioSummary& r);
/// {"inverted_before", "inverted_after", "below_target_before", ..., "min_quality_after"}
nlohmann::json untangle_json(const UntangleReport& u);
/// DG-harmonic's guard: null when it did not measure the step.
nlohmann::json guard_json(const DgHarmonicGuardReport& g);

/// A warning as the reports' `warning_items` list it: `code` and `text`, and
/// of `marker`, `count`, `node`, `element` and `value` those it has;
/// `method`, when not empty (--method all).
nlohmann::json warning_json(const Warning& w, const std::string& method = "");
/// The texts of `warnings` (the reports' `warnings`) and their items (`warning_items`).
nlohmann::json warning_texts_json(const std::vector<Warning>& warnings);
nlohmann::json warning_items_json(const std::vector<Warning>& warnings);

/// A frame's report: quality, ratio, inverted cells, the step's figures
/// (substeps, DGM's invalid simplices, RBF's centres and error), the repair
/// (untangle, last_resort), the guard, seconds ("deform", "untangle",
/// "quality") and warnings (texts and items). The CLI's `frames[k]` adds
/// "frame", "time", "output" and the write's seconds.
nlohmann::json frame_report_json(const FrameReport& f);

/// The reports' `options` object: every method option but the tuning ones,
/// by its report key (methods/option_table.hpp); dg_idw_weights is null
/// unless `weights_known` (a plan file's weighting is known once it is loaded).
nlohmann::json options_json(const MethodOptions& o, bool weights_known);

}  // namespace dgwarp
