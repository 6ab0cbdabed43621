#include "dgwarp/io/openfoam/openfoam_frames.hpp"

#include <algorithm>
#include <cstdio>
#include <set>
#include <system_error>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/output_checks.hpp"
#include "dgwarp/io/text_reader.hpp"

namespace dgwarp {

namespace {


std::string time_name(double t, int digits) {
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*g", digits, t);
    return buf;
}

/// The polyMesh folder the input mesh is read from ("" for another format).
std::filesystem::path input_poly_mesh(const std::filesystem::path& input_mesh) {
    if (!reads_openfoam(input_mesh)) return {};
    try {
        return find_poly_mesh(input_mesh);
    } catch (const Error&) {
        return {};
    }
}

bool same_folder(const std::filesystem::path& a, const std::filesystem::path& b) {
    std::error_code ec;
    return !a.empty() && !b.empty() && std::filesystem::equivalent(a, b, ec);
}

/// processorN under `out`.
std::filesystem::path processor_folder(const std::filesystem::path& out, std::size_t p) {
    return out / ("processor" + std::to_string(p));
}

}  // namespace

std::vector<std::string> openfoam_time_names(std::span<const double> times) {
    const std::size_t frames = times.size();
    if (frames <= 1) return {"0"};
    std::vector<std::string> names(frames);
    if (std::set<double>(times.begin(), times.end()).size() == frames) {
        for (int digits = 6; digits <= 17; ++digits) {
            for (std::size_t k = 0; k < frames; ++k) names[k] = time_name(times[k], digits);
            if (std::set<std::string>(names.begin(), names.end()).size() == frames) return names;
        }
    }
    for (std::size_t k = 0; k < frames; ++k) names[k] = std::to_string(k);
    return names;
}

std::vector<std::string> openfoam_frame_time_names(const MotionSpec& spec) {
    std::vector<double> times(frame_count(spec));
    for (std::size_t k = 0; k < times.size(); ++k) times[k] = frame_time(spec, k);
    return openfoam_time_names(times);
}

bool is_openfoam_time_name(std::string_view name) {
    double t = 0;
    return name == "constant" || parse_double(name, t);
}

void check_openfoam_frame_outputs(const std::filesystem::path& out, const std::vector<std::string>& times,
                                  const std::filesystem::path& input_mesh,
                                  const std::vector<std::filesystem::path>& inputs, bool with_processors) {
    std::vector<std::filesystem::path> processors;
    try {
        processors = openfoam_processor_meshes(input_mesh);
        if (with_processors)
            for (const auto& folder : openfoam_unread_processor_folders(input_mesh))
                processors.push_back(folder / "constant" / "polyMesh");
    } catch (const Error&) {
        // reading the mesh will say why
    }
    if (!processors.empty()) {
        check_nearest_folder_writable(out);
        for (std::size_t p = 0; p < processors.size(); ++p) {
            const std::filesystem::path base = openfoam_output_poly_mesh(processor_folder(out, p));
            for (const std::string& time : times) check_output(openfoam_points_file(processor_folder(out, p), time).file, inputs);
            if (same_folder(base, processors[p])) continue;
            for (const char* name : poly_mesh_file_names) check_output(base / name, inputs);
            for (const char* name : processor_addressing_file_names) check_output(base / name, inputs);
        }
        if (!with_processors) return;
    }
    const std::filesystem::path base = openfoam_output_poly_mesh(out);
    check_nearest_folder_writable(base);
    for (const std::string& time : times) check_output(openfoam_points_file(out, time).file, inputs);
    if (same_folder(base, input_poly_mesh(input_mesh))) return;  // the input case: nothing copied
    for (const char* name : poly_mesh_file_names) check_output(base / name, inputs);
}

namespace {

/// Each processor's polyMesh copied into OUT/processorN (not into itself;
/// without its points when `time` puts them there).
void copy_processor_bases(std::span<const OpenFoamProcessor> processors, const std::filesystem::path& out,
                          const std::string& time) {
    for (std::size_t p = 0; p < processors.size(); ++p) {
        const std::filesystem::path base = openfoam_output_poly_mesh(processor_folder(out, p));
        if (same_folder(base, processors[p].poly_mesh)) continue;
        const bool points_here = openfoam_points_file(processor_folder(out, p), time).file.parent_path() == base;
        copy_poly_mesh(processors[p].poly_mesh, base,
                       points_here ? std::vector<std::string>{"points", "points.gz"} : std::vector<std::string>{});
    }
}

/// Each processor's points (its own numbering and format) of the whole mesh's `points`.
void write_processor_points(std::span<const OpenFoamProcessor> processors, const std::filesystem::path& out,
                            const std::string& time, std::span<const double> points) {
    for (std::size_t p = 0; p < processors.size(); ++p) {
        const OpenFoamPointsFile file = openfoam_points_file(processor_folder(out, p), time);
        write_openfoam_points(file.file, processor_points(processors[p], points), processors[p].points_format,
                              file.location);
    }
}

}  // namespace

void write_openfoam_frame_base(const std::filesystem::path& out, const std::string& time, const Mesh& original,
                               const MeshExtras& extras, std::span<const OpenFoamProcessor> beside) {
    copy_processor_bases(beside, out, time);
    if (extras.openfoam && !extras.openfoam->processors.empty()) {
        copy_processor_bases(extras.openfoam->processors, out, time);
        return;
    }
    const std::filesystem::path base = openfoam_output_poly_mesh(out);
    const bool points_here = openfoam_points_file(out, time).file.parent_path() == base;
    if (extras.openfoam) {
        if (same_folder(base, extras.openfoam->poly_mesh)) return;
        copy_poly_mesh(extras.openfoam->poly_mesh, base,
                       points_here ? std::vector<std::string>{"points", "points.gz"} : std::vector<std::string>{});
    } else {
        write_openfoam(base, original);  // the original: OpenFOAM reads the time folders' points with its faces
    }
}

std::filesystem::path write_openfoam_frame_points(const std::filesystem::path& out, const std::string& time,
                                                  std::span<const double> points, const MeshExtras& extras,
                                                  std::span<const OpenFoamProcessor> beside) {
    write_processor_points(beside, out, time, points);
    if (extras.openfoam && !extras.openfoam->processors.empty()) {
        write_processor_points(extras.openfoam->processors, out, time, points);
        return openfoam_points_file(out / "processor*", time).file;
    }
    const OpenFoamPointsFile file = openfoam_points_file(out, time);
    write_openfoam_points(file.file, points, extras.openfoam ? extras.openfoam->points_format : foam::Format::ascii,
                          file.location);
    return file.file;
}

}  // namespace dgwarp
