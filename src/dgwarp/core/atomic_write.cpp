#include "dgwarp/core/atomic_write.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <random>
#include <string>

#include "dgwarp/core/error.hpp"

namespace dgwarp {

namespace {

/// A hidden name in the folder of `path`: ".NAME.TAG.PID.RANDOM", with NAME
/// cut short (at a UTF-8 character's start) so that it fits in a file name
/// of 255 bytes (NAME_MAX) whenever `path`'s own name does.
std::filesystem::path hidden_sibling(const std::filesystem::path& path, const std::string& name, const char* tag) {
    std::random_device rd;
    const std::string suffix =
        std::string(".") + tag + "." + std::to_string(::getpid()) + "." + std::to_string(rd() % 1000000);
    constexpr std::size_t name_max = 255;
    const std::size_t room = suffix.size() < name_max - 1 ? name_max - 1 - suffix.size() : 0;  // 1: the '.'
    std::size_t keep = name.size() < room ? name.size() : room;
    while (keep > 0 && keep < name.size() && (static_cast<unsigned char>(name[keep]) & 0xC0) == 0x80) --keep;
    std::string hidden = ".";
    hidden.append(name, 0, keep);
    hidden += suffix;
    std::filesystem::path p = path;
    p.replace_filename(hidden);
    return p;
}

std::filesystem::path temporary_path_for(const std::filesystem::path& path) {
    return hidden_sibling(path, path.filename().string(), "tmp");
}

/// The folder a file named `path` goes into, for messages and checks.
std::filesystem::path folder_of(const std::filesystem::path& path) {
    return path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
}

/// Creates `file` (which must not exist), empty, readable and writable as
/// the umask allows. Throws IoError naming `target` with errno's reason.
void create_new_file(const std::filesystem::path& file, const std::filesystem::path& target) {
    const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) {
        const int err = errno;
        throw IoError(target.string(),
                      "cannot create a file in folder '" + folder_of(target).string() + "': " + std::strerror(err), err);
    }
    ::close(fd);
}

void sync_file(const std::filesystem::path& path) {
    int fd = ::open(path.c_str(), O_RDONLY);
    if (fd < 0) throw IoError(path.string(), std::string("cannot reopen temporary file to sync it: ") + std::strerror(errno));
    const int rc = ::fsync(fd);
    const int err = errno;
    ::close(fd);
    if (rc != 0) throw IoError(path.string(), std::string("fsync failed: ") + std::strerror(err));
}

// The temporary files being written, for remove_unfinished_temporary_files,
// which a signal handler calls: fixed storage and lock-free atomics only.
// state: 0 free, 1 being filled in, 2 a temporary file that exists.
struct UnfinishedSlot {
    std::atomic<int> state{0};
    char path[4096];
};
UnfinishedSlot unfinished[16];

/// Records `tmp`; returns its slot, or -1 when there is no room (then it is
/// not removed on a signal: only a leftover, never a wrong file).
int register_unfinished(const std::filesystem::path& tmp) {
    const std::string& s = tmp.native();
    if (s.size() >= sizeof(UnfinishedSlot::path)) return -1;
    for (int i = 0; i < static_cast<int>(std::size(unfinished)); ++i) {
        int free_state = 0;
        if (!unfinished[i].state.compare_exchange_strong(free_state, 1)) continue;
        std::memcpy(unfinished[i].path, s.c_str(), s.size() + 1);
        unfinished[i].state.store(2);
        return i;
    }
    return -1;
}

void unregister_unfinished(int slot) {
    if (slot >= 0) unfinished[slot].state.store(0);
}

/// The file a write to `path` replaces: `path` itself, or, when it is a
/// symbolic link, the file it leads to (the link stays a link).
std::filesystem::path write_target(const std::filesystem::path& path) {
    std::filesystem::path p = path;
    std::error_code ec;
    for (int hops = 0; hops < 40 && std::filesystem::is_symlink(p, ec); ++hops) {
        const std::filesystem::path to = std::filesystem::read_symlink(p, ec);
        if (ec) break;
        p = to.is_absolute() ? to : p.parent_path() / to;
    }
    return p;
}

}  // namespace

void remove_unfinished_temporary_files() noexcept {
    for (UnfinishedSlot& slot : unfinished)
        if (slot.state.load() == 2) ::unlink(slot.path);
}

void check_replaceable(const std::filesystem::path& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return;  // nothing to replace (or the folder check will say why)
    if (S_ISDIR(st.st_mode)) throw IoError(path.string(), "is a folder, not a file");
    if (!S_ISREG(st.st_mode))
        throw IoError(path.string(), "is not a regular file (a device, a pipe or a socket): dgwarp writes files only");
    if ((st.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0 || ::access(path.c_str(), W_OK) != 0)
        throw IoError(path.string(), "is read-only: dgwarp does not replace a read-only file (make it writable, or "
                                     "write to another name)");
}

void check_folder_writable(const std::filesystem::path& folder) {
    const std::filesystem::path dir = folder.empty() ? std::filesystem::path(".") : folder;
    struct stat st {};
    if (::stat(dir.c_str(), &st) != 0) {
        const int err = errno;
        throw IoError(dir.string(), std::string("cannot write files into this folder: ") + std::strerror(err), err);
    }
    if (!S_ISDIR(st.st_mode))
        throw IoError(dir.string(), std::string("cannot write files into this folder: ") + std::strerror(ENOTDIR),
                      ENOTDIR);
    const std::filesystem::path probe = hidden_sibling(dir / "x", "dgwarp", "check");
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0) {
        const int err = errno;
        throw IoError(dir.string(), std::string("cannot write files into this folder: ") + std::strerror(err), err);
    }
    ::close(fd);
    ::unlink(probe.c_str());
}

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write) {
    write_file_atomically_at(path, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) throw IoError(path.string(), std::string("cannot open the temporary file ") + tmp.string() +
                                                   ": " + std::strerror(errno));
        write(out);
        out.flush();
        if (!out) throw IoError(path.string(), "write failed (disk full?)");
    });
}

void write_file_atomically_at(const std::filesystem::path& output,
                              const std::function<void(const std::filesystem::path& tmp)>& write) {
    if (output.empty()) throw IoError("", "empty output file name");
    check_replaceable(output);
    // Through a symbolic link: the file it leads to is replaced, the link stays.
    const std::filesystem::path path = write_target(output);
    const std::filesystem::path tmp = temporary_path_for(path);
    create_new_file(tmp, output);
    const int slot = register_unfinished(tmp);
    try {
        write(tmp);
        sync_file(tmp);
        struct stat old {};
        if (::stat(path.c_str(), &old) == 0) ::chmod(tmp.c_str(), old.st_mode & 07777);  // keep its permissions
        std::error_code ec;
        std::filesystem::rename(tmp, path, ec);
        if (ec) throw IoError(output.string(), "cannot rename temporary file into place: " + ec.message());
        unregister_unfinished(slot);
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        unregister_unfinished(slot);
        throw;
    }
}

}  // namespace dgwarp
