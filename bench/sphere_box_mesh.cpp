#include "sphere_box_mesh.hpp"

#include "dgwarp/cases/child_process.hpp"
#include "dgwarp/cases/sphere_box.hpp"
#include "dgwarp/core/stopwatch.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <numeric>
#include <stdexcept>

namespace dgwarp::bench {

namespace {

constexpr char magic[8] = {'D', 'G', 'W', 'S', 'P', 'H', 'M', '1'};

// Runs Gmsh (the library's make_sphere_box); returns the mesh. Called in a child process.
SphereBoxMesh generate(const SphereBoxCase& c) {
    const Clock::time_point t0 = Clock::now();
    const Mesh mesh = make_sphere_box(c.options);
    SphereBoxMesh m;
    m.points = mesh.points;
    m.sphere_nodes = marker_nodes(find_marker(mesh, "sphere"));
    m.box_nodes = marker_nodes(find_marker(mesh, "box"));
    m.generate_seconds = seconds_since(t0);
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
    run_in_child_process([&] { save(file, generate(c)); }, timeout_seconds, "Gmsh's mesh of case " + c.name);
    if (!load(file, m)) throw std::runtime_error("cannot read back " + file.string());
    return m;
}

SphereBoxMesh renumbered_along_hilbert_curve(const SphereBoxMesh& m) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Point = K::Point_3;
    const std::size_t n = m.num_points();
    std::vector<Point> points(n);
    for (std::size_t i = 0; i < n; ++i) points[i] = Point(m.points[3 * i], m.points[3 * i + 1], m.points[3 * i + 2]);
    std::vector<std::size_t> order(n);  // order[k]: the old id of new node k
    std::iota(order.begin(), order.end(), std::size_t{0});
    using Traits = CGAL::Spatial_sort_traits_adapter_3<K, CGAL::Pointer_property_map<Point>::type>;
    CGAL::hilbert_sort(order.begin(), order.end(), Traits(CGAL::make_property_map(points)),
                       CGAL::Hilbert_sort_median_policy());
    std::vector<NodeId> new_id(n);
    for (std::size_t k = 0; k < n; ++k) new_id[order[k]] = static_cast<NodeId>(k);
    SphereBoxMesh r;
    r.generate_seconds = m.generate_seconds;
    r.points.resize(m.points.size());
    for (std::size_t k = 0; k < n; ++k)
        for (int d = 0; d < 3; ++d) r.points[3 * k + d] = m.points[3 * order[k] + d];
    for (const auto& [from, to] : {std::pair{&m.sphere_nodes, &r.sphere_nodes}, std::pair{&m.box_nodes, &r.box_nodes}}) {
        for (NodeId id : *from) to->push_back(new_id[static_cast<std::size_t>(id)]);
        std::sort(to->begin(), to->end());
    }
    return r;
}

}  // namespace dgwarp::bench
