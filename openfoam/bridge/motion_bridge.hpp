#pragma once
// The motion solver's way into dgwarp: plain arrays in, plain arrays out.
// OpenFOAM v1912's headers need C++17 and dgwarp is C++20, so the OpenFOAM
// side (dgwarpFoam/dgwarpMotionSolver.C) includes only this header, which
// names no dgwarp type; motion_bridge.cpp (C++20) does the rest with the
// library (the run layer's step, repair and measure: run/deform_frame.hpp).
//
//   dgwarp_bridge::Solver s(std::move(mesh), settings, nullptr);
//   each time step: StepResult r = s.step(displacement, new_points);
//
// Conventions: OpenFOAM's own numbering (point i, cell i, face i), points
// num_points × 3 row-major; every failure a dgwarp_bridge::Error with the
// library's message.
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace dgwarp_bridge {

class Error : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// What the motion solver makes of a patch.
enum class PatchRole {
    moving,     // its points take their pointDisplacement
    fixed,      // its points stay where they are
    interface,  // not a boundary of the whole mesh (a processor patch): its points are volume nodes
};

struct Patch {
    std::string name, type;       // as in the boundary file
    std::int64_t start = 0, size = 0;  // startFace, nFaces
    PatchRole role = PatchRole::fixed;
};

/// The polyMesh at the motion solver's reference points (points0).
struct PolyMesh {
    std::vector<double> points;               // num_points × 3
    std::vector<std::int64_t> face_offsets;   // face f: face_nodes[face_offsets[f] .. face_offsets[f + 1])
    std::vector<std::int32_t> face_nodes;
    std::vector<std::int32_t> owner;          // one per face
    std::vector<std::int32_t> neighbour;      // one per internal face
    std::int64_t num_cells = 0;
    std::vector<Patch> patches;
};

struct Settings {
    std::string method = "dg-harmonic";  // as `dgwarp deform --method`
    /// Method options by their CLI names without "--" ("a-translation"), values as text.
    std::vector<std::pair<std::string, std::string>> options;
    /// After the step: "default" (dg-harmonic's last resort; nothing for the
    /// other methods), "untangle" (`dgwarp deform --untangle`) or "none".
    /// One process only: a parallel run measures and refuses inverted cells.
    std::string repair = "default";
};

/// A parallel run: this process's part of a decomposed case, in MPI_COMM_WORLD.
struct Parallel {
    std::vector<std::int64_t> global_ids;  // per local point: its point in the whole mesh (pointProcAddressing)
};

/// A moving patch's motion as a rigid body, when its condition knows it (a
/// solidBodyMotionDisplacement): its points go to
/// centre + R(rotation)(x - centre) + translation, R the rotation by the
/// vector `rotation` (axis × angle, radians). The methods then interpolate the
/// rotation and the translation apart (METHODS.md), rather than the
/// displacement alone.
struct RigidMotion {
    bool rigid = false;
    double rotation[3] = {0, 0, 0};
    double centre[3] = {0, 0, 0};
    double translation[3] = {0, 0, 0};
};

struct StepResult {
    std::int64_t cells = 0;          // this process's cells
    std::int64_t inverted = 0;       // of them, cells valid in points0 and inverted now (after the repair)
    std::vector<std::int64_t> worst_inverted;  // up to 10 of those, worst first (local cell numbers)
    double min_quality = 0;          // this process's smallest cell quality (Knupp's, docs/QUALITY.md)
    double mean_quality = 0;
    std::int64_t repaired = 0;       // cells the repair mended (0: none needed or none run)
    bool last_resort = false;        // the repair was dg-harmonic's last resort
    bool guard_redo = false;         // dg-harmonic's guard solved the step again with the laplacian reference
    double step_seconds = 0, repair_seconds = 0, quality_seconds = 0;
    std::vector<std::string> warnings;
};

class Solver {
  public:
    /// Prepares the method for `mesh` (the moving and fixed patches' points
    /// are the boundary), collectively over MPI_COMM_WORLD when `parallel` is
    /// given. Throws Error: an unknown method or option, faces that do not
    /// close a cell, a bad boundary.
    Solver(PolyMesh mesh, const Settings& settings, const Parallel* parallel);
    ~Solver();
    Solver(const Solver&) = delete;
    Solver& operator=(const Solver&) = delete;

    /// One step from points0: `displacement` (num_points × 3) is read at the
    /// moving patches' points; writes every point's new position to
    /// `new_points` (num_points × 3). `rigid`: empty, or one per patch (in
    /// the mesh's order): a point of a moving patch whose motion is rigid
    /// takes that motion (the first such patch of a point on several), and
    /// must land where its displacement says (within 1e-9 of the mesh's
    /// size: Error naming the patch otherwise). Collective in a parallel run.
    StepResult step(const double* displacement, const std::vector<RigidMotion>& rigid, double* new_points);

    /// The points of the moving and of the fixed patches (this process's).
    std::int64_t moving_points() const;
    std::int64_t fixed_points() const;
    /// One line for the log: the method, its options, the boundary and the prepare's time.
    std::string summary() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace dgwarp_bridge
