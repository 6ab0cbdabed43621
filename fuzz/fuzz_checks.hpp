#pragma once
// What each fuzz target does with one input, shared by the libFuzzer targets
// (fuzz/fuzz_*.cpp) and by the regression test that replays every input the
// fuzzers ever crashed on (tests/io/fuzz_regression_test.cpp).
//
// Each check runs one reader on the bytes. A dgwarp::Error (the input is
// malformed) is the expected failure and is let through to the caller; any
// other exception, or a crash, is a bug. When the reader accepts the input,
// the check also tests a property of the result (a written mesh reads back
// equal; a loaded plan deforms without leaving its arrays) and throws
// PropertyViolation when it fails.
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

namespace dgwarp::fuzz {

/// A reader's result breaks a property; deliberately not a dgwarp::Error.
struct PropertyViolation : std::logic_error {
    using std::logic_error::logic_error;
};

/// read_su2_text (zone 1, and zone 2 when the text has NZONE=); a mesh read
/// must survive write_su2 then read_su2_text unchanged.
void check_su2(std::span<const std::uint8_t> data);

/// read_vtu_text; a mesh read must survive write_vtu then read_vtu_text
/// unchanged (unless the writer refuses it with a dgwarp::Error).
void check_vtu(std::span<const std::uint8_t> data);

/// read_gmsh_text; a mesh read must survive write_gmsh (4.1 and 2.2) then
/// read_gmsh_text unchanged (unless the writer refuses it with a dgwarp::Error).
void check_gmsh(std::span<const std::uint8_t> data);

/// The separator between the polyMesh files of an OpenFOAM fuzz input.
inline constexpr const char* openfoam_file_separator = "\n//dgwarp-next-file\n";

/// read_openfoam_files on the input split at openfoam_file_separator into
/// points, faces, owner, neighbour and boundary (missing ones empty); a mesh
/// read must survive write_openfoam_files (ascii and binary, with the patches
/// read) then read_openfoam_files unchanged, patches included (unless the
/// writer refuses it with a dgwarp::Error).
void check_openfoam(std::span<const std::uint8_t> data);

/// read_cgns on the bytes written to a file (libcgns reads files only); a
/// mesh read must survive write_cgns then read_cgns unchanged (unless the
/// writer refuses it with a dgwarp::Error), and write_cgns_points of its own
/// points into a copy of the input must read back as the same mesh.
void check_cgns(std::span<const std::uint8_t> data);

/// parse_motion_file with an empty base folder, so the files a motion names
/// are never found. Inputs with a '/' in a JSON string are skipped: a path
/// such as /dev/zero would make the fuzzer read the machine's files.
void check_motion(std::span<const std::uint8_t> data);

/// load_plan_bytes (DG-IDW or DG-harmonic) on the bytes as they are, then (so
/// mutations get past the checksum to the index checks) on
/// with_valid_plan_checksum(bytes); a plan that loads is used for one step of
/// its method.
void check_plan(std::span<const std::uint8_t> data);

/// `bytes` with the trailing checksum recomputed when the array counts in its
/// header add up to the byte count; otherwise unchanged.
std::vector<std::byte> with_valid_plan_checksum(std::span<const std::byte> bytes);

}  // namespace dgwarp::fuzz
