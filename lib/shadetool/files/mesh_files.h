// mesh_files.h: the one door for mesh files: read any format of files/format_table.h (OBJ, PLY,
// OFF, STL through io/, glTF through gltf/) into a Mesh, write a Mesh into any of them.
// The only way data enters or leaves.
//
// Contract used by every subcommand and by library users:
//   read_mesh            file -> Mesh; format from the extension unless given
//   read_mesh_from_memory bytes -> Mesh (stdin, fuzzers); `name` is used in messages
//   write_mesh           Mesh -> file, atomically: written to a temporary file in the target
//                        directory and renamed into place; on any error no output file is left and
//                        an existing file at `path` is untouched. "-" writes to stdout.
//                        The bytes stream through a 1 MiB buffer (io/byte_sink.h): writing holds
//                        that buffer, never the whole output (glTF excepted: its JSON and binary
//                        chunk are built in memory, gltf/gltf_write.cpp).
//   write_mesh_to_sink   Mesh -> any io::ByteSink (a file descriptor, a string); the sink's owner
//                        flushes it. write_mesh_to_memory: to a string.
// Errors throw shadetool::Error with `FILE:LINE: what is wrong` (see core/error.h).
//
// Reading: a colour row read with a NaN or infinite value (float colours: OBJ `nan`, PLY float
// properties) is read as white, counted in ReadInfo::nonfinite_color_values, with one note.
// What no writer writes (Error `NAME: what`, nothing written): a NaN or infinite coordinate,
// texture coordinate or float colour (a colour a command computed); with WriteOptions::refuse_unusable_normals (every
// subcommand), a zero, NaN or infinite normal of a kind the format holds.
// What every writer writes as a unit vector: a stored normal (vertex, corner or face) that is
// finite and non-zero but off unit length by more than 1e-3 is written divided by its length (the
// same direction; a note counts them and gives the lengths): glTF requires unit normals, and a
// fixed-function renderer or a reader that does not normalise would shade with the length.
// A finite value beyond the range of the output's number type is written in a wider type where the
// format has one (binary PLY: double properties, with a note) and refused where it has none
// (binary STL holds float only: use --ascii or another format).
#pragma once

#include <string>
#include <string_view>

#include <shadetool/core/mesh.h>
#include <shadetool/io/byte_sink.h>
#include <shadetool/io/mesh_io.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

// A format name or extension of format_table.h (any case) -> Format; throws Error naming `what`
// and listing the names otherwise.
Format parse_format_name(const std::string& name, const std::string& what);
// From the extension of `path`; throws Error `path: unknown mesh format 'EXT' ...` otherwise.
Format format_from_extension(const std::string& path);
const char* format_extension(Format format);  // "obj", ... (no dot)
// The format a file at `path` is written in: `given` unless Auto, else from the extension
// ("-", stdout, has none: Error `stdout: writing stdout needs a format (--format)`).
Format output_format(const std::string& path, Format given);

Mesh read_mesh(const std::string& path, Format format = Format::Auto, ReadInfo* info = nullptr);
Mesh read_mesh_from_memory(std::string_view bytes, Format format, const std::string& name,
                           ReadInfo* info = nullptr);

void write_mesh(const Mesh& mesh, const std::string& path, const WriteOptions& options,
                WriteInfo* info = nullptr);
// Writes to a string (tests, pipes). Same bytes write_mesh would put in a file.
std::string write_mesh_to_memory(const Mesh& mesh, const WriteOptions& options, WriteInfo* info = nullptr);
// Appends the bytes write_mesh would put in a file to `sink` (options.format must be set: not Auto).
void write_mesh_to_sink(const Mesh& mesh, const WriteOptions& options, io::ByteSink& sink, WriteInfo* info = nullptr);
// The same in two steps, for callers that create the output between them (write_mesh,
// cli/driver.cpp): what no writer writes is refused now (Error, before any file exists); the
// function returned appends the bytes. It refers to `mesh` and `*info`: keep them alive until it
// has run.
io::ProduceBytes prepare_mesh_write(const Mesh& mesh, const WriteOptions& options, WriteInfo* info = nullptr);

}  // namespace shadetool
#pragma GCC visibility pop
