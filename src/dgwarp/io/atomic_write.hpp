#pragma once
// Every output of dgwarp goes through write_file_atomically: the content is
// written to a temporary file in the destination's folder and renamed into
// place only when complete, so a crash or a full disk never leaves a
// half-written file where a good one was.
#include <filesystem>
#include <functional>
#include <ostream>

namespace dgwarp {

/// Calls `write(stream)` on a temporary file beside `path`, flushes and syncs
/// it, then renames it to `path`. On any error (from `write` or the disk) the
/// temporary file is removed, `path` is left as it was, and the error is
/// rethrown (IoError for disk errors).
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);

}  // namespace dgwarp
