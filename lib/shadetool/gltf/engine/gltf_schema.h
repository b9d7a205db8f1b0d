// gltf_schema.h (engine, not installed): the JSON types of the glTF 2.0 core schema, checked
// before anything is read, so that a file the Khronos validator rejects for a type error is
// refused here (as assimp refuses it) and never passed through into an output.
//
// Checked, for every core object (asset, scenes, nodes, meshes and primitives, accessors and
// sparse blocks, bufferViews, buffers, materials and their texture infos, textures, images,
// samplers, cameras, skins, animations): each known property has its schema type (string,
// number, integer, boolean, object, array of those); an index is an integer >= 0 below the size of
// the array it names (`scene` < scenes, `material` < materials, a texture info's `index` <
// textures, ...); `name` is a string, `extensions` an object whose every value is an object
// (extension.schema.json). Unknown properties and what lies inside an extension's object are not
// checked (the validator does not reject them either).
//
// Bad input: Error `FILE: JSON.PATH: what it is, what the schema wants`
// (`x.gltf: scenes[0].name: a number, the schema wants a string`).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace shadetool::io::gltf {

void require_schema_types(const nlohmann::json& document, const std::string& name);

}  // namespace shadetool::io::gltf
