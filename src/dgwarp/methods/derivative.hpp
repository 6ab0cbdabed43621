#pragma once
// Derivatives of a step with respect to the boundary: for shape optimisation
// (an adjoint solver's surface sensitivities, IDWarp's warpDeriv) and for
// coupled solvers. A step of DG-IDW or DG-harmonic whose moving boundary
// nodes only translate (no rotation) is linear in their translations t:
//
//     points(t) = points0 + J t,
//
// with J of size (num_points × dim) × (num_boundary × dim), fixed by the
// plan (the same for every translation: these products are exact, not
// linearisations about a state). The translation of boundary index b is the
// move of the surface coordinates of boundary node boundary_nodes[b], so J
// is d(volume coordinates) / d(surface coordinates). Rows of static boundary
// nodes move nothing (J's columns for them are zero), and the rows of J for
// boundary nodes are the identity for moving nodes, zero for static ones.
// DG-harmonic: the derivative of its one pass (its guard's laplacian redo and
// the CLI's last resort repair a step; they are not differentiated).
//
// Both products are one pass over the nodes (and, for DG-harmonic, one solve
// with its coarse factor), single-threaded, so the bits do not depend on the
// thread count. Throws MeshError when an array size does not match the plan
// or an input value is not finite (naming its row), Error for a method
// without derivatives.
#include <span>

#include "dgwarp/methods/dg_harmonic.hpp"
#include "dgwarp/methods/dg_idw.hpp"
#include "dgwarp/methods/method.hpp"

namespace dgwarp {

/// Whether the plan's method has these derivatives (dg-idw, dg-harmonic).
bool has_deform_derivative(const Plan& plan);

/// out = J direction: `direction` num_boundary × dim (a translation per
/// boundary index, the plan's boundary order), `out` num_points × dim.
void deform_derivative(const Plan& plan, std::span<const double> direction, std::span<double> out);

/// out = Jᵀ weights: `weights` num_points × dim (e.g. an objective's
/// gradient with respect to the volume coordinates), `out` num_boundary × dim
/// (its gradient with respect to the boundary nodes' coordinates; zero rows
/// for static nodes).
void deform_derivative_transpose(const Plan& plan, std::span<const double> weights, std::span<double> out);

// The same per method.
void deform_derivative(const DgIdwPlan& plan, std::span<const double> direction, std::span<double> out);
void deform_derivative_transpose(const DgIdwPlan& plan, std::span<const double> weights, std::span<double> out);
void deform_derivative(const DgHarmonicPlan& plan, std::span<const double> direction, std::span<double> out);
void deform_derivative_transpose(const DgHarmonicPlan& plan, std::span<const double> weights,
                                 std::span<double> out);

namespace derivative_detail {
/// Checks the sizes (and finiteness of `in`) of a product's arrays.
void check_arrays(const char* method, const char* product, int dim, std::size_t in_rows, std::size_t out_rows,
                  std::span<const double> in, std::span<const double> out);
}  // namespace derivative_detail

}  // namespace dgwarp
