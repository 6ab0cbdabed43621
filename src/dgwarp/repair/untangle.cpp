#include "dgwarp/repair/untangle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/quality/cell_quality.hpp"

namespace dgwarp {

namespace {

// The tuning of the search (docs/UNTANGLE.md explains each step; measured on
// SU2's bricks and the twisted bar, where these values repair every cell).

// A hexahedron's 8 nodes, in up to 3 coordinates: the largest cell.
constexpr std::size_t max_cell_coordinates = 8 * 3;
// The deficit counts how far cells are below this small positive quality, not
// below 0: a cell repaired to a quality of 1e-12 would be inverted again by
// the next round-off, and a margin pushes it clearly clear.
constexpr double margin = 0.02;
// k of the soft minimum -log(sum exp(-k q)) / k: within log(n) / k of the
// smallest quality, about 0.1 for the 20 cells around a node of a
// tetrahedral mesh; larger k is closer to the minimum but less smooth.
constexpr double softness = 30;
// Deficits within this are equal: round-off of a sum of qualities of order 1.
constexpr double deficit_tolerance = 1e-14;
// A node's first search step, as a fraction of its shortest edge: a quarter
// leaves a fold in a few steps without jumping past a neighbour.
constexpr double first_step_fraction = 0.25;
// The search of one node ends when its step has halved to this fraction of
// the first: below it the gains are round-off.
constexpr double last_step_fraction = 1e-3;
// Qualities of up to this many cells around a node are kept on the stack (a
// node of a tetrahedral mesh has about 20-30); more go to the heap.
constexpr std::size_t cells_on_stack = 64;
// Jacobi sweeps of the smoothing restart after a stalled round: enough to
// move a band of folded cells a few cells wide (each sweep reaches one ring further).
constexpr int smoothing_sweeps = 20;
// A round gains nothing when it repairs no cell and lifts the worst one by
// less than this; after this many such rounds in a row the repair stops
// (the first of them starts the smoothing restart).
constexpr double min_gain = 1e-3;
constexpr int max_stalled_rounds = 2;

/// The cells around each node (compressed rows).
struct NodeCells {
    std::vector<std::int64_t> offsets;
    std::vector<std::int64_t> cells;
    std::span<const std::int64_t> of(std::size_t node) const {
        return {cells.data() + offsets[node], static_cast<std::size_t>(offsets[node + 1] - offsets[node])};
    }
};

NodeCells node_cells(const ElementList& cells, std::size_t num_points) {
    NodeCells nc;
    nc.offsets.assign(num_points + 1, 0);
    for (NodeId n : cells.nodes) ++nc.offsets[static_cast<std::size_t>(n) + 1];
    for (std::size_t i = 0; i < num_points; ++i) nc.offsets[i + 1] += nc.offsets[i];
    nc.cells.resize(cells.nodes.size());
    std::vector<std::int64_t> next(nc.offsets.begin(), nc.offsets.end() - 1);
    for (std::size_t c = 0; c < cells.size(); ++c)
        for (NodeId n : cells.nodes_of(c)) nc.cells[static_cast<std::size_t>(next[static_cast<std::size_t>(n)]++)] =
            static_cast<std::int64_t>(c);
    return nc;
}

/// Quality of the cells of one mesh under changing coordinates.
class CellJudge {
public:
    CellJudge(int dim, const ElementList& cells, std::span<const std::int8_t> orientations, std::span<const double> points)
        : dim_(dim), cells_(cells), orientations_(orientations), points_(points) {}

    double quality(std::int64_t c) const {
        return element_shape_quality(cells_, static_cast<std::size_t>(c), dim_, points_,
                                     orientations_[static_cast<std::size_t>(c)]);
    }

