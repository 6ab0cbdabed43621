// write_file_atomically: a crash, an error or a full disk in the middle of a
// write never leaves a half-written file where a good one was.
#include "dgwarp/core/atomic_write.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <vector>

#include "dgwarp/cases/rect_box.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/io/gmsh/gmsh.hpp"
#include "dgwarp/io/su2/su2.hpp"
#include "dgwarp/io/vtu/vtu.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;

namespace {

std::string read_file(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

void write_plain(const std::filesystem::path& p, const std::string& text) {
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out << text;
}

/// The names of the entries of `dir`, sorted.
std::vector<std::string> entries(const std::filesystem::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

/// True when `name` is a temporary file of write_file_atomically for `target`.
bool is_temporary_of(const std::string& name, const std::string& target) {
    return name.rfind("." + target + ".tmp.", 0) == 0;
}

/// A mesh whose SU2 text is large (about 1 MB): many stream buffers' worth.
Mesh large_mesh() {
    RectBoxOptions o;
    o.around = 312;
    o.layers = 60;
    return make_rect_box(o);
}

/// A stream buffer that passes everything on to `out` until `pause_after`
/// bytes have gone through; then it flushes `out` (so part of the file is on
/// disk), writes one byte to `signal_fd` and waits for ever (to be killed).
class PausingBuffer : public std::streambuf {
public:
    PausingBuffer(std::ostream& out, std::size_t pause_after, int signal_fd)
        : out_(out), left_(pause_after), signal_fd_(signal_fd) {}

protected:
    int_type overflow(int_type c) override {
        if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
        const char ch = traits_type::to_char_type(c);
        xsputn(&ch, 1);
        return c;
    }
    std::streamsize xsputn(const char* s, std::streamsize n) override {
        const auto now = static_cast<std::streamsize>(std::min<std::size_t>(left_, static_cast<std::size_t>(n)));
        out_.write(s, now);
        left_ -= static_cast<std::size_t>(now);
        if (left_ == 0) {
            out_.flush();
            const char byte = 'x';
            if (::write(signal_fd_, &byte, 1) != 1) ::_exit(10);
            for (;;) ::pause();
        }
        return n;
    }

private:
    std::ostream& out_;
    std::size_t left_;
    int signal_fd_;
};

/// Kills (SIGKILL) and reaps a child process when the test leaves early, so a
/// failed assertion never leaves a paused writer behind.
struct ChildGuard {
    pid_t pid = -1;
    ~ChildGuard() {
        if (pid > 0) {
            ::kill(pid, SIGKILL);
            ::waitpid(pid, nullptr, 0);
        }
    }
};

}  // namespace

TEST(AtomicWrite, KilledMidWriteLeavesTheOldFileIntact) {
    const auto dir = test::scratch_dir();
    const auto path = dir / "mesh.su2";
    const Mesh old_mesh = make_rect_box({.around = 12, .layers = 3});
    write_su2(path, old_mesh);
    const std::string old_text = read_file(path);
    ASSERT_FALSE(old_text.empty());

    const Mesh mesh = large_mesh();
    std::ostringstream full;
    write_su2(full, mesh);
    const std::size_t half = full.str().size() / 2;
    ASSERT_GT(half, std::size_t{200000});  // far beyond any stream buffer: half is on disk

    int pipe_fds[2];
    ASSERT_EQ(::pipe(pipe_fds), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        ::close(pipe_fds[0]);
        set_num_threads(1);  // a forked child runs no OpenMP region (libgomp is not fork-safe)
        try {
            write_file_atomically(path, [&](std::ostream& out) {
                PausingBuffer pausing(out, half, pipe_fds[1]);
                std::ostream through(&pausing);
                write_su2(through, mesh);
            });
        } catch (...) {
            ::_exit(11);
        }
        ::_exit(12);  // never reached: the writer pauses until killed
    }
    ChildGuard guard{child};
    ::close(pipe_fds[1]);
    char byte = 0;
    const ssize_t got = ::read(pipe_fds[0], &byte, 1);
    ::close(pipe_fds[0]);
    if (got != 1) {
        int status = 0;
        ::waitpid(child, &status, 0);
        guard.pid = -1;
        FAIL() << "the writer ended before writing half the file (status " << status << ")";
    }

    // Mid-write: half the new content is in a temporary file beside the target.
    std::vector<std::string> names = entries(dir);
    ASSERT_EQ(names.size(), 2u);
    const std::string tmp = names[0] == "mesh.su2" ? names[1] : names[0];
    EXPECT_TRUE(is_temporary_of(tmp, "mesh.su2")) << tmp;
    EXPECT_EQ(std::filesystem::file_size(dir / tmp), half);
    EXPECT_EQ(read_file(path), old_text);

    ASSERT_EQ(::kill(child, SIGKILL), 0);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    guard.pid = -1;
    ASSERT_TRUE(WIFSIGNALED(status));
    EXPECT_EQ(WTERMSIG(status), SIGKILL);

    // The old file is byte-identical; beside it at most the temporary file.
    EXPECT_EQ(read_file(path), old_text);
    EXPECT_EQ(read_su2(path), old_mesh);
    for (const std::string& name : entries(dir))
        EXPECT_TRUE(name == "mesh.su2" || is_temporary_of(name, "mesh.su2")) << name;

    // A later write replaces the file completely.
    write_su2(path, mesh);
    EXPECT_EQ(read_file(path), full.str());
}

namespace {
extern "C" void atomic_write_test_on_term(int) {
    remove_unfinished_temporary_files();
    ::_exit(13);
}
}  // namespace

TEST(AtomicWrite, ASignalHandlerRemovesTheTemporaryFileOfAnInterruptedWrite) {
    // Issue #27: SIGINT/SIGTERM during a write left ".out.su2.tmp.PID.N"
    // (35 MB, one per interrupted run). The CLI's handler does what this
    // child's does: remove_unfinished_temporary_files, then stop.
    const auto dir = test::scratch_dir();
    const auto path = dir / "mesh.su2";
    write_plain(path, "old");
    const Mesh mesh = large_mesh();
    int pipe_fds[2];
    ASSERT_EQ(::pipe(pipe_fds), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        ::close(pipe_fds[0]);
        set_num_threads(1);  // a forked child runs no OpenMP region (libgomp is not fork-safe)
        ::signal(SIGTERM, atomic_write_test_on_term);
        try {
            write_file_atomically(path, [&](std::ostream& out) {
                PausingBuffer pausing(out, 100000, pipe_fds[1]);
                std::ostream through(&pausing);
                write_su2(through, mesh);
            });
        } catch (...) {
            ::_exit(11);
        }
        ::_exit(12);
    }
    ChildGuard guard{child};
    ::close(pipe_fds[1]);
    char byte = 0;
    ASSERT_EQ(::read(pipe_fds[0], &byte, 1), 1);
    ::close(pipe_fds[0]);
    ASSERT_EQ(entries(dir).size(), 2u);  // mid-write: the temporary file is there
    ASSERT_EQ(::kill(child, SIGTERM), 0);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    guard.pid = -1;
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 13);
    EXPECT_EQ(entries(dir), std::vector<std::string>{"mesh.su2"});
    EXPECT_EQ(read_file(path), "old");
}

TEST(AtomicWrite, AWriteThroughASymbolicLinkReplacesTheFileItLeadsToAndKeepsTheLink) {
    // Issue #27: the link was replaced by a file, silently.
    const auto dir = test::scratch_dir();
    std::filesystem::create_directory(dir / "real");
    write_plain(dir / "real" / "out.su2", "old");
    std::filesystem::create_symlink("real/out.su2", dir / "link.su2");
    write_file_atomically(dir / "link.su2", [](std::ostream& out) { out << "new"; });
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.su2"));
    EXPECT_EQ(read_file(dir / "real" / "out.su2"), "new");
    EXPECT_EQ(entries(dir / "real"), std::vector<std::string>{"out.su2"});
    // A dangling link gets its file.
    std::filesystem::create_symlink("real/new.su2", dir / "dangling.su2");
    write_file_atomically(dir / "dangling.su2", [](std::ostream& out) { out << "made"; });
    EXPECT_TRUE(std::filesystem::is_symlink(dir / "dangling.su2"));
    EXPECT_EQ(read_file(dir / "real" / "new.su2"), "made");
}

TEST(AtomicWrite, AThrowingWriterLeavesTheOldFileAndNoTemporary) {
    const auto dir = test::scratch_dir();
    const auto path = dir / "out.txt";
    write_plain(path, "good content\n");
    EXPECT_THROW(write_file_atomically(path,
                                       [](std::ostream& out) {
                                           out << std::string(100000, 'x');
                                           throw std::runtime_error("writer failed");
                                       }),
                 std::runtime_error);
    EXPECT_EQ(read_file(path), "good content\n");
    EXPECT_EQ(entries(dir), std::vector<std::string>{"out.txt"});
}

TEST(AtomicWrite, WritersThatRefuseTheirInputLeaveTheOldFile) {
    // Each format's path writer: a mesh that fails validation throws from
    // inside the atomic write; the old file and the folder are untouched.
    const auto dir = test::scratch_dir();
    Mesh bad = make_rect_box({.around = 12, .layers = 3});
    bad.cells.nodes[0] = 100000;  // a node id out of range
    for (const char* name : {"mesh.su2", "mesh.msh", "mesh.vtu"}) {
        const auto path = dir / name;
        write_plain(path, "old\n");
        const std::string ext = path.extension().string();
        EXPECT_THROW(ext == ".su2"   ? write_su2(path, bad)
                     : ext == ".msh" ? write_gmsh(path, bad)
                                     : write_vtu(path, bad, {}),
                     MeshError)
            << name;
        EXPECT_EQ(read_file(path), "old\n") << name;
    }
    EXPECT_EQ(entries(dir), (std::vector<std::string>{"mesh.msh", "mesh.su2", "mesh.vtu"}));
}

TEST(AtomicWrite, WriteIntoAMissingFolderIsAnIoError) {
    const auto dir = test::scratch_dir();
    const auto path = dir / "missing" / "out.su2";
    try {
        write_file_atomically(path, [](std::ostream& out) { out << "x"; });
        FAIL() << "no error";
    } catch (const IoError& e) {
        EXPECT_EQ(e.file(), path.string());
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
    EXPECT_TRUE(entries(dir).empty());
}

TEST(AtomicWrite, ErrorsGiveTheOperatingSystemsReason) {
    const auto dir = test::scratch_dir();
    try {
        write_file_atomically(dir / "missing" / "out.su2", [](std::ostream& out) { out << "x"; });
        FAIL() << "no error";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find("No such file or directory"), std::string::npos) << e.what();
        EXPECT_EQ(std::string(e.what()).find("does the folder exist"), std::string::npos) << e.what();
    }
    write_plain(dir / "file", "x");
    try {
        check_folder_writable(dir / "file");
        FAIL() << "no error";
    } catch (const IoError& e) {
        EXPECT_EQ(e.file(), (dir / "file").string());
        EXPECT_NE(std::string(e.what()).find("Not a directory"), std::string::npos) << e.what();
    }
    EXPECT_THROW(check_folder_writable(dir / "missing"), IoError);
    check_folder_writable(dir);  // writable: no error, and no file left behind
    check_folder_writable("");   // the current folder
    EXPECT_EQ(entries(dir), std::vector<std::string>{"file"});
    if (::geteuid() != 0) {  // root may write anywhere
        std::filesystem::create_directory(dir / "locked");
        std::filesystem::permissions(dir / "locked", std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
        try {
            check_folder_writable(dir / "locked");
            ADD_FAILURE() << "no error";
        } catch (const IoError& e) {
            EXPECT_NE(std::string(e.what()).find("Permission denied"), std::string::npos) << e.what();
        }
        std::filesystem::permissions(dir / "locked", std::filesystem::perms::owner_all);
    }
}

TEST(AtomicWrite, ReadOnlyFilesFoldersAndDevicesAreNotReplaced) {
    const auto dir = test::scratch_dir();
    const auto kept = dir / "kept.su2";
    write_plain(kept, "keep me\n");
    std::filesystem::permissions(kept, std::filesystem::perms::owner_read | std::filesystem::perms::group_read);
    for (const auto& path : {kept, dir, std::filesystem::path("/dev/null")}) {
        EXPECT_THROW(check_replaceable(path), IoError) << path;
        EXPECT_THROW(write_file_atomically(path, [](std::ostream& out) { out << "new"; }), IoError) << path;
    }
    try {
        write_file_atomically(kept, [](std::ostream& out) { out << "new"; });
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find("read-only"), std::string::npos) << e.what();
    }
    EXPECT_EQ(read_file(kept), "keep me\n");
    EXPECT_EQ(entries(dir), std::vector<std::string>{"kept.su2"});
    check_replaceable(dir / "absent.su2");  // nothing to replace: fine
}

TEST(AtomicWrite, AReplacedFileKeepsItsPermissions) {
    const auto dir = test::scratch_dir();
    const auto path = dir / "private.su2";
    write_plain(path, "old\n");
    const auto mode = std::filesystem::perms::owner_read | std::filesystem::perms::owner_write |
                      std::filesystem::perms::group_read;
    std::filesystem::permissions(path, mode);
    write_file_atomically(path, [](std::ostream& out) { out << "new\n"; });
    EXPECT_EQ(read_file(path), "new\n");
    EXPECT_EQ(std::filesystem::status(path).permissions(), mode);
}

TEST(AtomicWrite, AFullDiskIsAnIoErrorAndLeavesTheOldFile) {
    // A file size limit makes every write past 64 KiB fail as on a full disk
    // (EFBIG); in a child process, so the limit does not outlive the test.
    const auto dir = test::scratch_dir();
    const auto path = dir / "mesh.su2";
    write_plain(path, "old\n");
    const Mesh mesh = large_mesh();
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        set_num_threads(1);  // a forked child runs no OpenMP region (libgomp is not fork-safe)
        ::signal(SIGXFSZ, SIG_IGN);  // report EFBIG instead of killing the process
        const rlimit limit{64 * 1024, 64 * 1024};
        if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) ::_exit(20);
        try {
            write_su2(path, mesh);
        } catch (const IoError&) {
            ::_exit(0);
        } catch (...) {
            ::_exit(21);
        }
        ::_exit(22);  // no error: the limit did not apply
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status)) << status;
    EXPECT_EQ(WEXITSTATUS(status), 0) << "20: setrlimit failed, 21: another error, 22: no error";
    EXPECT_EQ(read_file(path), "old\n");
    EXPECT_EQ(entries(dir), std::vector<std::string>{"mesh.su2"});
}

