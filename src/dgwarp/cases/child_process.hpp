#pragma once
// Runs work in a child process with a time limit: a Gmsh run that takes too
// long (a large 3D case) can be killed, which a thread cannot be. Used where
// meshes are generated on demand (dgwarp bench, the benchmarks).
#include <functional>
#include <string>

namespace dgwarp {

/// Runs `work` in a child process (fork) and waits for it, killing the child
/// after `timeout_seconds` (at least 1). `work` runs in the child only, so it
/// hands its results back through files. Throws Error naming `what`:
/// "<what> took more than N s" when the child was killed,
/// "<what> failed: <its message>" when `work` threw, and
/// "<what> failed: ..." when the child ended otherwise (exit status, signal);
/// Error when fork fails. Call it before the process starts threads: fork
/// copies only the calling thread, and OpenMP's pool in the child would wait
/// for threads it does not have.
void run_in_child_process(const std::function<void()>& work, int timeout_seconds, const std::string& what);

}  // namespace dgwarp
