#include "dgwarp/bench/bench_pictures.hpp"

#include "dgwarp/picture/mesh_picture.hpp"

namespace dgwarp {

std::vector<std::string> write_bench_pictures(const std::filesystem::path& folder, const std::filesystem::path& markdown,
                                              const std::string& case_name, const Mesh& original, const Mesh& mesh,
                                              std::span<const double> quality, const std::string& stem,
                                              const std::string& caption) {
    std::vector<std::string> written;
    if (mesh.dim != 2) return written;
    std::filesystem::create_directories(folder);
    PictureOptions o;
    o.width = 800;
    o.height = 600;
    o.title = caption;
    const auto rel = [&](const std::filesystem::path& p) {
        return markdown.empty() ? p.string()
                                : std::filesystem::relative(p, std::filesystem::absolute(markdown).parent_path()).string();
    };
    // The whole mesh for the original only; deformed meshes as close-ups (as
    // the paper's figures), which keeps the pictures few enough to commit.
    if (&original == &mesh) {
        const auto whole = std::filesystem::absolute(folder) / (stem + ".png");
        write_mesh_picture(whole, mesh, quality, o);
        written.push_back(rel(whole));
    }
    // Close-up: of the moving body; for the NACA0012, of its trailing edge and
    // the sliver behind it (the trailing edge is the original mesh's airfoil
    // node of largest x: node ids do not change).
    const Marker& body = mesh.markers.front();
    std::vector<NodeId> nodes = marker_nodes(body);
    if (case_name == "naca0012") {
        NodeId te = nodes.front();
        for (NodeId n : nodes)
            if (original.points[2 * n] > original.points[2 * te]) te = n;
        const double x = mesh.points[2 * te], y = mesh.points[2 * te + 1];
        o.window = std::array<double, 4>{x - 0.06, x + 0.06, y - 0.045, y + 0.045};
    } else {
        o.window = window_around(mesh, nodes, 1.6, 4.0 / 3.0);
    }
    o.title = caption + " (close-up)";
    const auto close = std::filesystem::absolute(folder) / (stem + "-close.png");
    write_mesh_picture(close, mesh, quality, o);
    written.push_back(rel(close));
    return written;
}

}  // namespace dgwarp
