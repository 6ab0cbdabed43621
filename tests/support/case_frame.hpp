#pragma once
// One of the built-in cases (cases/paper_cases.hpp) with one of its motions,
// resolved on the mesh: its boundary and its first frame.
#include <string>

#include "dgwarp/cases/paper_cases.hpp"
#include "dgwarp/motion/resolve_motion.hpp"

namespace dgwarp::test {

struct CaseFrame {
    Mesh mesh;
    MotionSpec spec;
    ResolvedBoundary boundary;
    ResolvedFrame frame;  // frame 0
};

inline CaseFrame case_frame(const std::string& name, const std::string& motion) {
    CaseFrame c;
    c.mesh = make_case(name);
    for (const CaseMotion& m : case_motions(name, c.mesh))
        if (m.name == motion) c.spec = m.spec;
    c.boundary = resolve_boundary(c.mesh, c.spec);
    c.frame = resolve_frame(c.mesh, c.spec, c.boundary, 0);
    return c;
}

}  // namespace dgwarp::test
