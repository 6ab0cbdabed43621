#include "fuzz_checks.hpp"

#include <stdlib.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "dgwarp/core/error.hpp"
#include "dgwarp/core/hash.hpp"
#include "dgwarp/io/cgns/cgns.hpp"
#include "dgwarp/io/gmsh/gmsh.hpp"
#include "dgwarp/io/motion_file.hpp"
#include "dgwarp/io/openfoam/openfoam.hpp"
#include "dgwarp/plan/plan_file.hpp"
#include "dgwarp/io/su2/su2.hpp"
#include "dgwarp/io/vtu/vtu.hpp"

namespace dgwarp::fuzz {

namespace {

std::string as_text(std::span<const std::uint8_t> data) {
    return {reinterpret_cast<const char*>(data.data()), data.size()};
}

void require(bool ok, const char* what) {
    if (!ok) throw PropertyViolation(what);
}

/// An empty folder for the lifetime of the process.
class EmptyFolder {
public:
    EmptyFolder() {
        std::string pattern = (std::filesystem::temp_directory_path() / "dgwarp-fuzz-XXXXXX").string();
        if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
        path_ = pattern;
    }
    ~EmptyFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

bool has_string_with_slash(const nlohmann::json& j) {
    if (j.is_string()) return j.get_ref<const std::string&>().find('/') != std::string::npos;
    if (j.is_object())
        for (const auto& [key, value] : j.items())
            if (key.find('/') != std::string::npos || has_string_with_slash(value)) return true;
    if (j.is_array())
        for (const auto& value : j)
            if (has_string_with_slash(value)) return true;
    return false;
}


}  // namespace

void check_su2(std::span<const std::uint8_t> data) {
    const std::string text = as_text(data);
    const Mesh mesh = read_su2_text("fuzz.su2", text);
    std::ostringstream out;
    try {
        write_su2(out, mesh);
    } catch (const Error&) {
        return;  // a mesh the writer cannot store (e.g. a marker name)
    }
    require(read_su2_text("fuzz-written.su2", out.str()) == mesh, "SU2 write then read changed the mesh");
    if (text.find("NZONE") != std::string::npos) read_su2_text("fuzz.su2", text, 2);
}

void check_gmsh(std::span<const std::uint8_t> data) {
    const Mesh mesh = read_gmsh_text("fuzz.msh", as_text(data));
    for (int version : {41, 22}) {
        std::ostringstream out;
        try {
            write_gmsh(out, mesh, version);
        } catch (const Error&) {
            return;  // a mesh the writer cannot store (e.g. a marker name with a quote)
        }
        require(read_gmsh_text("fuzz-written.msh", out.str()) == mesh, "Gmsh write then read changed the mesh");
    }
}

void check_vtu(std::span<const std::uint8_t> data) {
    const Mesh mesh = read_vtu_text("fuzz.vtu", as_text(data));
    std::ostringstream out;
    try {
        write_vtu(out, mesh);
    } catch (const Error&) {
        return;  // a mesh the writer cannot store
    }
    require(read_vtu_text("fuzz-written.vtu", out.str()) == mesh, "VTU write then read changed the mesh");
}

void check_openfoam(std::span<const std::uint8_t> data) {
    const std::string text = as_text(data);
    PolyMeshFiles files;
    std::string* parts[] = {&files.points, &files.faces, &files.owner, &files.neighbour, &files.boundary};
    const std::string separator = openfoam_file_separator;
    std::size_t at = 0;
    for (std::string* part : parts) {
        if (at > text.size()) break;
        const std::size_t end = std::min(text.find(separator, at), text.size());
        *part = text.substr(at, end - at);
        at = end + separator.size();
    }
    OpenFoamSource source;
    const Mesh mesh = read_openfoam_files("fuzz", files, &source);
    for (const foam::Format format : {foam::Format::ascii, foam::Format::binary}) {
        PolyMeshFiles written;
        try {
            written = write_openfoam_files(mesh, {format, &source});
        } catch (const Error&) {
            return;  // a mesh no polyMesh of dgwarp's can hold (a face in two patches, a patch name with a blank)
        }
        OpenFoamSource again;
        require(read_openfoam_files("fuzz-written", written, &again) == mesh, "OpenFOAM write then read changed the mesh");
        require(again.patches == source.patches, "OpenFOAM write then read changed the patches");
    }
}

void check_cgns(std::span<const std::uint8_t> data) {
    static const EmptyFolder folder;
    const std::filesystem::path input = folder.path() / "fuzz.cgns", written = folder.path() / "fuzz-written.cgns",
                                copy = folder.path() / "fuzz-copy.cgns";
    {
        std::ofstream out(input, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data.data()), static_cast<std::streamsize>(data.size()));
        if (!out) throw std::runtime_error("cannot write " + input.string());
    }
    CgnsSource source;
    const Mesh mesh = read_cgns(input, &source);
    write_cgns_points(copy, source, mesh.points);
    require(read_cgns(copy) == mesh, "CGNS points written back changed the mesh");
    try {
        write_cgns(written, mesh);
    } catch (const Error&) {
        return;  // a mesh the writer cannot store (a marker name CGNS cannot hold, an empty marker)
    }
    // A marker without elements is written as a boundary family, which comes
    // back after the BCs' markers (docs/CGNS.md): compare in that order.
    Mesh expected = mesh;
    std::stable_partition(expected.markers.begin(), expected.markers.end(),
                          [](const Marker& m) { return !m.elements.empty(); });
    require(read_cgns(written) == expected, "CGNS write then read changed the mesh");
}

void check_motion(std::span<const std::uint8_t> data) {
    static const EmptyFolder base;
    const std::string text = as_text(data);
    const nlohmann::json parsed = nlohmann::json::parse(text, nullptr, false);
    if (!parsed.is_discarded() && has_string_with_slash(parsed)) return;
    const MotionSpec spec = parse_motion_file(text, "fuzz.json", base.path());
    const std::size_t frames = frame_count(spec);
    require(frames >= 1 && frames <= static_cast<std::size_t>(max_time_steps), "frame count out of range");
    for (const std::size_t k : {std::size_t{0}, frames - 1}) {
        const MotionFrame& frame = frame_spec(spec, k);
        for (const auto& [name, motion] : frame.markers)
            if (const auto* periodic = std::get_if<PeriodicMotion>(&motion))
                periodic_motion_at(*periodic, frame_time(spec, k));
    }
}

std::vector<std::byte> with_valid_plan_checksum(std::span<const std::byte> bytes) {
    return with_recomputed_plan_checksum(bytes);
}

void check_plan(std::span<const std::uint8_t> data) {
    const auto bytes = std::as_bytes(data);
    Plan plan;
    try {
        plan = load_plan_bytes(bytes, "fuzz.plan");
    } catch (const Error&) {
        plan = load_plan_bytes(with_valid_plan_checksum(bytes), "fuzz-checksum-fixed.plan");
    }
    // One step over the whole plan (DG-IDW or DG-harmonic): every index it holds is followed.
    auto step = [](const auto& p, auto&& deform_step) {
        const std::vector<double> points(static_cast<std::size_t>(p.num_points() * p.dim), 0.5);
        BoundaryMotion motion(p.boundary_nodes.size());
        for (std::size_t b = 0; b < motion.size(); ++b)
            if (p.boundary_moving[b]) motion[b] = {{0.1, 0.2, 0.3}, {0.0, 0.0, 0.1}, {0.5, 0.5, 0.5}};
        std::vector<double> out(points.size());
        deform_step(p, points, motion, out);
    };
    if (const auto* d = std::get_if<DgIdwPlan>(&plan))
        step(*d, [](const DgIdwPlan& p, const auto& x, const auto& m, auto& y) { deform_dg_idw(p, x, m, y); });
    if (const auto* h = std::get_if<DgHarmonicPlan>(&plan))
        step(*h, [](const DgHarmonicPlan& p, const auto& x, const auto& m, auto& y) { deform_dg_harmonic(p, x, m, y); });
}

}  // namespace dgwarp::fuzz
