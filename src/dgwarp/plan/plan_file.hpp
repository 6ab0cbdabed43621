#pragma once
// A plan on disk, so a solver can prepare once and deform in later runs:
// DG-IDW plans (below) and DG-harmonic plans (magic "DGWHARM", format 1: the
// same layout of header, arrays and chained checksum with DgHarmonicPlan's
// fields; dg_harmonic_plan_file.cpp). save_plan / load_plan take either.
//
// DG-IDW:
// Format (version 3, little-endian, no padding):
//   header:  magic "DGWPLAN\0" (8 bytes), u32 format version, u32 dim,
//            u32 weighting (0 paper, 1 continuous), i64 num_points, u64
//            points hash, u64 boundary hash (the mesh fingerprint), f64 auto
//            length scale, i64 outside / snapped / shared-vertex /
//            graph-vertex counts, f64 a_translation, a_rotation and
//            length_scale (0 = auto: DgIdwPlan::options), then u64 element
//            counts of the 7 arrays;
//   arrays:  boundary_nodes i32, boundary_moving u8, simplex_motion i32,
//            shared_offsets i32, shared_members i32, node_simplex i32,
//            node_coefficients f64 (DgIdwPlan's fields);
//   trailer: u64 checksum: hash64 (XXH64) chained over the header and then
//            each array (each part hashed with the previous part's hash as seed).
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "dgwarp/methods/dg_idw.hpp"
#include "dgwarp/methods/method.hpp"

namespace dgwarp {

/// Writes `plan` to `path` atomically (write_file_atomically). Throws IoError.
void save_dg_idw_plan(const std::filesystem::path& path, const DgIdwPlan& plan);

/// Reads a plan. Throws IoError when the file cannot be read, and ParseError
/// (naming the file and the byte offset) when it is not a plan file, has
/// another format version, is truncated or longer than its header says, fails
/// its checksum, or holds inconsistent indices. The sizes in the header are
/// checked against the file size before anything is allocated. Timings in
/// the loaded plan's stats are 0.
DgIdwPlan load_dg_idw_plan(const std::filesystem::path& path);

/// The same, from the bytes of a plan file in memory (a whole file: header,
/// arrays, checksum); `name` names it in error messages.
DgIdwPlan load_dg_idw_plan_bytes(std::span<const std::byte> bytes, const std::string& name);

/// `bytes` (a plan file image) with its trailing checksum recomputed from its
/// content, so that tests and fuzzers can reach the checks behind the
/// checksum. Returned unchanged when the sizes in its header do not add up to
/// its length.
std::vector<std::byte> with_recomputed_plan_checksum(std::span<const std::byte> bytes);

/// load_dg_idw_plan, then check_plan_fits: also throws MeshError when the plan
/// was made for another mesh (points: num_points × dim original coordinates)
/// or another boundary set.
DgIdwPlan load_dg_idw_plan(const std::filesystem::path& path, std::span<const double> points,
                           const BoundarySet& boundary);

/// Any savable plan (DG-IDW, DG-harmonic), atomically. Throws Error for a
/// method whose plans cannot be saved, IoError when the file cannot be written.
void save_plan(const std::filesystem::path& path, const Plan& plan);

/// Whether save_plan can save plans of this kind (DG-IDW and DG-harmonic).
bool plan_can_be_saved(const Plan& plan);

/// The bytes save_plan would write (a whole plan file: load_plan_bytes reads
/// them back). Throws Error for a method whose plans cannot be saved.
std::vector<std::byte> plan_file_bytes(const Plan& plan);

/// A plan file of either kind (told apart by its magic), checked as
/// load_dg_idw_plan checks DG-IDW plans; with points and boundary, also
/// check_plan_fits (MeshError for another mesh or boundary set).
Plan load_plan(const std::filesystem::path& path);
Plan load_plan(const std::filesystem::path& path, std::span<const double> points, const BoundarySet& boundary);
Plan load_plan_bytes(std::span<const std::byte> bytes, const std::string& name);

}  // namespace dgwarp
