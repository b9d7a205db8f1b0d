// mesh_io.h: what every format's reader and writer in io/ (and gltf/) take and report: the Format
// enumerator, ReadInfo, WriteOptions and WriteInfo. Reading and writing files through the format
// table is files/mesh_files.h.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <shadetool/core/progress.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

// One enumerator per entry of files/format_table.h (Auto: from the file name's extension).
enum class Format { Auto, Obj, Ply, Off, Stl, Gltf };

struct ReadInfo {
  Format format = Format::Auto;
  std::size_t merged_vertices = 0;  // STL: identical positions merged into shared vertices
  std::size_t nonfinite_color_values = 0;  // NaN/Inf colour values read (their rows read as white:
                                           // files/mesh_files.h), for `info` to count
  std::vector<std::string> notes;   // things the user should know (one line each)
  // In: where reading reports its stage "reading" in bytes of the file (core/progress.h); a
  // reader calls progress.at(bytes consumed) every so often, read_mesh_from_memory begins the
  // stage and ends it at the file's size. Default: nobody listens.
  ProgressCursor progress;
};

struct WriteOptions {
  Format format = Format::Auto;  // Auto: from the extension of the path
  bool binary = true;            // PLY and STL: binary (default) or ascii
  std::string name;              // for messages ("" : the path given to write_mesh, or "<output>")
  // Refuse a zero, NaN or infinite normal of a kind the format holds (every subcommand sets it;
  // off for library users and test fixtures that must write such files on purpose). STL facet
  // normals are never refused: a bad one is written as its triangle's own.
  bool refuse_unusable_normals = false;
  // glTF: the mesh's material gets KHR_materials_unlit (baked colours: gltf/gltf_baked.h).
  bool gltf_unlit = false;
};

struct WriteInfo {
  std::size_t split_vertices = 0;  // vertices added to carry per-corner normals (PLY, OFF) or
                                   // face colours (OBJ: each face's corners get its colour)
  std::vector<std::string> notes;  // what the format could not carry (one line each)
};

}  // namespace shadetool
#pragma GCC visibility pop
