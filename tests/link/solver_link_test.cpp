// A program linking only the deformation core and the file formats
// (solver_program.cpp: dgwarp_methods + dgwarp_io) pulls in neither Cairo
// (dgwarp_picture) nor Gmsh (dgwarp_cases), and deforms as the library does.
//
// The program is linked with --no-as-needed, so its dynamic section lists
// every shared library its link line names: what the library targets hand to
// a program linking them, whatever the toolchain's default (Debian's gcc
// passes --as-needed, which drops unused libraries, except with -fsanitize).
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "dgwarp/cases/rect_box.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/methods/method.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {

/// The NEEDED entries of `program`'s dynamic section (readelf -d).
std::vector<std::string> needed_libraries(const std::filesystem::path& program) {
    const CommandResult r = run_command("readelf -d " + test::quoted(program));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    std::vector<std::string> needed;
    std::istringstream in(r.out);
    for (std::string line; std::getline(in, line);) {
        const auto open = line.find("(NEEDED)");
        const auto lib = line.find('[');
        if (open != std::string::npos && lib != std::string::npos)
            needed.push_back(line.substr(lib + 1, line.find(']', lib) - lib - 1));
    }
    return needed;
}

bool any_starts_with(const std::vector<std::string>& names, const std::string& prefix) {
    for (const std::string& n : names)
        if (n.rfind(prefix, 0) == 0) return true;
    return false;
}

}  // namespace

TEST(SolverLink, ADeformationOnlyProgramNeedsNeitherCairoNorGmsh) {
    const std::vector<std::string> needed = needed_libraries(DGWARP_SOLVER_PROGRAM);
    std::string all;
    for (const std::string& n : needed) all += n + " ";
    // What it does need: OpenMP (core) and zlib (io's VTU reader), so the list is read right.
    EXPECT_TRUE(any_starts_with(needed, "libgomp.so")) << all;
    EXPECT_TRUE(any_starts_with(needed, "libz.so")) << all;
    EXPECT_FALSE(any_starts_with(needed, "libcairo")) << all;
    EXPECT_FALSE(any_starts_with(needed, "libgmsh")) << all;
}

TEST(SolverLink, TheProgramDeformsAsTheLibraryDoes) {
    const auto dir = scratch_dir();
    write_mesh(dir / "rect.su2", make_rect_box());
    write_text(dir / "turn.json",
               R"({"markers": {"rectangle": {"rotate": {"angle_deg": 20, "center": [0.1, 0]}}}})");
    const std::filesystem::path program = DGWARP_SOLVER_PROGRAM;
    const CommandResult r = run_command(test::quoted(program) + " " + test::quoted(dir / "rect.su2") + " " +
                                        test::quoted(dir / "turn.json") + " " + test::quoted(dir / "out.su2"));
    ASSERT_EQ(r.exit_code, 0) << r.err;

    const Mesh mesh = read_mesh(dir / "rect.su2");
    const MotionSpec spec = read_motion_file(dir / "turn.json");
    const ResolvedBoundary rb = resolve_boundary(mesh, spec);
    std::vector<double> expected(mesh.points.size());
    deform(prepare(Method::dg_idw, mesh.dim, mesh.points, rb.boundary), mesh.points,
           resolve_frame(mesh, spec, rb, 0).motion, expected);
    EXPECT_NE(expected, mesh.points);
    EXPECT_EQ(read_mesh(dir / "out.su2").points, expected);
}
