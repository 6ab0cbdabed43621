#pragma once
// dgwarp.Motion: a parsed motion (motion_spec.hpp), from a dict in the
// motion-file form (docs/MOTION.md) or a motion file. A dict goes through
// Python's json and the library's motion-file parser, so it is checked as a
// file is, with the same messages (naming the key path, e.g.
// markers.airfoil.rotate.angle_deg).
#include <pybind11/pybind11.h>

#include <memory>

#include "dgwarp/motion/motion_spec.hpp"

namespace dgwarp::python {

struct PyMotion {
    MotionSpec spec;
};

using MotionPtr = std::shared_ptr<const PyMotion>;

/// `obj` as a motion: a Motion, a dict (relative file names in it are
/// relative to the current folder), or a path (str or os.PathLike) of a
/// motion file. TypeError for anything else.
MotionPtr motion_arg(pybind11::handle obj);

/// Whether `obj` is something motion_arg takes.
bool is_motion_like(pybind11::handle obj);

}  // namespace dgwarp::python
