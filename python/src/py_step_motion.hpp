#pragma once
// One step's motion for a plan, from what Plan.deform was given, and what
// follows the step: the pieces of `dgwarp deform`'s frame loop
// (apps/dgwarp/cmd_deform.cpp), through the same library calls.
#include <pybind11/pybind11.h>

#include <span>

#include "dgwarp/motion/motion_spec.hpp"
#include "dgwarp/motion/resolve_motion.hpp"
#include "dgwarp/run/deform_frame.hpp"
#include "py_plan.hpp"

namespace dgwarp::python {

/// A motion's frame resolved against the plan's boundary (resolve_frame),
/// after checking that the motion fits the plan: it names markers of the
/// mesh, moves no marker the plan holds static, has the plan's shared-node
/// rule. IndexError for a frame out of range.
ResolvedFrame resolve_motion_frame(const PyPlan& p, const MotionSpec& spec, std::size_t frame);

/// One motion per boundary node from arrays (translation, rotation vector,
/// centre): each None (zero), one vector for every moving node, or one row
/// per boundary node in Plan.boundary_nodes order (static rows zero).
BoundaryMotion motion_from_arrays(const PyPlan& p, pybind11::handle translation, pybind11::handle rotation,
                                  pybind11::handle center);

/// After a step that wrote `points`: untangle when `untangle` is True (cells
/// at or below `target`), DG-harmonic's last resort when it is None, nothing
/// when False, as `dgwarp deform` does (finish_frame), and the frame's
/// quality in `report`. Nothing when there is no repair to run and not
/// `measure`; returns whether it ran. Releases the GIL. `measured`: the
/// cells of `points` when the step measured them (step_frame).
bool finish_step(const PyPlan& p, std::span<double> points, const pybind11::object& untangle, double target,
                 bool measure, FrameReport& report, std::optional<FrameCells> measured = std::nullopt);

}  // namespace dgwarp::python
