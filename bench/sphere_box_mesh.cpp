#include "sphere_box_mesh.hpp"

#include <gmsh.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <thread>
#include <unordered_map>

namespace dgwarp::bench {

namespace {

constexpr char magic[8] = {'D', 'G', 'W', 'S', 'P', 'H', 'M', '1'};

// Runs Gmsh; returns the mesh. Called in a child process.
SphereBoxMesh generate(const SphereBoxCase& c) {
    const auto t0 = std::chrono::steady_clock::now();
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.NumThreads", 2);
    gmsh::option::setNumber("Mesh.Algorithm", 6);     // Frontal-Delaunay surfaces
    gmsh::option::setNumber("Mesh.Algorithm3D", 10);  // HXT, parallel
    gmsh::option::setNumber("Mesh.Optimize", 0);
    gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromPoints", 0);
    gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
    gmsh::model::add("sphere_box");
    const int box = gmsh::model::occ::addBox(-5, -5, -5, 10, 10, 10);
    const int sphere = gmsh::model::occ::addSphere(0, 0, 0, 1);
    gmsh::vectorpair out;
    std::vector<gmsh::vectorpair> map;
    gmsh::model::occ::cut({{3, box}}, {{3, sphere}}, out, map);
    gmsh::model::occ::synchronize();

    // Which surfaces are the sphere (its bounding box is within radius 1.01).
    gmsh::vectorpair surfaces;
    gmsh::model::getEntities(surfaces, 2);
    std::vector<double> sphere_surfaces;
    std::vector<int> sphere_tags, box_tags;
    for (const auto& [dim, tag] : surfaces) {
        double x0, y0, z0, x1, y1, z1;
        gmsh::model::getBoundingBox(dim, tag, x0, y0, z0, x1, y1, z1);
        const bool on_sphere = std::max({std::abs(x0), std::abs(y0), std::abs(z0), x1, y1, z1}) < 1.01;
        (on_sphere ? sphere_tags : box_tags).push_back(tag);
        if (on_sphere) sphere_surfaces.push_back(tag);
    }
    // Size: h_sphere on the sphere, growing linearly with the distance from it
    // up to h_max; near the box faces (within 1) it blends up to h_box, so the
    // box's node count is set by h_box alone.
    auto distance_to = [](const std::vector<double>& faces) {
        const int f = gmsh::model::mesh::field::add("Distance");
        gmsh::model::mesh::field::setNumbers(f, "FacesList", faces);
        gmsh::model::mesh::field::setNumber(f, "NNodesByEdge", 200);
        return f;
    };
    std::vector<double> box_surfaces(box_tags.begin(), box_tags.end());
    const int from_sphere = distance_to(sphere_surfaces), from_box = distance_to(box_surfaces);
    const int graded = gmsh::model::mesh::field::add("MathEval");
    gmsh::model::mesh::field::setString(graded, "F", "Min(" + std::to_string(c.h_max) + ", " +
                                                         std::to_string(c.h_sphere) + " + " + std::to_string(c.growth) +
                                                         " * F" + std::to_string(from_sphere) + ")");
    const int near_box = gmsh::model::mesh::field::add("Threshold");
    gmsh::model::mesh::field::setNumber(near_box, "IField", from_box);
    gmsh::model::mesh::field::setNumber(near_box, "LcMin", c.h_box);
    gmsh::model::mesh::field::setNumber(near_box, "LcMax", 1e-3);
    gmsh::model::mesh::field::setNumber(near_box, "DistMin", 0);
    gmsh::model::mesh::field::setNumber(near_box, "DistMax", 1);
    const int size = gmsh::model::mesh::field::add("Max");
    gmsh::model::mesh::field::setNumbers(size, "FieldsList", {double(graded), double(near_box)});
    gmsh::model::mesh::field::setAsBackgroundMesh(size);
    gmsh::model::mesh::generate(3);

    // All nodes, renumbered 0.. in Gmsh's order.
    std::vector<std::size_t> tags;
    std::vector<double> coords, parametric;
    gmsh::model::mesh::getNodes(tags, coords, parametric, -1, -1, false, false);
    SphereBoxMesh m;
    m.points = coords;
    std::unordered_map<std::size_t, NodeId> index;
    index.reserve(tags.size());
    for (std::size_t i = 0; i < tags.size(); ++i) index[tags[i]] = static_cast<NodeId>(i);
    auto collect = [&](const std::vector<int>& entity_tags, std::vector<NodeId>& ids) {
        for (int tag : entity_tags) {
            std::vector<std::size_t> t;
            std::vector<double> x, p;
            gmsh::model::mesh::getNodes(t, x, p, 2, tag, true, false);
            for (std::size_t n : t) ids.push_back(index.at(n));
        }
        std::sort(ids.begin(), ids.end());
        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    };
    collect(sphere_tags, m.sphere_nodes);
    collect(box_tags, m.box_nodes);
    gmsh::finalize();
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
    const auto file = cache_dir / ("sphere_box_" + c.name + "_" + std::to_string(c.h_sphere) + "_" +
                                   std::to_string(c.h_max) + "_" + std::to_string(c.growth) + "_" +
                                   std::to_string(c.h_box) + ".bin");
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
