#include "dgwarp/job/frame_outputs.hpp"

#include <algorithm>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/openfoam/openfoam_frames.hpp"
#include "dgwarp/quality/mesh_quality.hpp"

namespace dgwarp {

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

std::optional<Warning> stale_frames_warning(const std::filesystem::path& out, std::size_t frames) {
    const std::vector<std::filesystem::path> stale = stale_frames(out, frames);
    if (stale.empty()) return std::nullopt;
    const auto count = static_cast<std::int64_t>(stale.size());
    Warning w(WarningCode::stale_frames,
              stale.front().string() + (count > 1 ? " ... " + stale.back().string() : std::string()) + " (" +
                  std::to_string(count) + " file" + (count > 1 ? "s" : "") +
                  ") are left from an earlier run, not written by this one (" + std::to_string(frames) + " frame" +
                  (frames > 1 ? "s" : "") + "); remove them if they are not wanted",
              "", count);
    return w;
}

std::optional<Warning> unread_processors_warning(const std::string& case_path, bool processors_written) {
    if (processors_written || !reads_openfoam(case_path)) return std::nullopt;
    const std::vector<std::filesystem::path> folders = openfoam_unread_processor_folders(case_path);
    if (folders.empty()) return std::nullopt;
    const std::string names = folders.size() > 1 ? "s (" + folders.front().filename().string() + " ... " +
                                                       folders.back().filename().string() + ")"
                                                 : " (" + folders.front().filename().string() + ")";
    return Warning(WarningCode::processors_unchanged,
                   case_path + " holds constant/polyMesh and " + std::to_string(folders.size()) + " processor folder" +
                       names +
                       ": this run reads and writes the whole mesh (constant/polyMesh) only; a parallel run reads the "
                       "processor folders, which it does not change",
                   "", static_cast<std::int64_t>(folders.size()));
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

std::filesystem::path write_frame(JobInputs& in, FrameOutputs& o, std::size_t frame, std::vector<double>& points,
                                  const std::vector<double>& quality) {
    if (!o.foam_times.empty()) {
        if (frame >= o.foam_times.size())
            throw Error("write_frame: frame " + std::to_string(frame) + " of " + std::to_string(o.foam_times.size()) +
                        " time folders");
        const std::string& time = o.foam_times[frame];
        if (!o.base_written) write_openfoam_frame_base(o.out, time, output_mesh(in), in.extras, o.beside);
        o.base_written = true;
        return write_openfoam_frame_points(o.out, time, output_points(in, std::span<const double>(points), o.lifted),
                                           in.extras, o.beside);
    }
    const std::filesystem::path path = frame_path(o.out, frame, o.frames);
    std::vector<double>& written = output_points(in, points, o.lifted);
    const MeshFields fields = writes_fields(path) ? deformation_fields(output_mesh(in), written, quality,
                                                                       quality_ratios(quality, in.original.quality))
                                                  : MeshFields{};
    WriteOptions options;
    options.extras = &in.extras;  // an SU2 output keeps the input's other zones, FFD boxes, periodic data
    write_output_mesh(in, path, written, fields, options);
    return path;
}

}  // namespace dgwarp
