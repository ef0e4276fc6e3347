#pragma once
// Files the tools write are complete or absent: written to a new file beside them, flushed to
// disk, renamed, and the folder flushed so that the new name survives a crash. Used by the engine
// (XDMF views), the pipeline (study copies, manifests, records) and the validation tools
// (validation.json, tables, reports).
#include <string>

namespace dem {

// Writes `text` to `file` through a new file beside it (write_temp_beside), then a rename and an
// fsync of the folder; throws std::runtime_error naming the file and the reason if any step fails
// (the old file, if any, is then left as it was, and the new one is removed). Only a regular file
// is replaced: a `file` that is anything else (a device node such as /dev/full, a FIFO, a folder,
// a symbolic link) is refused before anything is written, and left as it was.
void write_file_atomically(const std::string& file, const std::string& text);

// Writes `text` to a new file beside `file`, named <file>.tmp.<pid>.<n> and created exclusively
// (an existing file of that name, e.g. the user's own <file>.tmp, is never opened, truncated or
// followed as a link), flushed to disk; returns its name. The caller renames it over `file`
// (rename_durably) or removes it. Throws std::runtime_error as write_file_atomically does.
std::string write_temp_beside(const std::string& file, const std::string& text);

// "" for a regular file or nothing at all at `path`; otherwise what is there, not following a
// symbolic link ("a character device", "a FIFO (named pipe)", "a symbolic link", ...).
std::string non_regular_kind(const std::string& path);

// fsync of a file that was written and closed (by HDF5, say); throws std::runtime_error naming
// the file and the reason (e.g. "No space left on device").
void sync_file(const std::string& file);

// fsync of the folder holding `file`, after a rename or a removal in it: without it the new name
// may be lost in a crash although the data are on disk. Throws like sync_file.
void sync_folder_of(const std::string& file);

// Copies the bytes of `from` to `to` (created or truncated; a symbolic link at `to` is refused);
// throws std::runtime_error naming the file and the system's reason (std::filesystem::copy_file
// reports a full disk as "Input/output error"). It does not fsync.
void copy_file_contents(const std::string& from, const std::string& to);

// rename(from, to) then sync_folder_of(to); throws std::runtime_error naming both and the reason.
void rename_durably(const std::string& from, const std::string& to);

}  // namespace dem
