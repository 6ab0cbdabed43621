#include "frame_output.hpp"

#include <algorithm>
#include <numeric>

namespace dgwarp::cli {

std::filesystem::path frame_path(const std::filesystem::path& out, std::size_t frame, std::size_t frames) {
    if (frames <= 1) return out;
    std::size_t digits = 4;
    for (std::size_t n = frames - 1; n >= 10000; n /= 10) ++digits;
    std::string number = std::to_string(frame);
    number.insert(0, digits > number.size() ? digits - number.size() : 0, '0');
    std::filesystem::path p = out;
    p.replace_filename(out.stem().string() + "_" + number + out.extension().string());
    return p;
}

std::vector<std::filesystem::path> stale_frames(const std::filesystem::path& out, std::size_t frames) {
    std::vector<std::filesystem::path> stale;
    const std::size_t numbered = std::max<std::size_t>(frames, 2);  // the numbering of a series
    for (std::size_t k = frames > 1 ? frames : 0;; ++k) {
        const std::filesystem::path p = frame_path(out, k, std::max(numbered, k + 1));
        std::error_code ec;
        if (!std::filesystem::exists(p, ec)) break;
        stale.push_back(p);
    }
    return stale;
}

MeshFields deformation_fields(const Mesh& original, std::span<const double> new_points,
                              const std::vector<double>& quality, const std::vector<double>& ratio) {
    const std::size_t n = original.num_points(), dim = static_cast<std::size_t>(original.dim);
    Field displacement{"displacement", 3, std::vector<double>(n * 3, 0.0)};
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t d = 0; d < dim; ++d)
            displacement.values[3 * i + d] = new_points[dim * i + d] - original.points[dim * i + d];
    MeshFields fields;
    fields.point_data.push_back(std::move(displacement));
    fields.cell_data.push_back({"quality", 1, quality});
    if (!ratio.empty()) fields.cell_data.push_back({"quality_ratio", 1, ratio});
    return fields;
}

}  // namespace dgwarp::cli
