#include "dgwarp/core/output_checks.hpp"

#include <string>
#include <system_error>

#include "dgwarp/core/atomic_write.hpp"
#include "dgwarp/core/error.hpp"

namespace dgwarp {

void check_output(const std::filesystem::path& output, const std::vector<std::filesystem::path>& inputs) {
    std::error_code ec;
    if (std::filesystem::exists(output, ec)) {
        for (const auto& in : inputs)
            if (std::filesystem::equivalent(output, in, ec))
                throw UsageError(output.string() + " is " +
                                 (output == in ? std::string("an input of this command")
                                               : "the same file as the input " + in.string()) +
                                 ": it would be overwritten; write the output to another name");
        check_replaceable(output);
    }
}

void check_output_file(const std::filesystem::path& output, const std::vector<std::filesystem::path>& inputs) {
    check_output(output, inputs);
    check_folder_writable(output.parent_path());
}

void check_nearest_folder_writable(const std::filesystem::path& folder) {
    std::filesystem::path p = folder;
    std::error_code ec;
    while (!p.empty() && !std::filesystem::exists(p, ec) && p.has_parent_path() && p.parent_path() != p)
        p = p.parent_path();
    if (!p.empty() && !std::filesystem::exists(p, ec)) p.clear();
    check_folder_writable(p);
}

void make_output_folder(const std::filesystem::path& folder) {
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    if (ec) throw IoError(folder.string(), "cannot create this folder: " + ec.message());
    check_folder_writable(folder);
}

}  // namespace dgwarp
