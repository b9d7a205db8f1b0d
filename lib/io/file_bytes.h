// file_bytes.h: a whole file read into memory in one call (readers parse from memory).
//
// Inputs:  path  file to read
// Outputs: the file's bytes
// Errors (shadetool::Error, `PATH: what`): missing file, a directory, unreadable, empty file.
#pragma once

#include <string>

namespace shadetool::io {

std::string read_file_bytes(const std::string& path);

}  // namespace shadetool::io
