#include "foam_output.hpp"

#include <CLI/CLI.hpp>

#include "dgwarp/io/openfoam/openfoam_frames.hpp"

namespace dgwarp::cli {

std::vector<std::string> foam_time_names(const MotionSpec& spec, std::size_t frames, const std::string& given) {
    if (!given.empty()) {
        if (!is_openfoam_time_name(given))
            throw CLI::ValidationError("--foam-time", "'" + given +
                                                          "' is not a time folder's name: give a number (0, 0.001, "
                                                          "1e-05) or constant");
        if (frames > 1)
            throw CLI::ValidationError("--foam-time",
                                       "names the time folder of a single frame; this motion has " +
                                           std::to_string(frames) +
                                           " frames, each written to a time folder of its own (its time, or its "
                                           "number when the frames have no times)");
        return {given};
    }
    return openfoam_frame_time_names(spec);
}

}  // namespace dgwarp::cli
