// off_format.cpp
#include "io/off_format.h"

#include "core/error.h"

namespace shadetool::io {

Mesh read_off(std::string_view, const std::string& name, ReadInfo&) { fail(name, 0, "OFF: not supported yet"); }
void write_off(const Mesh&, std::string&, WriteInfo&) { fail("<output>", 0, "OFF: not supported yet"); }

}  // namespace shadetool::io
