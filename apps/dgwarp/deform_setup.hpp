#pragma once
// What `dgwarp deform` and `dgwarp prepare` share: reading the mesh and the
// motion, classifying the boundary, and building (or loading) the plan.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/methods/dg_idw.hpp"
#include "dgwarp/mesh/mesh.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "progress_line.hpp"

namespace dgwarp::cli {

struct SetupArgs {
    std::string mesh;
    std::string motion;
    int zone = 1;
    int threads = 0;
    double a_translation = 7.0;
    double a_rotation = 1.4;
    std::string length_scale = "1";
};

/// Adds the mesh, --motion, --zone, --threads and method options to `cmd`.
void add_setup_options(CLI::App* cmd, SetupArgs& args);

struct SetupTimes {
    double read = 0;     // mesh and motion files
    double resolve = 0;  // boundary classification
    double prepare = 0;  // plan: built or loaded
    double quality = 0;  // quality of the original mesh
};

struct Setup {
    SetupArgs args;
    std::string plan_file;  // the plan loaded, "" when built
    Mesh mesh;
    MotionSpec spec;
    ResolvedBoundary boundary;
    DgIdwOptions options;
    DgIdwPlan plan;
    std::vector<std::int8_t> orientation;      // per cell, of the original mesh
    std::vector<double> original_cell_quality;  // per cell
    QualitySummary original_quality;
    SetupTimes seconds;
};

/// Reads, resolves, and builds the plan (or loads it from `plan_file` when
/// not empty, checking it was made for this mesh and boundary), showing each
/// phase on `progress`.
Setup set_up(const SetupArgs& args, const std::string& plan_file, ProgressLine& progress);

/// Moves the mesh for one frame: new coordinates of every node into `out`.
void deform_mesh(const Setup& s, const BoundaryMotion& motion, std::vector<double>& out);

/// Lines about the mesh, motion, boundary, plan and set-up times.
void print_setup(std::ostream& out, const Setup& s, std::size_t frames);

/// The JSON report's common part (docs/JSON.md).
nlohmann::json setup_json(const Setup& s, const std::string& command);

}  // namespace dgwarp::cli
