// Outputs are checked before the work starts (issue #17 items 2 and 13): no
// output may be an input of the command (also through links, a frame's or a
// method's output name, a file the motion names), its extension must say what
// is written, its folder must be writable, and a read-only file is not
// replaced. OS errors say why ("No such file or directory").
#include <gtest/gtest.h>
#include <unistd.h>

#include "dgwarp/io/mesh_io.hpp"
#include "support/rect_box_files.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using namespace dgwarp::test;

namespace {

/// The command failed with `code` and left `kept` byte for byte as `bytes`.
void outputs_expect_refused(const std::string& args, int code, const std::filesystem::path& kept,
                            const std::string& bytes, const std::string& message) {
    const CommandResult r = run_cli(args);
    EXPECT_EQ(r.exit_code, code) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << "\n" << r.err;
    EXPECT_EQ(r.out, "") << args << ": work started before the output was checked";
    EXPECT_EQ(slurp(kept), bytes) << args << ": " << kept << " changed";
}

}  // namespace

TEST(CliOutputs, AnOutputThatIsAnInputIsRefusedEvenThroughLinks) {
    const RectBoxFiles f = rect_box_files();
    const std::string mesh_bytes = slurp(f.mesh), motion_bytes = slurp(f.motion);
    const std::string m = quoted(f.mesh), motion = " -m " + quoted(f.motion);
    std::filesystem::create_symlink(f.mesh, f.dir / "link.su2");
    std::filesystem::create_hard_link(f.mesh, f.dir / "hard.su2");
    const std::string same = "it would be overwritten";
    for (const std::string& out : {m, quoted(f.dir / "link.su2"), quoted(f.dir / "hard.su2"),
                                   quoted(f.dir / "." / "rect_box.su2")}) {
        outputs_expect_refused("deform " + m + motion + " -o " + out, 1, f.mesh, mesh_bytes, same);
        outputs_expect_refused("deform " + m + motion + " -o " + out + " --json", 1, f.mesh, mesh_bytes, same);
        outputs_expect_refused("convert " + m + " " + out, 1, f.mesh, mesh_bytes, same);
    }
    // The extension is checked first for these: a plan or a picture is never a mesh.
    outputs_expect_refused("prepare " + m + motion + " -o " + m, 1, f.mesh, mesh_bytes, ".plan");
    outputs_expect_refused("picture " + m + " -o " + m, 1, f.mesh, mesh_bytes, ".png");
    outputs_expect_refused("deform " + m + motion + " -o " + quoted(f.motion), 1, f.motion, motion_bytes, ".su2");
    EXPECT_TRUE(std::filesystem::is_symlink(f.dir / "link.su2"));
}

TEST(CliOutputs, NoFrameOrMethodOutputAndNoFileTheMotionNamesIsOverwritten) {
    const RectBoxFiles f = rect_box_files();
    // A mesh named as frame 1 of the output "m.su2" would be: m_0001.su2.
    const auto mesh = f.dir / "m_0001.su2";
    std::filesystem::copy_file(f.mesh, mesh);
    const std::string mesh_bytes = slurp(mesh);
    const auto frames = write_text(f.dir / "frames.json",
                                   R"({"frames": [{"markers": {"rectangle": {"translate": [0.1, 0]}}},
                                                  {"markers": {"rectangle": {"translate": [0.2, 0]}}}]})");
    outputs_expect_refused("deform " + quoted(mesh) + " -m " + quoted(frames) + " -o " + quoted(f.dir / "m.su2"), 1,
                           mesh, mesh_bytes, "m_0001.su2");
    EXPECT_FALSE(std::filesystem::exists(f.dir / "m_0000.su2"));
    // --method all: the output of DGM is m_dgm.su2.
    const auto dgm_named = f.dir / "m_dgm.su2";
    std::filesystem::copy_file(f.mesh, dgm_named);
    outputs_expect_refused("deform " + quoted(dgm_named) + " -m " + quoted(f.motion) + " -o " + quoted(f.dir / "m.su2") +
                               " --method all",
                           1, dgm_named, mesh_bytes, "m_dgm.su2");
    // A displacement file (CSV text under a mesh's name) the motion names.
    std::string csv = "node,dx,dy\n";
    for (NodeId n : marker_nodes(find_marker(read_mesh(f.mesh), "rectangle")))
        csv += std::to_string(n) + ",0.01,0\n";
    const auto table = write_text(f.dir / "shift.su2", csv);
    const auto by_file = write_text(f.dir / "by_file.json", R"({"markers": {"rectangle": {"displacement_file": "shift.su2"}}})");
    outputs_expect_refused("deform " + quoted(f.mesh) + " -m " + quoted(by_file) + " -o " + quoted(table), 1, table, csv,
                           "shift.su2");
    outputs_expect_refused("prepare " + quoted(f.mesh) + " -m " + quoted(by_file) + " -o " + quoted(f.dir / "a.plan") +
                               " --zone 1 -q",
                           0, table, csv, "");
}

