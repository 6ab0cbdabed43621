#pragma once
// A file's bytes for a reader, without copying them where the system allows
// (issue #33): a large regular file is mapped read-only, so that its bytes
// are the page cache's own pages (reading 261 MB into a fresh string took
// 1.3 s in a virtual machine whose page faults are dear, mapping it 0.13 s);
// a small file, and anything mmap refuses, is read into a string.
//
// A mapped file must not shrink while it is read: its bytes past the new end
// would no longer exist, and touching them stops the process (SIGBUS).
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>

namespace dgwarp {

class FileBytes {
public:
    /// The bytes of the file at `path`; throws IoError as read_file_text
    /// (text_reader.hpp) does: a folder, a device, a pipe, a missing or
    /// unreadable file.
    static FileBytes read(const std::filesystem::path& path);
    /// Bytes held in memory (tests, text made by a program).
    explicit FileBytes(std::string text) : text_(std::move(text)) {}

    FileBytes(FileBytes&& other) noexcept;
    FileBytes& operator=(FileBytes&& other) noexcept;
    FileBytes(const FileBytes&) = delete;
    FileBytes& operator=(const FileBytes&) = delete;
    ~FileBytes();

    std::string_view view() const {
        return mapped_ ? std::string_view(static_cast<const char*>(mapped_), mapped_size_) : std::string_view(text_);
    }
    /// Whether the bytes are a mapping of the file (false: a string).
    bool mapped() const { return mapped_ != nullptr; }
    /// Bytes [0, end) are read: a mapping's whole pages there leave the
    /// process's memory (madvise MADV_DONTNEED; the file's pages stay in the
    /// page cache, and reading them again maps them again, so view() is
    /// unchanged). A reader calls it as it goes, so that a large file and
    /// what it becomes are not both in memory. Nothing for a string.
    void release_before(std::size_t end) noexcept;

private:
    FileBytes() = default;
    std::string text_;
    void* mapped_ = nullptr;  // the mapping's start, or nullptr
    std::size_t mapped_size_ = 0;
    std::size_t released_ = 0;  // bytes [0, released_) given back (whole pages)
    void release() noexcept;
};

}  // namespace dgwarp