TEST(AtomicWrite, EveryOutputOfTheProjectGoesThroughIt) {
    // No source outside atomic_write.cpp opens a file for writing: every
    // output (mesh, plan, VTU, image, report) must use write_file_atomically.
    const std::regex writes_a_file(
        R"(\bofstream\b|\bstd::fstream\b|\bfopen\s*\(|\bfdopen\s*\(|\bcreat\s*\(|O_WRONLY|O_RDWR|O_CREAT|)"
        R"(cairo_surface_write_to_png\s*\(|\bFILE\s*\*)");
    int files = 0;
    for (const char* root : {"src", "apps"}) {
        for (const auto& e : std::filesystem::recursive_directory_iterator(test::source_dir() / root)) {
            const std::string ext = e.path().extension().string();
            if (ext != ".cpp" && ext != ".hpp") continue;
            if (e.path().filename() == "atomic_write.cpp") continue;
            ++files;
            std::ifstream in(e.path());
            std::string line;
            for (int n = 1; std::getline(in, line); ++n) {
                const auto code = line.substr(0, line.find("//"));
                EXPECT_FALSE(std::regex_search(code, writes_a_file))
                    << e.path().string() << ":" << n << " writes a file without write_file_atomically: " << line;
            }
        }
    }
    EXPECT_GT(files, 50);
}

TEST(AtomicWrite, WritesWithAndWithoutSyncGiveTheSameFileAndSyncIsOffByDefault) {
    EXPECT_FALSE(sync_writes());
    const auto dir = test::scratch_dir();
    const Mesh mesh = large_mesh();
    write_su2(dir / "plain.su2", mesh);
    set_sync_writes(true);
    EXPECT_TRUE(sync_writes());
    write_su2(dir / "synced.su2", mesh);
    write_file_atomically_at(dir / "synced.txt", [](const std::filesystem::path& tmp) { write_plain(tmp, "at\n"); });
    set_sync_writes(false);
    EXPECT_FALSE(sync_writes());
    EXPECT_EQ(read_file(dir / "synced.su2"), read_file(dir / "plain.su2"));
    EXPECT_EQ(read_file(dir / "synced.txt"), "at\n");
    EXPECT_EQ(entries(dir), (std::vector<std::string>{"plain.su2", "synced.su2", "synced.txt"}));
}