    /// The smallest quality of `around`.
    double worst(std::span<const std::int64_t> around) const {
        double q = std::numeric_limits<double>::infinity();
        for (std::int64_t c : around) q = std::min(q, quality(c));
        return q;
    }

private:
    int dim_;
    const ElementList& cells_;
    std::span<const std::int8_t> orientations_;
    std::span<const double> points_;
};

/// The shortest edge length from `node` to the other nodes of its cells, a
/// scale for its search steps (0 when every neighbour sits on it).
double local_length(int dim, const ElementList& cells, std::span<const std::int64_t> around, NodeId node,
                    std::span<const double> points) {
    double shortest = std::numeric_limits<double>::infinity();
    for (std::int64_t c : around)
        for (NodeId m : cells.nodes_of(static_cast<std::size_t>(c))) {
            if (m == node) continue;
            double s = 0;
            for (int d = 0; d < dim; ++d) {
                const double e = points[static_cast<std::size_t>(m) * dim + d] - points[static_cast<std::size_t>(node) * dim + d];
                s += e * e;
            }
            if (s > 0) shortest = std::min(shortest, s);
        }
    return std::isfinite(shortest) ? std::sqrt(shortest) : 0.0;
}

/// How much the cells around a node are worth: first the deficit, how far the
/// cells are below a small positive margin in all (Σ min(q - margin, 0), the
/// untangling objective: 0 when every cell clears the margin); then a soft
/// minimum of their qualities, -log(Σ exp(-k q)) / k, within log(n) / k of the
/// smallest one but smooth, so that a search is not stuck where two cells are
/// the worst at once; and the smallest quality itself.
struct Worth {
    double deficit = -std::numeric_limits<double>::infinity();
    double soft = -std::numeric_limits<double>::infinity();
    double worst = std::numeric_limits<double>::infinity();
};

Worth worth(const CellJudge& judge, std::span<const std::int64_t> around) {
    Worth w;
    std::array<double, cells_on_stack> small{};
    std::vector<double> large;
    double* q = small.data();
    if (around.size() > small.size()) {
        large.resize(around.size());
        q = large.data();
    }
    w.deficit = 0;
    for (std::size_t i = 0; i < around.size(); ++i) {
        q[i] = judge.quality(around[i]);
        w.worst = std::min(w.worst, q[i]);
        w.deficit += std::min(q[i] - margin, 0.0);
    }
    double sum = 0;
    for (std::size_t i = 0; i < around.size(); ++i) sum += std::exp(-softness * (q[i] - w.worst));
    w.soft = w.worst - std::log(sum) / softness;
    return w;
}

/// A move is better when it lowers the deficit, or keeps it and raises the
/// soft minimum without turning a valid neighbourhood invalid.
bool better(const Worth& candidate, const Worth& current) {
    if (candidate.deficit > current.deficit + deficit_tolerance) return true;
    if (candidate.deficit < current.deficit - deficit_tolerance) return false;
    if (current.worst > 0 && !(candidate.worst > 0)) return false;
    return candidate.soft > current.soft;
}

/// The quantity a node's search climbs first: the deficit while there is one.
double climbed(const Worth& w, const Worth& current) { return current.deficit < 0 ? w.deficit : w.soft; }

/// Moves `node` to raise the quality of the cells around it: each step tries
/// the 2·dim axis moves of the current length and the move along the soft
/// minimum's gradient (from the same trials), takes the best, and halves the
/// length when none is better.
void improve_node(int dim, const ElementList& cells, const CellJudge& judge, std::span<const std::int64_t> around,
                  NodeId node, std::span<double> points, int max_steps) {
    double* x = points.data() + static_cast<std::size_t>(node) * dim;
    Worth current = worth(judge, around);
    double step = first_step_fraction * local_length(dim, cells, around, node, points);
    if (!(step > 0)) return;
    const double smallest_step = step * last_step_fraction;
    for (int s = 0; s < max_steps && step > smallest_step; ++s) {
        std::array<double, 3> best_move{}, gradient{};
        Worth best = current;
        bool found = false;
        auto trial = [&](const std::array<double, 3>& move) {
            std::array<double, 3> keep{};
            for (int d = 0; d < dim; ++d) {
                keep[d] = x[d];
                x[d] += move[d];
            }
            const Worth w = worth(judge, around);
            for (int d = 0; d < dim; ++d) x[d] = keep[d];
            if (better(w, best)) {
                best = w;
                best_move = move;
                found = true;
            }
            return w;
        };
        for (int d = 0; d < dim; ++d) {
            std::array<double, 3> move{};
            move[d] = step;
            const Worth plus = trial(move);
            move[d] = -step;
            const Worth minus = trial(move);
            const double up = climbed(plus, current), down = climbed(minus, current);
            gradient[d] = std::isfinite(up) && std::isfinite(down) ? up - down : 0.0;
        }
        double norm = 0;
        for (int d = 0; d < dim; ++d) norm += gradient[d] * gradient[d];
        if (norm > 0) {
            norm = std::sqrt(norm);
            std::array<double, 3> move{};
            for (int d = 0; d < dim; ++d) move[d] = step * gradient[d] / norm;
            trial(move);
        }
        if (!found) {
            step *= 0.5;
            continue;
        }
        for (int d = 0; d < dim; ++d) x[d] += best_move[d];
        current = best;
    }
}

/// `iterations` Jacobi sweeps moving each of `nodes` to the mean of the
/// centroids of its cells.
void smooth(int dim, const ElementList& cells, const NodeCells& around, std::span<const NodeId> nodes,
            std::span<double> points, int iterations) {
    const auto at = [&](NodeId n, int d) -> double& { return points[static_cast<std::size_t>(n) * dim + d]; };
    std::vector<std::array<double, 3>> next(nodes.size());
    for (int it = 0; it < iterations; ++it) {
        for (std::size_t i = 0; i < nodes.size(); ++i) {
            const auto star = around.of(static_cast<std::size_t>(nodes[i]));
            std::array<double, 3> sum{};
            for (std::int64_t c : star) {
                const auto cell = cells.nodes_of(static_cast<std::size_t>(c));
                for (NodeId m : cell)
                    for (int d = 0; d < dim; ++d) sum[d] += at(m, d) / static_cast<double>(cell.size());
            }
            for (int d = 0; d < dim; ++d)
                next[i][d] = star.empty() ? at(nodes[i], d) : sum[d] / static_cast<double>(star.size());
        }
        for (std::size_t i = 0; i < nodes.size(); ++i)
            for (int d = 0; d < dim; ++d) at(nodes[i], d) = next[i][d];
    }
}

bool is_bad(double quality, double target) { return !(quality > target); }

/// Checks the inputs (see untangle.hpp); one flag per node: 1 when it is fixed.
std::vector<std::uint8_t> checked_fixed_flags(int dim, const ElementList& cells,
                                              std::span<const std::int8_t> orientations,
                                              std::span<const NodeId> fixed_nodes, std::size_t coordinates,
                                              const UntangleOptions& options) {
    if (dim != 2 && dim != 3) throw MeshError("untangle: dimension " + std::to_string(dim) + " is not 2 or 3");
    if (coordinates % static_cast<std::size_t>(dim) != 0)
        throw MeshError("untangle: " + std::to_string(coordinates) + " coordinates are not a whole number of " +
                        std::to_string(dim) + "D points");
    if (orientations.size() != cells.size())
        throw MeshError("untangle: " + std::to_string(orientations.size()) + " orientations for " +
                        std::to_string(cells.size()) + " cells");
    const std::size_t num_points = coordinates / static_cast<std::size_t>(dim);
    for (std::size_t i = 0; i < cells.nodes.size(); ++i)
        if (cells.nodes[i] < 0 || static_cast<std::size_t>(cells.nodes[i]) >= num_points)
            throw MeshError("untangle: a cell names node " + std::to_string(cells.nodes[i]) + " of " +
                                std::to_string(num_points),
                            {}, cells.nodes[i]);
    std::vector<std::uint8_t> fixed(num_points, 0);
    for (NodeId n : fixed_nodes) {
        if (n < 0 || static_cast<std::size_t>(n) >= num_points)
            throw MeshError("untangle: fixed node " + std::to_string(n) + " is not one of the " +
                                std::to_string(num_points) + " nodes",
                            {}, n);
        fixed[static_cast<std::size_t>(n)] = 1;
    }
    if (!(options.target_quality >= 0 && options.target_quality < 1))
        throw Error("untangle: the target quality must be in [0, 1), not " + std::to_string(options.target_quality));
    return fixed;
}

/// The cells to repair (at or below the target, with a node free to move;
/// of `only` when it is not empty), ascending; counts the inverted and
/// below-target cells in `report` (all of them).
std::vector<std::int64_t> cells_to_repair(const ElementList& cells, std::span<const double> quality,
                                          std::span<const std::uint8_t> fixed, double target,
                                          std::span<const std::int64_t> only, UntangleReport& report) {
    std::vector<std::uint8_t> asked;
    if (!only.empty()) {
        asked.assign(cells.size(), 0);
        for (std::int64_t c : only) {
            if (c < 0 || static_cast<std::size_t>(c) >= cells.size())
                throw MeshError("untangle: cell " + std::to_string(c) + " to repair is out of range (" +
                                std::to_string(cells.size()) + " cells)");
            asked[static_cast<std::size_t>(c)] = 1;
        }
    }
    auto movable_cell = [&](std::size_t c) {
        for (NodeId n : cells.nodes_of(c))
            if (!fixed[static_cast<std::size_t>(n)]) return true;
        return false;
    };
    std::vector<std::int64_t> bad;
    for (std::size_t c = 0; c < cells.size(); ++c) {
        if (!(quality[c] > 0)) ++report.inverted_before;
        if (is_bad(quality[c], target)) {
            ++report.below_target_before;
            if (movable_cell(c) && (asked.empty() || asked[c])) bad.push_back(static_cast<std::int64_t>(c));
        }
    }
    return bad;
}

/// How far from done a list of cells to repair is: fewer, then a better worst quality.
std::pair<std::size_t, double> score(const CellJudge& judge, const std::vector<std::int64_t>& bad) {
    double worst = std::numeric_limits<double>::infinity();
    for (std::int64_t c : bad) worst = std::min(worst, judge.quality(c));
    return {bad.size(), worst};
}

/// The free nodes of the cells `bad` and of their neighbours up to `rings`
/// rings out, ascending.
std::vector<NodeId> free_nodes_around(const ElementList& cells, const NodeCells& around,
                                      std::span<const std::uint8_t> fixed, std::span<const std::int64_t> bad,
                                      int rings) {
    std::vector<std::uint8_t> in_region(fixed.size(), 0);
    std::vector<NodeId> region;
    auto add = [&](NodeId n) {
        if (!in_region[static_cast<std::size_t>(n)]) {
            in_region[static_cast<std::size_t>(n)] = 1;
            region.push_back(n);
        }
    };
    for (std::int64_t c : bad)
        for (NodeId n : cells.nodes_of(static_cast<std::size_t>(c))) add(n);
    for (int ring = 0; ring < rings; ++ring) {
        const std::size_t end = region.size();
        for (std::size_t i = 0; i < end; ++i)
            for (std::int64_t c : around.of(static_cast<std::size_t>(region[i])))
                for (NodeId n : cells.nodes_of(static_cast<std::size_t>(c))) add(n);
    }
    std::vector<NodeId> movable;
    for (NodeId n : region)
        if (!fixed[static_cast<std::size_t>(n)]) movable.push_back(n);
    std::sort(movable.begin(), movable.end());
    return movable;
}

/// What a repair round works on.
struct Repair {
    int dim;
    const ElementList& cells;
    const CellJudge& judge;
    const NodeCells& around;
    std::span<double> points;
    const UntangleOptions& options;
};

/// The cells of `bad` and around `moved` still at or below the target, ascending
/// (only the cells around moved nodes can have changed).
std::vector<std::int64_t> still_bad(const Repair& r, std::span<const std::int64_t> bad,
                                    std::span<const NodeId> moved) {
    std::vector<std::int64_t> still;
    std::vector<std::uint8_t> seen(r.cells.size(), 0);
    auto check = [&](std::int64_t c) {
        if (seen[static_cast<std::size_t>(c)]) return;
        seen[static_cast<std::size_t>(c)] = 1;
        if (is_bad(r.judge.quality(c), r.options.target_quality)) still.push_back(c);
    };
    for (std::int64_t c : bad) check(c);
    for (NodeId n : moved)
        for (std::int64_t c : r.around.of(static_cast<std::size_t>(n))) check(c);
    std::sort(still.begin(), still.end());
    return still;
}

/// One round: moves each of `movable` in turn, sweeps_per_round times, and
/// returns the cells still to repair. After a round that gained nothing
/// (`restart`), the search is stuck in a fold that no single node can leave:
/// the region is smoothed first (each node to the mean of its cells'
/// centroids, which unfolds bands of flipped cells), and the round is undone
/// unless it then ends better than `bad` (whose worst quality is `worst`).
std::vector<std::int64_t> repair_round(const Repair& r, std::span<const NodeId> movable,
                                       const std::vector<std::int64_t>& bad, bool restart, double worst) {
    const int dim = r.dim;
    std::vector<double> snapshot;
    if (restart) {
        snapshot.reserve(movable.size() * static_cast<std::size_t>(dim));
        for (NodeId n : movable)
            for (int d = 0; d < dim; ++d) snapshot.push_back(r.points[static_cast<std::size_t>(n) * dim + d]);
        smooth(dim, r.cells, r.around, movable, r.points, smoothing_sweeps);
    }
    for (int sweep = 0; sweep < r.options.sweeps_per_round; ++sweep)
        for (NodeId n : movable)
            improve_node(dim, r.cells, r.judge, r.around.of(static_cast<std::size_t>(n)), n, r.points,
                         r.options.max_steps);
    std::vector<std::int64_t> still = still_bad(r, bad, movable);
    const bool better = still.size() < bad.size() || (still.size() == bad.size() && score(r.judge, still).second > worst);
    if (!snapshot.empty() && !better) {
        for (std::size_t i = 0; i < movable.size(); ++i)  // the smoothing did not help: undo the round
            for (int d = 0; d < dim; ++d)
                r.points[static_cast<std::size_t>(movable[i]) * dim + d] = snapshot[i * static_cast<std::size_t>(dim) + d];
        return bad;
    }
    return still;
}

/// The report's counts after the rounds: only the cells around the touched
/// nodes can have changed (`quality`: every cell's quality before).
void count_after(const Repair& r, std::span<const double> quality, std::vector<NodeId> touched,
                 std::span<const double> original, UntangleReport& report) {
    const int dim = r.dim;
    std::sort(touched.begin(), touched.end());
    std::vector<std::uint8_t> changed(r.cells.size(), 0);
    for (NodeId n : touched)
        for (std::int64_t c : r.around.of(static_cast<std::size_t>(n))) changed[static_cast<std::size_t>(c)] = 1;
    report.inverted_after = report.below_target_after = 0;
    double worst_changed = 1;
    for (std::size_t c = 0; c < r.cells.size(); ++c) {
        const double q = changed[c] ? r.judge.quality(static_cast<std::int64_t>(c)) : quality[c];
        if (!(q > 0)) ++report.inverted_after;
        if (is_bad(q, r.options.target_quality)) ++report.below_target_after;
        if (changed[c]) worst_changed = std::min(worst_changed, q);
    }
    for (NodeId n : touched) {
        double s = 0;
        for (int d = 0; d < dim; ++d) {
            const double e =
                r.points[static_cast<std::size_t>(n) * dim + d] - original[static_cast<std::size_t>(n) * dim + d];
            s += e * e;
        }
        if (s > 0) {
            ++report.nodes_moved;
            report.max_move = std::max(report.max_move, std::sqrt(s));
        }
    }
    report.min_quality_after = worst_changed;
}

}  // namespace

std::vector<std::int64_t> cells_to_untangle(int dim, const ElementList& cells, std::span<const std::int8_t> orientations,
                                            std::span<const NodeId> fixed_nodes, std::span<const double> points,
                                            const UntangleOptions& options, UntangleReport* census) {
    const std::vector<std::uint8_t> fixed =
        checked_fixed_flags(dim, cells, orientations, fixed_nodes, points.size(), options);
    const CellJudge judge(dim, cells, orientations, points);
    std::vector<double> quality(cells.size());
    parallel_for(static_cast<std::int64_t>(cells.size()),
                 [&](std::int64_t c) { quality[static_cast<std::size_t>(c)] = judge.quality(c); });
    UntangleReport report;
    std::vector<std::int64_t> bad = cells_to_repair(cells, quality, fixed, options.target_quality, options.cells, report);
    if (census) *census = report;
    return bad;
}

UntangleReport untangle(int dim, const ElementList& cells, std::span<const std::int8_t> orientations,
                        std::span<const NodeId> fixed_nodes, std::span<double> points, const UntangleOptions& options) {
    const std::vector<std::uint8_t> fixed =
        checked_fixed_flags(dim, cells, orientations, fixed_nodes, points.size(), options);
    const std::size_t num_points = fixed.size();
    const CellJudge judge(dim, cells, orientations, points);
    UntangleReport report;
    std::vector<double> quality(cells.size());
    parallel_for(static_cast<std::int64_t>(cells.size()),
                 [&](std::int64_t c) { quality[static_cast<std::size_t>(c)] = judge.quality(c); });
    std::vector<std::int64_t> bad = cells_to_repair(cells, quality, fixed, options.target_quality, options.cells, report);
    report.inverted_after = report.inverted_before;
    report.below_target_after = report.below_target_before;
    report.min_quality_after = 1;
    if (bad.empty()) return report;

    const NodeCells around = node_cells(cells, num_points);
    const Repair r{dim, cells, judge, around, points, options};
    const std::vector<double> original(points.begin(), points.end());
    std::vector<std::uint8_t> touched(num_points, 0);
    std::vector<NodeId> touched_list;
    auto last = score(judge, bad);
    int stalled = 0;
    for (int round = 1; round <= options.max_rounds && !bad.empty() && stalled < max_stalled_rounds; ++round) {
        report.rounds = round;
        // Round r moves the free nodes within r - 1 rings of the cells to repair.
        const std::vector<NodeId> movable = free_nodes_around(cells, around, fixed, bad, round - 1);
        for (NodeId n : movable)
            if (!touched[static_cast<std::size_t>(n)]) {
                touched[static_cast<std::size_t>(n)] = 1;
                touched_list.push_back(n);
            }
        bad = repair_round(r, movable, bad, stalled > 0, last.second);
        const auto now = score(judge, bad);
        stalled = (now.first < last.first || now.second > last.second + min_gain) ? 0 : stalled + 1;
        last = now;
    }
    count_after(r, quality, std::move(touched_list), original, report);
    return report;
}

}  // namespace dgwarp
