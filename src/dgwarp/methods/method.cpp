#include "dgwarp/methods/method.hpp"

namespace dgwarp {

std::string_view method_name(Method m) {
    switch (m) {
        case Method::dg_idw: return "dg-idw";
        case Method::idw: return "idw";
        case Method::rbf: return "rbf";
    }
    return "?";
}

std::optional<Method> method_from_name(std::string_view name) {
    for (Method m : all_methods)
        if (method_name(m) == name) return m;
    return std::nullopt;
}

Plan prepare(Method method, int dim, std::span<const double> points, const BoundarySet& boundary,
             const MethodOptions& options) {
    switch (method) {
        case Method::dg_idw: return prepare_dg_idw(dim, points, boundary, options.dg_idw);
        case Method::idw: return prepare_idw(dim, points, boundary, options.idw);
        case Method::rbf: return prepare_rbf(dim, points, boundary, options.rbf);
    }
    return {};
}

namespace {
template <class... F>
struct overloaded : F... {
    using F::operator()...;
};
template <class... F>
overloaded(F...) -> overloaded<F...>;
}  // namespace

StepReport deform(const Plan& plan, std::span<const double> points, const BoundaryMotion& motion,
                  std::span<double> out, const MethodOptions& options) {
    return std::visit(overloaded{[&](const DgIdwPlan& p) {
                                     StepReport r;
                                     r.conflicting_shared_vertices =
                                         deform_dg_idw(p, points, motion, out, options.dg_idw)
                                             .conflicting_shared_vertices;
                                     return r;
                                 },
                                 [&](const IdwPlan& p) {
                                     deform_idw(p, points, motion, out, options.idw);
                                     return StepReport{};
                                 },
                                 [&](const RbfPlan& p) {
                                     const RbfStepReport rbf = deform_rbf(p, points, motion, out);
                                     StepReport r;
                                     r.rbf_centres = rbf.centres;
                                     r.rbf_boundary_error = rbf.boundary_error;
                                     return r;
                                 }},
                      plan);
}

Method plan_method(const Plan& plan) {
    return std::visit(overloaded{[](const DgIdwPlan&) { return Method::dg_idw; },
                                 [](const IdwPlan&) { return Method::idw; },
                                 [](const RbfPlan&) { return Method::rbf; }},
                      plan);
}

std::size_t plan_memory_bytes(const Plan& plan) {
    return std::visit([](const auto& p) { return plan_bytes(p); }, plan);
}

}  // namespace dgwarp
