#include "dgwarp/io/atomic_write.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <fstream>
#include <random>
#include <string>

#include "dgwarp/core/error.hpp"

namespace dgwarp {

namespace {

std::filesystem::path temporary_path_for(const std::filesystem::path& path) {
    std::random_device rd;
    std::string name = ".";
    name += path.filename().string();
    name += ".tmp.";
    name += std::to_string(::getpid());
    name += '.';
    name += std::to_string(rd() % 1000000);
    std::filesystem::path tmp = path;
    tmp.replace_filename(name);
    return tmp;
}

void sync_file(const std::filesystem::path& path) {
    int fd = ::open(path.c_str(), O_RDONLY);
    if (fd < 0) throw IoError(path.string(), "cannot reopen temporary file to sync it");
    const int rc = ::fsync(fd);
    ::close(fd);
    if (rc != 0) throw IoError(path.string(), "fsync failed (disk full?)");
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write) {
    if (path.empty()) throw IoError("", "empty output file name");
    const std::filesystem::path tmp = temporary_path_for(path);
    try {
        {
            std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
            if (!out) throw IoError(path.string(), "cannot create file for writing (does the folder exist?)");
            write(out);
            out.flush();
            if (!out) throw IoError(path.string(), "write failed (disk full?)");
        }
        sync_file(tmp);
        std::error_code ec;
        std::filesystem::rename(tmp, path, ec);
        if (ec) throw IoError(path.string(), "cannot rename temporary file into place: " + ec.message());
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        throw;
    }
}

}  // namespace dgwarp
