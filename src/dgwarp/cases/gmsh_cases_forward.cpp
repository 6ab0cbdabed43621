// dgwarp_cases' meshes made with Gmsh: calls into the Gmsh module, loaded the
// first time one is asked for (gmsh_cases_module.hpp).
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "dgwarp/cases/gmsh_cases_module.hpp"
#include "dgwarp/core/error.hpp"

namespace dgwarp {

namespace {

constexpr const char* module_file = "libdgwarp_gmsh_cases.so";

/// Where to look for the module, in order.
std::vector<std::filesystem::path> module_candidates() {
    std::vector<std::filesystem::path> at;
    if (const char* given = std::getenv("DGWARP_GMSH_CASES"); given && *given) at.emplace_back(given);
    Dl_info self{};
    if (::dladdr(reinterpret_cast<void*>(&module_candidates), &self) != 0 && self.dli_fname) {
        const auto dir = std::filesystem::path(self.dli_fname).parent_path();
        at.push_back(dir / module_file);
#ifdef DGWARP_GMSH_CASES_LIBDIR
        // An installed program, PREFIX/bin/dgwarp: PREFIX/lib/dgwarp/, wherever PREFIX was moved.
        at.push_back(dir.parent_path() / DGWARP_GMSH_CASES_LIBDIR / module_file);
#endif
    }
#ifdef DGWARP_GMSH_CASES_BUILD
    at.emplace_back(DGWARP_GMSH_CASES_BUILD);
#endif
#ifdef DGWARP_GMSH_CASES_INSTALL
    at.emplace_back(DGWARP_GMSH_CASES_INSTALL);
#endif
    return at;
}

const detail::GmshCases& load_module() {
    static std::once_flag once;
    static const detail::GmshCases* table = nullptr;
    static std::string error;
    std::call_once(once, [] {
        std::string tried;
        for (const auto& path : module_candidates()) {
            std::error_code ec;
            if (!std::filesystem::exists(path, ec)) {
                tried += "\n  " + path.string() + ": not there";
                continue;
            }
            void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
            if (!handle) {
                const char* why = ::dlerror();
                tried += "\n  " + path.string() + ": " + (why ? why : "cannot be loaded");
                continue;
            }
            using Entry = const detail::GmshCases* (*)();
            const auto entry = reinterpret_cast<Entry>(::dlsym(handle, "dgwarp_gmsh_cases"));
            const detail::GmshCases* t = entry ? entry() : nullptr;
            if (!t || t->version != detail::gmsh_cases_version) {
                tried += "\n  " + path.string() + ": not this dgwarp's Gmsh module";
                continue;  // the handle stays open: unloading code is never worth the risk
            }
            table = t;
            return;
        }
        error = "meshing a case needs dgwarp's Gmsh module (" + std::string(module_file) +
                "), which was not found; looked at:" + tried;
    });
    if (!table) throw Error(error);
    return *table;
}

}  // namespace

Mesh make_naca0012(const Naca0012Options& o) { return load_module().naca0012(o); }
Mesh make_sphere_box(const SphereBoxOptions& o) { return load_module().sphere_box(o); }
Mesh make_store(const StoreOptions& o) { return load_module().store(o); }
Mesh make_two_element(const TwoElementOptions& o) { return load_module().two_element(o); }
Mesh make_wing_body(const WingBodyOptions& o) { return load_module().wing_body(o); }
Mesh make_random_scene_mesh(const RandomScene& scene) { return load_module().random_scene_mesh(scene); }

}  // namespace dgwarp
