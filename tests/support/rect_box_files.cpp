#include "support/rect_box_files.hpp"

#include <gtest/gtest.h>

#include "support/test_paths.hpp"

namespace dgwarp::test {

RectBoxFiles rect_box_files() {
    RectBoxFiles f;
    f.dir = scratch_dir();
    EXPECT_EQ(run_cli("demo -o " + quoted(f.dir)).exit_code, 0);
    f.mesh = f.dir / "rect_box.su2";
    f.motion = write_text(f.dir / "m.json", R"({"markers": {"rectangle": {"rotate": {"angle_deg": 10, "center": [0, 0]}}}})");
    return f;
}

}  // namespace dgwarp::test
