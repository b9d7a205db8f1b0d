// split_corner_normals.h: per-corner normals carried as per-vertex normals, for formats that store
// normals only per vertex (PLY, OFF).
//
// Inputs:  mesh  with corner_normal_index (C) into corner_normals (N*3)
// Outputs: a mesh whose vertex_normals (V'*3) hold, for each distinct (vertex, normal index) pair
//          used by a corner, one vertex; `added` = V' - V.
// The first pair met for vertex v keeps index v (so order and unreferenced vertices are kept);
// further pairs become new vertices appended after the originals, copying position and colour.
// Unreferenced vertices keep their vertex normal if the mesh had a valid one, else get
// kFallbackNormal (core/fallback_normal.h): no written normal is ever zero.
// Corner normals and their index are removed from the result; faces keep their order and size.
// Flat arrays: corners bucketed by vertex (count, then fill), then one pass over the buckets with
// an O(1) lookup per corner (the last vertex that used each normal index): O(V + C + N).
#pragma once

#include <cstddef>

#include <shadetool/core/mesh.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool::io {

Mesh split_corner_normals(const Mesh& mesh, std::size_t& added);

// What a writer of a per-vertex-normal format writes: `input` itself when it has no corner
// normals (no copy), else split_corner_normals(input) held in `storage`. `added` as above.
const Mesh& with_corner_normals_split(const Mesh& input, Mesh& storage, std::size_t& added);

// True when some vertex's corners carry different corner normals (by value: a crease), so that no
// one normal per vertex stands for them; false without corner normals.
bool corner_normals_disagree(const Mesh& mesh);

// What a step that shades or casts per vertex uses (render, bake-lighting and occlusion per
// vertex): `input` itself unless corner_normals_disagree(input), else split_corner_normals(input)
// in `storage`, so that every corner is shaded with its own normal, exactly as the same normals
// read back from a PLY file (whose writer splits them the same way) are. `added` as above.
const Mesh& with_creases_split(const Mesh& input, Mesh& storage, std::size_t& added);

}  // namespace shadetool::io
#pragma GCC visibility pop