TEST(CliOutputs, AnExtensionThatDoesNotSayWhatIsWrittenIsAUsageError) {
    const RectBoxFiles f = rect_box_files();
    const std::string m = quoted(f.mesh), motion = " -m " + quoted(f.motion);
    for (const std::string& args :
         std::vector<std::string>{"prepare " + m + motion + " -o " + quoted(f.dir / "p.bin"),
                                  "picture " + m + " -o " + quoted(f.dir / "p.jpg"),
                                  "picture " + m + " -o " + quoted(f.dir / "p"),
                                  "deform " + m + motion + " -o " + quoted(f.dir / "p.xyz"),
                                  "convert " + m + " " + quoted(f.dir / "p.txt"),
                                  "case naca0012 -o " + quoted(f.dir / "p.dat"),
                                  "bench --case rect-box --markdown " + quoted(f.dir / "p.txt"),
                                  "bench --case rect-box --json " + quoted(f.dir / "p.md")}) {
        const CommandResult r = run_cli(args);
        EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.err;
        EXPECT_NE(r.err.find("must end in"), std::string::npos) << args << "\n" << r.err;
        EXPECT_EQ(r.out, "") << args;
    }
    for (const char* name : {"p.bin", "p.jpg", "p", "p.xyz", "p.txt", "p.dat", "p.md"})
        EXPECT_FALSE(std::filesystem::exists(f.dir / name)) << name;
    const CommandResult upper = run_cli("picture " + m + " -o " + quoted(f.dir / "p.PNG"));
    EXPECT_EQ(upper.exit_code, 0) << upper.err;
    const CommandResult plan = run_cli("prepare " + m + motion + " -o " + quoted(f.dir / "p.plan") + " -q");
    EXPECT_EQ(plan.exit_code, 0) << plan.err;
}

TEST(CliOutputs, AnUnwritableOutputFailsBeforeTheWorkWithTheReason) {
    const RectBoxFiles f = rect_box_files();
    const std::string m = quoted(f.mesh), motion = " -m " + quoted(f.motion);
    const std::string mesh_bytes = slurp(f.mesh);
    const auto missing = f.dir / "missing" / "out.su2";
    for (const std::string& args : std::vector<std::string>{
             "deform " + m + motion + " -o " + quoted(missing), "prepare " + m + motion + " -o " + quoted(f.dir / "missing" / "p.plan"),
             "convert " + m + " " + quoted(missing), "picture " + m + " -o " + quoted(f.dir / "missing" / "p.png"),
             "case naca0012 -o " + quoted(missing), "bench --case rect-box --markdown " + quoted(f.dir / "missing" / "r.md"),
             "deform " + m + motion + " -o " + quoted(f.mesh / "out.su2")}) {
        const CommandResult r = run_cli(args);
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
        EXPECT_TRUE(r.err.find("No such file or directory") != std::string::npos ||
                    r.err.find("Not a directory") != std::string::npos)
            << args << "\n" << r.err;
        EXPECT_EQ(r.err.find("does the folder exist"), std::string::npos) << r.err;
        EXPECT_EQ(r.out, "") << args << ": work started before the output was checked";
    }
    EXPECT_FALSE(std::filesystem::exists(f.dir / "missing"));
    // An output that is a folder.
    std::filesystem::create_directory(f.dir / "folder.su2");
    const CommandResult folder = run_cli("convert " + m + " " + quoted(f.dir / "folder.su2"));
    EXPECT_EQ(folder.exit_code, 2) << folder.err;
    EXPECT_NE(folder.err.find("is a folder"), std::string::npos) << folder.err;
    EXPECT_TRUE(std::filesystem::is_directory(f.dir / "folder.su2"));
    // Permission denied (root may write anywhere).
    if (::geteuid() != 0) {
        std::filesystem::create_directory(f.dir / "locked");
        std::filesystem::permissions(f.dir / "locked", std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
        const CommandResult locked = run_cli("deform " + m + motion + " -o " + quoted(f.dir / "locked" / "out.su2"));
        EXPECT_EQ(locked.exit_code, 2) << locked.err;
        EXPECT_NE(locked.err.find("Permission denied"), std::string::npos) << locked.err;
        std::filesystem::permissions(f.dir / "locked", std::filesystem::perms::owner_all);
    }
}

TEST(CliOutputs, AReadOnlyOutputIsRefusedAndKept) {
    const RectBoxFiles f = rect_box_files();
    const auto kept = write_text(f.dir / "kept.su2", "precious\n");
    std::filesystem::permissions(kept, std::filesystem::perms::owner_read | std::filesystem::perms::group_read);
    const std::string m = quoted(f.mesh);
    outputs_expect_refused("convert " + m + " " + quoted(kept), 2, kept, "precious\n", "read-only");
    outputs_expect_refused("deform " + m + " -m " + quoted(f.motion) + " -o " + quoted(kept), 2, kept, "precious\n",
                           "read-only");
}

TEST(CliOutputs, UnreadableInputsSayWhy) {
    const auto dir = scratch_dir();
    CommandResult r = run_cli("quality " + quoted(dir / "absent.su2"));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("absent.su2: cannot open file for reading: No such file or directory"), std::string::npos)
        << r.err;
    std::filesystem::create_directory(dir / "folder.su2");
    r = run_cli("quality " + quoted(dir / "folder.su2"));
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("Is a directory"), std::string::npos) << r.err;
}

