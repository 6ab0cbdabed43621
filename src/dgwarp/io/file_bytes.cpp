#include "dgwarp/io/file_bytes.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <utility>

#include "dgwarp/core/error.hpp"
#include "dgwarp/io/text_reader.hpp"

namespace dgwarp {

namespace {
// Smaller files are read: a mapping costs a few system calls, and its pages
// are no cheaper than a small string's.
constexpr off_t smallest_mapped = off_t{1} << 20;
}  // namespace

FileBytes FileBytes::read(const std::filesystem::path& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    struct stat st {};
    if (fd >= 0 && ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size >= smallest_mapped) {
        const auto size = static_cast<std::size_t>(st.st_size);
        // MAP_POPULATE: the page table is filled in one call (the file's pages
        // are read first when they are not cached), not one fault per page.
        void* p = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
        ::close(fd);
        if (p != MAP_FAILED) {
            FileBytes bytes;
            bytes.mapped_ = p;
            bytes.mapped_size_ = size;
            return bytes;
        }
    } else if (fd >= 0) {
        ::close(fd);
    }
    // Everything else, errors included, as read_file_text has it.
    return FileBytes(read_file_text(path));
}

FileBytes::FileBytes(FileBytes&& other) noexcept { *this = std::move(other); }

FileBytes& FileBytes::operator=(FileBytes&& other) noexcept {
    if (this == &other) return *this;
    release();
    text_ = std::move(other.text_);
    mapped_ = std::exchange(other.mapped_, nullptr);
    mapped_size_ = std::exchange(other.mapped_size_, 0);
    released_ = std::exchange(other.released_, 0);
    return *this;
}

FileBytes::~FileBytes() { release(); }

void FileBytes::release_before(std::size_t end) noexcept {
    if (!mapped_) return;
    static const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    const std::size_t upto = std::min(end, mapped_size_) / page * page;
    if (upto <= released_) return;
    // Advice only: a failure leaves the pages mapped, which is no error.
    ::madvise(static_cast<char*>(mapped_) + released_, upto - released_, MADV_DONTNEED);
    released_ = upto;
}

void FileBytes::release() noexcept {
    if (mapped_) ::munmap(mapped_, mapped_size_);
    mapped_ = nullptr;
    mapped_size_ = 0;
    released_ = 0;
}

}  // namespace dgwarp
