// off_format.h: Geomview OFF reader and writer (OFF, COFF, NOFF, CNOFF).
#pragma once

#include <string>
#include <string_view>

#include "core/mesh.h"
#include "io/mesh_io.h"

namespace shadetool::io {

Mesh read_off(std::string_view bytes, const std::string& name, ReadInfo& info);
void write_off(const Mesh& mesh, std::string& out, WriteInfo& info);

}  // namespace shadetool::io
