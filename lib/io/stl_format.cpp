// stl_format.cpp
#include "io/stl_format.h"

#include "core/error.h"

namespace shadetool::io {

Mesh read_stl(std::string_view, const std::string& name, ReadInfo&) { fail(name, 0, "STL: not supported yet"); }
void write_stl(const Mesh&, bool, std::string&, WriteInfo&) { fail("<output>", 0, "STL: not supported yet"); }

}  // namespace shadetool::io
