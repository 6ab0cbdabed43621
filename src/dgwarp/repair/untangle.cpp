#include "dgwarp/repair/untangle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/quality/cell_quality.hpp"

namespace dgwarp {

namespace {

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
        const auto nodes = cells_.nodes_of(static_cast<std::size_t>(c));
        std::array<double, 8 * 3> coords{};
        for (std::size_t k = 0; k < nodes.size(); ++k)
            for (int d = 0; d < dim_; ++d)
                coords[k * dim_ + d] = points_[static_cast<std::size_t>(nodes[k]) * dim_ + d];
        return cell_shape_quality(cells_.types[static_cast<std::size_t>(c)],
                                  std::span<const double>(coords.data(), nodes.size() * dim_), dim_,
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

constexpr double softness = 30;
constexpr double margin = 0.02;

Worth worth(const CellJudge& judge, std::span<const std::int64_t> around) {
    Worth w;
    std::array<double, 64> small{};
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
    constexpr double tiny = 1e-14;
    if (candidate.deficit > current.deficit + tiny) return true;
    if (candidate.deficit < current.deficit - tiny) return false;
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
    double step = 0.25 * local_length(dim, cells, around, node, points);
    if (!(step > 0)) return;
    const double smallest_step = step * 1e-3;
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

}  // namespace

UntangleReport untangle(int dim, const ElementList& cells, std::span<const std::int8_t> orientations,
                        std::span<const NodeId> fixed_nodes, std::span<double> points, const UntangleOptions& options) {
    if (dim != 2 && dim != 3) throw MeshError("untangle: dimension " + std::to_string(dim) + " is not 2 or 3");
    if (points.size() % static_cast<std::size_t>(dim) != 0)
        throw MeshError("untangle: " + std::to_string(points.size()) + " coordinates are not a whole number of " +
                        std::to_string(dim) + "D points");
    if (orientations.size() != cells.size())
        throw MeshError("untangle: " + std::to_string(orientations.size()) + " orientations for " +
                        std::to_string(cells.size()) + " cells");
    const std::size_t num_points = points.size() / static_cast<std::size_t>(dim);
    for (std::size_t i = 0; i < cells.nodes.size(); ++i)
        if (cells.nodes[i] < 0 || static_cast<std::size_t>(cells.nodes[i]) >= num_points)
            throw MeshError("untangle: a cell names node " + std::to_string(cells.nodes[i]) + " of " +
                            std::to_string(num_points), {}, cells.nodes[i]);
    std::vector<std::uint8_t> fixed(num_points, 0);
    for (NodeId n : fixed_nodes) {
        if (n < 0 || static_cast<std::size_t>(n) >= num_points)
            throw MeshError("untangle: fixed node " + std::to_string(n) + " is not one of the " +
                            std::to_string(num_points) + " nodes", {}, n);
        fixed[static_cast<std::size_t>(n)] = 1;
    }

    if (!(options.target_quality >= 0 && options.target_quality < 1))
        throw Error("untangle: the target quality must be in [0, 1), not " + std::to_string(options.target_quality));

    const CellJudge judge(dim, cells, orientations, points);
    const double target = options.target_quality;
    auto is_bad = [&](double q) { return !(q > target); };
    UntangleReport report;
    std::vector<double> quality(cells.size());
    parallel_for(static_cast<std::int64_t>(cells.size()),
                 [&](std::int64_t c) { quality[static_cast<std::size_t>(c)] = judge.quality(c); });
    // The cells to repair: at or below the target, with a node free to move.
    auto movable_cell = [&](std::int64_t c) {
        for (NodeId n : cells.nodes_of(static_cast<std::size_t>(c)))
            if (!fixed[static_cast<std::size_t>(n)]) return true;
        return false;
    };
    std::vector<std::int64_t> bad;
    for (std::size_t c = 0; c < cells.size(); ++c) {
        if (!(quality[c] > 0)) ++report.inverted_before;
        if (is_bad(quality[c])) {
            ++report.below_target_before;
            if (movable_cell(static_cast<std::int64_t>(c))) bad.push_back(static_cast<std::int64_t>(c));
        }
    }
    report.inverted_after = report.inverted_before;
    report.below_target_after = report.below_target_before;
    report.min_quality_after = 1;
    if (bad.empty()) return report;

    const NodeCells around = node_cells(cells, num_points);
    const std::vector<double> original(points.begin(), points.end());
    std::vector<std::uint8_t> touched(num_points, 0);
    std::vector<NodeId> touched_list;
    auto score = [&](const std::vector<std::int64_t>& list) {  // how far from done: fewer, then better
        double worst = std::numeric_limits<double>::infinity();
        for (std::int64_t c : list) worst = std::min(worst, judge.quality(c));
        return std::pair<std::size_t, double>(list.size(), worst);
    };
    auto last = score(bad);
    int stalled = 0;
    for (int round = 1; round <= options.max_rounds && !bad.empty() && stalled < 2; ++round) {
        report.rounds = round;
        // The free nodes within round - 1 rings of the bad cells' nodes.
        std::vector<std::uint8_t> in_region(num_points, 0);
        std::vector<NodeId> region;
        auto add = [&](NodeId n) {
            if (!in_region[static_cast<std::size_t>(n)]) {
                in_region[static_cast<std::size_t>(n)] = 1;
                region.push_back(n);
            }
        };
        for (std::int64_t c : bad)
            for (NodeId n : cells.nodes_of(static_cast<std::size_t>(c))) add(n);
        for (int ring = 1; ring < round; ++ring) {
            const std::size_t end = region.size();
            for (std::size_t i = 0; i < end; ++i)
                for (std::int64_t c : around.of(static_cast<std::size_t>(region[i])))
                    for (NodeId n : cells.nodes_of(static_cast<std::size_t>(c))) add(n);
        }
        std::vector<NodeId> movable;
        for (NodeId n : region)
            if (!fixed[static_cast<std::size_t>(n)]) movable.push_back(n);
        std::sort(movable.begin(), movable.end());
        for (NodeId n : movable)
            if (!touched[static_cast<std::size_t>(n)]) {
                touched[static_cast<std::size_t>(n)] = 1;
                touched_list.push_back(n);
            }
        // After a round that gained nothing, the search is stuck in a fold that
        // no single node can leave: smooth the region first (each node to the
        // mean of its cells' centroids, which unfolds bands of flipped cells),
        // and keep the result only if the round then ends better.
        std::vector<double> snapshot;
        if (stalled > 0) {
            snapshot.reserve(movable.size() * static_cast<std::size_t>(dim));
            for (NodeId n : movable)
                for (int d = 0; d < dim; ++d) snapshot.push_back(points[static_cast<std::size_t>(n) * dim + d]);
            smooth(dim, cells, around, movable, points, 20);
        }
        for (int sweep = 0; sweep < options.sweeps_per_round; ++sweep)
            for (NodeId n : movable)
                improve_node(dim, cells, judge, around.of(static_cast<std::size_t>(n)), n, points, options.max_steps);

        // Only the cells around moved nodes can have changed.
        std::vector<std::int64_t> still;
        std::vector<std::uint8_t> seen(cells.size(), 0);
        auto check = [&](std::int64_t c) {
            if (seen[static_cast<std::size_t>(c)]) return;
            seen[static_cast<std::size_t>(c)] = 1;
            if (is_bad(judge.quality(c))) still.push_back(c);
        };
        for (std::int64_t c : bad) check(c);
        for (NodeId n : movable)
            for (std::int64_t c : around.of(static_cast<std::size_t>(n))) check(c);
        std::sort(still.begin(), still.end());
        if (!snapshot.empty() && !(still.size() < bad.size() || (still.size() == bad.size() && score(still).second > last.second))) {
            for (std::size_t i = 0; i < movable.size(); ++i)  // the smoothing did not help: undo the round
                for (int d = 0; d < dim; ++d)
                    points[static_cast<std::size_t>(movable[i]) * dim + d] = snapshot[i * static_cast<std::size_t>(dim) + d];
            still = bad;
        }
        bad = std::move(still);
        const auto now = score(bad);
        stalled = (now.first < last.first || now.second > last.second + 1e-3) ? 0 : stalled + 1;
        last = now;
    }

    // Final counts: only cells around the touched nodes changed.
    std::sort(touched_list.begin(), touched_list.end());
    std::vector<std::uint8_t> changed(cells.size(), 0);
    for (NodeId n : touched_list)
        for (std::int64_t c : around.of(static_cast<std::size_t>(n))) changed[static_cast<std::size_t>(c)] = 1;
    report.inverted_after = report.below_target_after = 0;
    double worst_changed = 1;
    for (std::size_t c = 0; c < cells.size(); ++c) {
        const double q = changed[c] ? judge.quality(static_cast<std::int64_t>(c)) : quality[c];
        if (!(q > 0)) ++report.inverted_after;
        if (is_bad(q)) ++report.below_target_after;
        if (changed[c]) worst_changed = std::min(worst_changed, q);
    }
    for (NodeId n : touched_list) {
        double s = 0;
        for (int d = 0; d < dim; ++d) {
            const double e =
                points[static_cast<std::size_t>(n) * dim + d] - original[static_cast<std::size_t>(n) * dim + d];
            s += e * e;
        }
        if (s > 0) {
            ++report.nodes_moved;
            report.max_move = std::max(report.max_move, std::sqrt(s));
        }
    }
    report.min_quality_after = worst_changed;
    return report;
}

}  // namespace dgwarp
