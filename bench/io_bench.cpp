// Reading and writing mesh files (issue #33 item 1): the file's bytes into
// memory, the whole read (bytes and parse), and the write to a file of the
// same format beside the system's temporary folder, each the median of
// --repeats runs, in seconds and MB/s of the file's size, one thread then two.
//
// Usage: dgwarp_bench_io MESH [--repeats N]
//   e.g. dgwarp case squeezed-sphere --size 2 -o s2.su2 (865k nodes, 261 MB)
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "bench_timing.hpp"
#include "dgwarp/core/parallel_for.hpp"
#include "dgwarp/io/file_bytes.hpp"
#include "dgwarp/io/mesh_io.hpp"
#include "dgwarp/io/text_reader.hpp"

using namespace dgwarp;
using bench::median_seconds;

int main(int argc, char** argv) {
    std::string file;
    int repeats = 3;
    if (!bench::mesh_and_repeats(argc, argv, file, repeats)) return 1;
    const std::filesystem::path path = file;
    const double mb = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
    const auto out = std::filesystem::temp_directory_path() /
                     ("dgwarp-bench-io" + path.extension().string());
    std::printf("%s: %.1f MB\n", path.string().c_str(), mb);
    const double bytes = median_seconds(repeats, [&] { (void)FileBytes::read(path); });
    std::printf("the file's bytes into memory: %.3f s (%.0f MB/s)\n", bytes, mb / bytes);
    for (int threads : {1, 2}) {
        set_num_threads(threads);
        Mesh mesh;
        const double read = median_seconds(repeats, [&] { mesh = read_mesh(path); });
        const double write = median_seconds(repeats, [&] { write_mesh(out, mesh); });
        std::printf("%d thread%s: read %.3f s (%.0f MB/s), write %.3f s (%.0f MB/s)\n", threads,
                    threads > 1 ? "s" : "", read, mb / read, write, mb / write);
    }
    std::filesystem::remove(out);
    return 0;
}
