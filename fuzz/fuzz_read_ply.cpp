// fuzz_read_ply.cpp: libFuzzer target for the PLY reader (read_mesh_from_memory), see fuzz_mesh_reader.h.
#include "fuzz_mesh_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return shadetool_fuzz::fuzz_one(data, size, shadetool::Format::Ply, "fuzz.ply");
}
