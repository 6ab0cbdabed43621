#include "dgwarp/methods/method.hpp"

namespace dgwarp {

std::string_view method_name(Method m) {
    switch (m) {
        case Method::dg_idw: return "dg-idw";
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
                              deform_dg_idw(p, points, motion, out, options.dg_idw).conflicting_shared_vertices;
                          return r;
                      }},
                      plan);
}

Method plan_method(const Plan& plan) {
    return std::visit(overloaded{[](const DgIdwPlan&) { return Method::dg_idw; }}, plan);
}

std::size_t plan_memory_bytes(const Plan& plan) {
    return std::visit(overloaded{[](const DgIdwPlan& p) { return plan_bytes(p); }}, plan);
}

}  // namespace dgwarp