TEST(CliOutputs, DevicesAndPipesAreNotReadEvenThroughLinks) {
    // Issue #27: `-m /dev/zero`, a displacement file or a mesh linked to
    // /dev/zero filled the memory. /dev/null (which ends) shows the rule
    // without that risk: a device is refused before it is read.
    const RectBoxFiles c = rect_box_files();
    for (const char* name : {"z.su2", "z.msh", "z.vtu"}) {
        std::filesystem::create_symlink("/dev/null", c.dir / name);
        const CommandResult r = run_cli("info " + quoted(c.dir / name));
        EXPECT_EQ(r.exit_code, 2) << name << ": " << r.err;
        EXPECT_NE(r.err.find("is not a regular file"), std::string::npos) << r.err;
    }
    CommandResult r = run_cli("check " + quoted(c.mesh) + " -m /dev/null");
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("/dev/null: is not a regular file"), std::string::npos) << r.err;
    const auto motion = write_text(c.dir / "d.json", R"({"markers": {"rectangle": {"displacement_file": "/dev/null"}}})");
    r = run_cli("check " + quoted(c.mesh) + " -m " + quoted(motion));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("is not a regular file"), std::string::npos) << r.err;
}

TEST(CliOutputs, AMarkerNameTheOutputCannotStoreIsWrittenAsOneItCanWithAWarning) {
    // Issue #27: a marker " lead" (from a Gmsh file) failed at the .su2
    // write, after the prepare and the step, without naming the file. Since
    // #30 item 5, deform writes it as "lead" (as convert does) and says so.
    const RectBoxFiles c = rect_box_files();
    const auto msh = c.dir / "lead.msh";
    ASSERT_EQ(run_cli("convert " + quoted(c.mesh) + " " + quoted(msh) + " -q").exit_code, 0);
    std::string text = slurp(msh);
    const auto at = text.find("\"rectangle\"");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 11, "\" lead\"");
    write_text(msh, text);
    const auto motion = write_text(c.dir / "lead.json", R"({"markers": {" lead": {"translate": [0.1, 0]}}})");
    const auto out = c.dir / "out.su2";
    const CommandResult r = run_cli("deform " + quoted(msh) + " -m " + quoted(motion) + " -o " + quoted(out));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find(out.string() + " cannot hold the marker name ' lead': it is written as 'lead'"), std::string::npos)
        << r.err;
    const Mesh written = read_mesh(out);
    EXPECT_NO_THROW(find_marker(written, "lead"));
    // .vtu stores it.
    EXPECT_EQ(run_cli("deform " + quoted(msh) + " -m " + quoted(motion) + " -o " + quoted(c.dir / "out.vtu") + " -q")
                  .exit_code,
              0);
}
