#include "support/test_paths.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>
#include <string_view>

namespace dgwarp::test {

std::filesystem::path source_dir() { return DGWARP_SOURCE_DIR; }

std::filesystem::path su2_meshes_dir() {
    const char* meshes = std::getenv("DGWARP_SHARED_MESHES");
    return std::filesystem::path(meshes && *meshes ? meshes : DGWARP_SHARED_MESHES) / "su2";
}

bool running_in_ci() {
    const char* ci = std::getenv("CI");
    return ci && std::string_view(ci) == "true";
}

std::vector<std::filesystem::path> su2_meshes() {
    std::vector<std::filesystem::path> files;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(su2_meshes_dir(), ec))
        if (e.path().extension() == ".su2") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::filesystem::path cli_path() { return DGWARP_CLI; }

std::filesystem::path scratch_dir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "dgwarp";
    std::replace(name.begin(), name.end(), '/', '_');
    // Tagged with the build folder (from the CLI's path), so suites of two
    // builds or two clones running at once never share (and remove) a folder.
    char tag[17];
    std::snprintf(tag, sizeof tag, "%016zx", std::hash<std::string>{}(cli_path().string()));
    auto dir = std::filesystem::temp_directory_path() / ("dgwarp-test-" + std::string(tag) + "-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

CommandResult run_command(const std::string& command) {
    const auto dir = std::filesystem::temp_directory_path();
    static int counter = 0;
    const auto stem = dir / ("dgwarp-cmd-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    const std::string out_file = stem.string() + ".out", err_file = stem.string() + ".err";
    const std::string full = command + " >" + out_file + " 2>" + err_file;
    const int status = std::system(full.c_str());
    CommandResult r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    auto slurp = [](const std::string& f) {
        std::ifstream in(f);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    };
    r.out = slurp(out_file);
    r.err = slurp(err_file);
    std::remove(out_file.c_str());
    std::remove(err_file.c_str());
    return r;
}

CommandResult run_cli(const std::string& args) { return run_command(cli_path().string() + " " + args); }

std::string quoted(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

std::filesystem::path write_text(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path) << text;
    return path;
}

std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace dgwarp::test
