// atomic_write.h: a file replaced in one step, or not at all.
//
// Inputs:  path   target file ("-" writes to stdout)
//          bytes  the complete contents
// The bytes go to a temporary file created next to `path` (same directory, so rename(2) is
// atomic), which is renamed onto `path` (and fsync'ed first when the environment has
// SHADETOOL_FSYNC=1, for durability across a power loss). On any error the temporary file is removed
// and an existing file at `path` is left untouched. The new file gets the usual 0666 & ~umask mode.
// Errors: shadetool::Error `PATH: cannot write: REASON`.
//
// write_files_atomically: several files that belong together (a mesh and its report) committed
// together: every temporary file is written first; if any of them fails, all are removed and no
// file is replaced. Only then are they renamed into place, in order (a rename within a directory
// does not fail for want of space; should one fail anyway, the later temporaries are removed).
// Entries "-" are written to stdout last, after every rename.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::io {

void write_file_atomically(const std::string& path, std::string_view bytes);

struct FileToWrite {
  std::string path;  // "-": stdout
  std::string_view bytes;
};
void write_files_atomically(const std::vector<FileToWrite>& files);

}  // namespace shadetool::io
#pragma GCC visibility pop
