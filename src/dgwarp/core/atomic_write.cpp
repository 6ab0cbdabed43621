#include "dgwarp/core/atomic_write.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <cerrno>
#include <cstring>
#include <iterator>
#include <random>
#include <streambuf>
#include <string>
#include <vector>

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

std::atomic<bool> sync_before_rename{false};

/// The output stream's buffer: writes go to the file descriptor (large ones
/// straight from the caller's memory). When the file is to be synced, every
/// `kick` bytes the disk is asked to start writing them (sync_file_range,
/// SYNC_FILE_RANGE_WRITE: no wait), so that the fsync at the end waits for
/// the last few megabytes rather than the whole file (0.2-0.3 s for 261 MB
/// measured in a virtual machine, then spent while the next rows are formatted).
class FileOut : public std::streambuf {
public:
    FileOut(int fd, bool kick) : fd_(fd), kick_(kick), buffer_(std::size_t{1} << 16) {
        setp(buffer_.data(), buffer_.data() + buffer_.size());
    }
    /// errno of the first failed write, 0 when none failed.
    int error() const { return error_; }

protected:
    int_type overflow(int_type c) override {
        if (!drain()) return traits_type::eof();
        if (!traits_type::eq_int_type(c, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(c);
            pbump(1);
        }
        return traits_type::not_eof(c);
    }
    std::streamsize xsputn(const char* s, std::streamsize n) override {
        if (n < static_cast<std::streamsize>(buffer_.size()) / 2) return std::streambuf::xsputn(s, n);
        if (!drain() || !write_all(s, static_cast<std::size_t>(n))) return 0;
        return n;
    }
    int sync() override { return drain() ? 0 : -1; }

private:
    static constexpr std::uint64_t kick = std::uint64_t{32} << 20;
    int fd_;
    bool kick_;
    std::vector<char> buffer_;
    std::uint64_t written_ = 0, kicked_ = 0;
    int error_ = 0;

    bool drain() {
        const auto n = static_cast<std::size_t>(pptr() - pbase());
        setp(buffer_.data(), buffer_.data() + buffer_.size());
        return n == 0 || write_all(buffer_.data(), n);
    }
    bool write_all(const char* p, std::size_t n) {
        if (error_) return false;
        while (n > 0) {
            const ssize_t k = ::write(fd_, p, n);
            if (k < 0) {
                if (errno == EINTR) continue;
                error_ = errno;
                return false;
            }
            p += k;
            n -= static_cast<std::size_t>(k);
            written_ += static_cast<std::uint64_t>(k);
        }
        if (kick_ && written_ - kicked_ >= kick) {
#ifdef SYNC_FILE_RANGE_WRITE
            ::sync_file_range(fd_, static_cast<off_t>(kicked_), static_cast<off_t>(written_ - kicked_),
                              SYNC_FILE_RANGE_WRITE);
#endif
            kicked_ = written_;
        }
        return true;
    }
};

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

void set_sync_writes(bool sync) { sync_before_rename.store(sync); }
bool sync_writes() { return sync_before_rename.load(); }

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
        // Opened without O_TRUNC (the file is new and empty): ext4 flushes a
        // truncated-and-rewritten file at its close (auto_da_alloc), which
        // the fsync after it would only wait for again.
        const int fd = ::open(tmp.c_str(), O_WRONLY | O_CLOEXEC);
        if (fd < 0) {
            const int err = errno;
            throw IoError(path.string(),
                          std::string("cannot open the temporary file ") + tmp.string() + ": " + std::strerror(err), err);
        }
        struct Closer {
            int fd;
            ~Closer() {
                if (fd >= 0) ::close(fd);
            }
        } closer{fd};
        FileOut buffer(fd, sync_writes());
        std::ostream out(&buffer);
        write(out);
        out.flush();
        if (buffer.error() != 0)
            throw IoError(path.string(), std::string("write failed: ") + std::strerror(buffer.error()), buffer.error());
        if (!out) throw IoError(path.string(), "write failed (disk full?)");
        // close's own error (a network file system may report a failed write only there).
        closer.fd = -1;
        if (::close(fd) != 0 && errno != EINTR) {  // on EINTR Linux has closed it
            const int err = errno;
            throw IoError(path.string(), std::string("write failed: ") + std::strerror(err), err);
        }
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
        if (sync_writes()) sync_file(tmp);
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
