#include "dgwarp/bench/paper_figures.hpp"

#include <map>
#include <tuple>

namespace dgwarp {

namespace {

using F = PaperFigures;
F fig(double mean, double min, std::optional<double> seconds = std::nullopt) { return {mean, min, seconds, false, false}; }
F failed() { return {std::nullopt, std::nullopt, std::nullopt, true, false}; }
F time_only(double seconds) { return {std::nullopt, std::nullopt, seconds, false, false}; }
F not_run() { return {std::nullopt, std::nullopt, std::nullopt, false, true}; }

// Order in PaperEntry::methods: dg-idw, dgm, idw, rbf (all_methods).
const std::map<std::tuple<std::string, int, std::string>, PaperEntry>& paper_table() {
    static const std::map<std::tuple<std::string, int, std::string>, PaperEntry> t = {
        {{"rect-box", 0, "rotate-30"},
         {"Tables 1-3", {fig(0.952, 0.784, 0.001), fig(0.885, 0.684, 0.001), fig(0.970, 0.882, 0.015), fig(0.954, 0.784, 0.065)}, {}, {}}},
        {{"rect-box", 0, "rotate-45"},
         {"Tables 1-3", {fig(0.920, 0.627, 0.001), fig(0.781, 0.408, 0.001), fig(0.946, 0.768, 0.016), fig(0.907, 0.580, 0.062)}, {}, {}}},
        {{"rect-box", 0, "rotate-60"},
         {"Tables 1-3", {fig(0.884, 0.469, 0.001), fig(0.676, 0.159, 0.001), fig(0.919, 0.641, 0.016), fig(0.851, 0.363, 0.062)}, {}, {}}},
        {{"rect-box", 0, "rotate-90"},
         {"Tables 1-3", {fig(0.814, 0.208, 0.001), failed(), fig(0.863, 0.396, 0.016), fig(0.739, 0.356, 0.063)}, {}, {}}},
        {{"rect-box", 0, "translate"},
         {"Table 4", {fig(0.881, 0.591, 0.001), fig(0.792, 0.649, 0.001), fig(0.777, 0.422, 0.033), fig(0.860, 0.223, 0.107)}, {}, {}}},
        {{"naca0012", 0, "translate"},
         {"Table 5", {fig(0.908, 0.176), fig(0.736, -0.185), fig(0.895, 0.116), fig(0.895, 0.176)}, 0.965, 0.177}},
        {{"naca0012", 0, "rotate-45"},
         {"Table 6", {fig(0.933, 0.177), fig(0.942, 0.151), fig(0.927, 0.162), fig(0.923, 0.176)}, 0.965, 0.177}},
        {{"twisted-bar", 0, "twist"},
         {"Table 7", {fig(0.980, 0.799, 0.001), fig(0.981, 0.792, 0.001), fig(0.943, 0.414, 0.202), fig(0.914, 0.666, 0.405)}, {}, {}}},
        {{"twisted-bar", 0, "twist-rotate-45"},
         {"Table 8", {fig(0.879, 0.262, 0.001), fig(0.793, 0.185, 0.001), fig(0.828, 0.356, 0.202), fig(0.747, 0.141, 0.402)}, {}, {}}},
        {{"squeezed-sphere", 0, "squeeze"},
         {"Tables 9-10 (201,920 nodes, 10,096 boundary)",
          {fig(0.836, 0.613, 0.143), fig(0.845, 0.552, 0.099), fig(0.880, 0.414, 485.105), fig(0.833, 0.705, 11692.154)}, {}, {}}},
        {{"squeezed-sphere", 1, "squeeze"},
         {"Table 9 (403,840 nodes, 10,096 boundary)", {time_only(0.237), time_only(0.172), time_only(955.096), not_run()}, {}, {}}},
        {{"squeezed-sphere", 2, "squeeze"},
         {"Table 9 (826,080 nodes, 41,304 boundary)", {time_only(0.451), time_only(0.359), time_only(8295.252), not_run()}, {}, {}}},
        // Section 6 gives only the two CPU times, and (Fig. 24) a quality ratio above 0.85 near the wing.
        {{"wing-body", 1, "fold-20"},
         {"section 6 (257,909 nodes, 1,507,462 tetrahedra)", {time_only(0.510), time_only(0.503), not_run(), not_run()}, {}, {}}},
    };
    return t;
}

}  // namespace

std::optional<PaperEntry> paper_entry(const std::string& case_name, int size, const std::string& motion) {
    const auto& t = paper_table();
    const auto it = t.find({case_name, size, motion});
    if (it == t.end()) return std::nullopt;
    return it->second;
}

PaperFigures paper_figures(const PaperEntry& entry, Method method) {
    const auto i = static_cast<std::size_t>(method);
    return i < entry.methods.size() ? entry.methods[i] : PaperFigures{};
}

}  // namespace dgwarp
