#include "dgwarp/io/gmsh/gmsh_sections.hpp"

#include <algorithm>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/gmsh/gmsh_record.hpp"

namespace dgwarp::msh {

GmshContent::GmshContent(std::size_t size)
    // Tags below file_size / 4 are mapped densely: the table (4 bytes per
    // entry) is never larger than the file, yet holds tags 1..N, since every
    // node takes more than 4 bytes of text.
    : file_size(size), node_ids(static_cast<std::int64_t>(size / 4 + 64)) {}

std::uint32_t GmshContent::group_of(std::vector<int> tags) {
    std::sort(tags.begin(), tags.end());
    tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
    const auto [it, inserted] = group_index_.emplace(tags, static_cast<std::uint32_t>(group_tags.size()));
    if (inserted) group_tags.push_back(std::move(tags));
    return it->second;
}

void read_mesh_format(TextReader& r, GmshContent& content) {
    require_record(r, "the format line 'version file-type data-size'");
    const std::string_view version = r.require_token("the MSH version number");
    const std::int64_t file_type = r.next_int("the file type (0 for ASCII)");
    r.next_int("the data size");
    double v = 0;
    if (!parse_double(version, v)) r.fail("the MSH version number (4.1 or 2.2)", version);
    if (v == 4.1)
        content.version = 41;
    else if (v == 2.2)
        content.version = 22;
    else
        throw FormatError(r.file() + ": MSH version " + std::string(version) +
                          " is not supported; dgwarp reads MSH 4.1 and 2.2 (save with Gmsh option "
                          "Mesh.MshFileVersion = 4.1)");
    if (file_type != 0)
        throw FormatError(r.file() + ": binary MSH files are not supported; dgwarp reads ASCII MSH only "
                          "(save with Gmsh option Mesh.Binary = 0)");
    expect_end_of_record(r, "the format line");
    expect_end_marker(r, "$EndMeshFormat");
}

void read_physical_names(TextReader& r, GmshContent& content) {
    require_record(r, "the number of physical names");
    const std::int64_t count = read_count(r, "the number of physical names");
    expect_end_of_record(r, "the number of physical names");
    for (std::int64_t i = 0; i < count; ++i) {
        require_record(r, "a physical name 'dimension tag \"name\"'");
        const int dim = read_dimension(r, "the physical group dimension");
        const int tag = read_int32(r, "the physical tag");
        const std::string_view quoted = r.rest_of_line();
        if (quoted.size() < 2 || quoted.front() != '"' || quoted.back() != '"')
            r.fail("a physical name in double quotes", quoted.empty() ? "end of line" : quoted);
        if (!content.physical_names.emplace(std::pair{dim, tag}, std::string(quoted.substr(1, quoted.size() - 2))).second)
            r.fail("a (dimension, tag) pair not named before", std::to_string(dim) + " " + std::to_string(tag));
    }
    expect_end_marker(r, "$EndPhysicalNames");
}

void read_entities(TextReader& r, GmshContent& content) {
    require_record(r, "the entity counts 'numPoints numCurves numSurfaces numVolumes'");
    std::int64_t counts[4];
    for (std::int64_t& c : counts) c = read_count(r, "an entity count");
    expect_end_of_record(r, "the entity counts");
    constexpr const char* what[] = {"a point entity 'tag x y z numPhysicalTags tags...'",
                                    "a curve entity 'tag box(6) numPhysicalTags tags... numBoundingPoints tags...'",
                                    "a surface entity 'tag box(6) numPhysicalTags tags... numBoundingCurves tags...'",
                                    "a volume entity 'tag box(6) numPhysicalTags tags... numBoundingSurfaces tags...'"};
    for (int dim = 0; dim < 4; ++dim) {
        for (std::int64_t i = 0; i < counts[dim]; ++i) {
            require_record(r, what[dim]);
            const int tag = read_int32(r, "the entity tag");
            for (int k = 0; k < (dim == 0 ? 3 : 6); ++k) r.next_double(dim == 0 ? "a point coordinate" : "a bounding box coordinate");
            // Tags are pushed one by one (no reserve from the count): a huge count
            // fails at the end of the line.
            std::vector<int> physicals;
            const std::int64_t num_physicals = read_count(r, "the number of physical tags");
            for (std::int64_t k = 0; k < num_physicals; ++k) physicals.push_back(read_int32(r, "a physical tag"));
            if (dim > 0) {
                const std::int64_t num_bounding = read_count(r, "the number of bounding entities");
                for (std::int64_t k = 0; k < num_bounding; ++k) read_int32(r, "a bounding entity tag");
            }
            expect_end_of_record(r, "the entity");
            if (!content.entity_physicals.emplace(std::pair{dim, tag}, std::move(physicals)).second)
                r.fail("an entity tag not used before in this dimension", std::to_string(tag));
        }
    }
    expect_end_marker(r, "$EndEntities");
    content.has_entities = true;
}

void skip_section(TextReader& r, std::string_view name) {
    const std::string end = "$End" + std::string(name);
    while (r.next_line())
        if (trim(r.line()) == end) return;
    r.fail(end + " closing the $" + std::string(name) + " section", "end of file");
}

}  // namespace dgwarp::msh
