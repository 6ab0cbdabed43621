#include "sphere_box_mesh.hpp"

#include "dgwarp/cases/sphere_box.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <thread>

namespace dgwarp::bench {

namespace {

constexpr char magic[8] = {'D', 'G', 'W', 'S', 'P', 'H', 'M', '1'};

// Runs Gmsh (the library's make_sphere_box); returns the mesh. Called in a child process.
SphereBoxMesh generate(const SphereBoxCase& c) {
    const auto t0 = std::chrono::steady_clock::now();
    const Mesh mesh = make_sphere_box(c.options);
    SphereBoxMesh m;
    m.points = mesh.points;
    m.sphere_nodes = marker_nodes(find_marker(mesh, "sphere"));
    m.box_nodes = marker_nodes(find_marker(mesh, "box"));
    m.generate_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return m;
}

template <class T>
void write_vector(std::ofstream& out, const std::vector<T>& v) {
    const std::int64_t n = static_cast<std::int64_t>(v.size());
    out.write(reinterpret_cast<const char*>(&n), sizeof n);
    out.write(reinterpret_cast<const char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(T)));
}

template <class T>
bool read_vector(std::ifstream& in, std::vector<T>& v) {
    std::int64_t n = 0;
    if (!in.read(reinterpret_cast<char*>(&n), sizeof n) || n < 0 || n > (std::int64_t{1} << 32)) return false;
    v.resize(static_cast<std::size_t>(n));
    return static_cast<bool>(in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(n * sizeof(T))));
}

void save(const std::filesystem::path& file, const SphereBoxMesh& m) {
    const auto tmp = file.string() + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out.write(magic, sizeof magic);
        out.write(reinterpret_cast<const char*>(&m.generate_seconds), sizeof m.generate_seconds);
        write_vector(out, m.points);
        write_vector(out, m.sphere_nodes);
        write_vector(out, m.box_nodes);
        if (!out) throw std::runtime_error("cannot write " + tmp);
    }
    std::filesystem::rename(tmp, file);
}

bool load(const std::filesystem::path& file, SphereBoxMesh& m) {
    std::ifstream in(file, std::ios::binary);
    char head[8];
    if (!in.read(head, sizeof head) || std::memcmp(head, magic, sizeof magic) != 0) return false;
    return in.read(reinterpret_cast<char*>(&m.generate_seconds), sizeof m.generate_seconds) &&
           read_vector(in, m.points) && read_vector(in, m.sphere_nodes) && read_vector(in, m.box_nodes);
}

}  // namespace

SphereBoxMesh sphere_box_mesh(const SphereBoxCase& c, const std::filesystem::path& cache_dir, int timeout_seconds) {
    std::filesystem::create_directories(cache_dir);
    const SphereBoxOptions& o = c.options;
    const auto file = cache_dir / ("sphere_box_" + c.name + "_" + std::to_string(o.h_sphere) + "_" +
                                   std::to_string(o.h_max) + "_" + std::to_string(o.growth) + "_" +
                                   std::to_string(o.h_box) + "_t" + std::to_string(o.threads) + ".bin");
    SphereBoxMesh m;
    if (load(file, m)) return m;

    // Gmsh runs in a child process, so a run that takes too long can be killed.
    const pid_t child = ::fork();
    if (child < 0) throw std::runtime_error("fork failed");
    if (child == 0) {
        try {
            save(file, generate(c));
            ::_exit(0);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "mesh generation failed: %s\n", e.what());
            ::_exit(1);
        }
    }
    const auto start = std::chrono::steady_clock::now();
    int status = 0;
    while (::waitpid(child, &status, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() - start > std::chrono::seconds(timeout_seconds)) {
            ::kill(child, SIGKILL);
            ::waitpid(child, &status, 0);
            throw std::runtime_error("Gmsh took more than " + std::to_string(timeout_seconds) + " s for case " + c.name);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !load(file, m))
        throw std::runtime_error("Gmsh mesh generation failed for case " + c.name);
    return m;
}

}  // namespace dgwarp::bench
