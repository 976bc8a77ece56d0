#pragma once
// Files written so that a failure is reported and what is kept is on the disk:
// every write checked, each file fsynced before its directory is moved into
// place (run_directory.hpp).
#include <cstdint>
#include <filesystem>
#include <string>

namespace shockgas::app {

// A new file at path for writing, returned as an open descriptor (-1 with
// errno set if it cannot be made): whatever was at path before (a temporary
// file of a killed write) is removed first, and the file is created without
// following a link (O_EXCL | O_NOFOLLOW), so that a link put in its place can
// never have another file written through it. Every file shockgas writes is
// made so.
int open_new_file(const std::filesystem::path& path) noexcept;

// Writes text to path (created or truncated), fsyncs and closes it; RunError
// naming the file, the system's reason and the free space on a failure. Passes
// the fault point "write:<file name>" half-way (fault.hpp).
void write_file(const std::filesystem::path& path, const std::string& text);

// A file in a directory that is not staged (a finished run's, a shard's)
// replaced whole: text written to PATH.partial (removed again on a failure)
// and renamed over path, the directory synced. RunError as write_file; its
// fault point is that of path ("write:manifest.json").
void replace_file(const std::filesystem::path& path, const std::string& text);

// fsync of every file and directory under dir, then of dir itself.
void sync_tree(const std::filesystem::path& dir);
// fsync of one directory (its entries: after a rename into it).
void sync_directory(const std::filesystem::path& dir);
// The same at best effort, where the rename is done and a directory that cannot
// be opened or synced leaves only its durability to the system (checkpoints).
void try_sync_directory(const std::filesystem::path& dir) noexcept;

// Bytes free for an unprivileged user on the file system holding path (or its
// nearest existing ancestor); the largest value if unknown.
std::uint64_t free_bytes(const std::filesystem::path& path);

// "1.4 MB", "830 kB", "12 GB": a size for messages (decimal units), to
// `digits` significant digits.
std::string size_text(double bytes, int digits = 3);

// " (the file system holding it has N free)": the free space of path's file
// system, for a message about a write there.
std::string room_note(const std::filesystem::path& path);

// "cannot write PATH: REASON (the file system holding it has N free)".
std::string write_failure(const std::filesystem::path& path, const std::string& reason);

}  // namespace shockgas::app
