#pragma once
// The CLI tests' common input: the rect-box mesh written by `dgwarp demo` and
// a motion file turning its rectangle 10° about the origin.
#include <filesystem>

namespace dgwarp::test {

struct RectBoxFiles {
    std::filesystem::path dir;     // a fresh scratch_dir() of the current test
    std::filesystem::path mesh;    // dir/rect_box.su2
    std::filesystem::path motion;  // dir/m.json: {"rectangle": rotate 10° about (0, 0)}
};

/// Runs `dgwarp demo -o DIR` in a fresh scratch folder (expecting exit 0) and
/// writes the rotation beside the mesh.
RectBoxFiles rect_box_files();

}  // namespace dgwarp::test
