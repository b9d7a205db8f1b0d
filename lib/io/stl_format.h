// stl_format.h: STL reader and writer (ascii and binary).
#pragma once

#include <string>
#include <string_view>

#include "core/mesh.h"
#include "io/mesh_io.h"

namespace shadetool::io {

Mesh read_stl(std::string_view bytes, const std::string& name, ReadInfo& info);
void write_stl(const Mesh& mesh, bool binary, std::string& out, WriteInfo& info);

}  // namespace shadetool::io
