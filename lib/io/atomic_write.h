// atomic_write.h: a file replaced in one step, or not at all.
//
// Inputs:  path   target file ("-" writes to stdout)
//          bytes  the complete contents
// The bytes go to a temporary file created next to `path` (same directory, so rename(2) is
// atomic), which is renamed onto `path` (and fsync'ed first when the environment has
// SHADETOOL_FSYNC=1, for durability across a power loss). On any error the temporary file is removed
// and an existing file at `path` is left untouched. The new file gets the usual 0666 & ~umask mode.
// Errors: shadetool::Error `PATH: cannot write: REASON`.
#pragma once

#include <string>
#include <string_view>

namespace shadetool::io {

void write_file_atomically(const std::string& path, std::string_view bytes);

}  // namespace shadetool::io
