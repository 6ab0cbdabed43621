#pragma once
// Every output of dgwarp goes through write_file_atomically: the content is
// written to a temporary file in the destination's folder and renamed into
// place only when complete, so a crash or a full disk never leaves a
// half-written file where a good one was.
#include <filesystem>
#include <functional>
#include <ostream>

namespace dgwarp {

/// Calls `write(stream)` on a temporary file beside `path`, flushes and
/// closes it (synced to the disk first when sync_writes()), then renames it
/// to `path`. A file already at `path` is replaced and
/// its permissions are kept; one that check_replaceable refuses (a folder, a
/// device or other non-regular file, a read-only file) is not touched. On any
/// error (from `write` or the disk) the temporary file is removed, `path` is
/// left as it was, and the error is rethrown (IoError for disk errors, with
/// the operating system's reason: "Permission denied", "No such file or
/// directory", ...).
/// When `path` is a symbolic link, the file it leads to is replaced and the
/// link stays (the temporary file is written beside that file).
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);

/// The same for a writer that needs a file name rather than a stream (a
/// library that opens the file itself, such as libcgns): `write(tmp)` fills
/// the temporary file `tmp` (which exists, empty, and which it may replace),
/// then it is renamed to `path` (synced first when sync_writes()), with the same guarantees.
void write_file_atomically_at(const std::filesystem::path& path,
                              const std::function<void(const std::filesystem::path& tmp)>& write);

/// Whether the writes above wait for the disk (fsync) before the rename.
/// Off by default: the rename alone means that a write that fails or is
/// interrupted (an error, a full disk, the process killed) never leaves a
/// partial file where a good one was, and the new file is whole for every
/// program that reads it. What the fsync adds is the same after a power cut
/// or a crash of the operating system in the seconds after the write (a
/// file renamed before its data reached the disk may then be empty), at the
/// price of waiting for the disk: 0.4-0.5 s for a 261 MB mesh on a disk of
/// 340 MB/s, per file (`dgwarp deform --sync`). Process-wide, as the thread count.
void set_sync_writes(bool sync);
bool sync_writes();

/// Removes the temporary files of the writes under way (unlink only): for a
/// program's SIGINT/SIGTERM handler, so that an interrupted write leaves
/// nothing behind (the old file is intact anyway). Async-signal-safe; the
/// library installs no handler itself.
void remove_unfinished_temporary_files() noexcept;

/// Throws IoError when `path` exists and write_file_atomically would not
/// replace it: a folder, not a regular file (a device, a pipe), or read-only
/// (no write permission for anyone, or none for this user). A read-only file
/// is refused rather than replaced: its mode says someone meant to keep it.
void check_replaceable(const std::filesystem::path& path);

/// Throws IoError, with the operating system's reason, when files cannot be
/// created in `folder` ("" is the current folder): it is missing, not a
/// folder, not writable, or on a read-only file system. Checked by creating
/// and removing an empty file there. With check_replaceable, this lets a
/// program check its outputs before long work rather than fail at its end.
void check_folder_writable(const std::filesystem::path& folder);

}  // namespace dgwarp
