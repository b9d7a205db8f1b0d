// gltf_lights.h: a lighting Scene (lighting/scene.h) from a glTF file's own KHR_lights_punctual
// lights, first camera and the placement of one primitive, for `bake-lighting` without --scene.
//
// Inputs:  document   a GltfDocument read from a file (its JSON: nodes, scenes, cameras,
//                     materials, extensions.KHR_lights_punctual.lights)
//          primitive  the primitive to light
// Output:  Scene, every position and direction in world space:
//   world_from_object  the world matrix of the first node (scene order, depth first) whose mesh is
//                      the primitive's (node matrix, or T * R * S; glTF 2.0, 3.5.2); identity if no
//                      node shows it
//   camera_from_world  inverse world matrix of the first node (same order) with a camera; none:
//                      OpenGL's default eye at the origin. glTF cameras look down their -Z, as
//                      OpenGL's eye does, so no axis change is needed.
//   lights             one per node carrying a KHR_lights_punctual light, at the node's world
//                      position, pointing down its world -Z. Unit mapping (documented in
//                      man/shadetool-bake-lighting.1): diffuse = specular = color * intensity
//                      taken as a number (directional lux and point/spot candela -> radiance
//                      scale 1 per unit); point and spot attenuate 1/d^2 (kc = kl = 0, kq = 1, the
//                      physical inverse square of KHR_lights_punctual); spot cutoff =
//                      outerConeAngle in degrees, exponent 0 (the smooth inner-to-outer falloff
//                      has no fixed-function form); `range` is not applied.
//   material           kd = baseColorFactor rgb (default 1), ka = 0 (glTF has no ambient term),
//                      ks = 0, emission = emissiveFactor; global_ambient = 0.
//   notes              what the mapping approximated (one line each)
// Error (`FILE: JSON.PATH: what`) for a light of unknown type, a light index out of range, a value
// of the wrong JSON type (a string intensity), a negative colour or intensity, and whatever
// lighting/validate_scene.h refuses in the Scene built (an intensity whose product with the colour
// overflows, a negative base colour), named by its glTF path
// (extensions.KHR_lights_punctual.lights[2].intensity, materials[0].emissiveFactor, nodes[3]).
#pragma once

#include <string>
#include <vector>

#include <shadetool/gltf/gltf_document.h>
#include <shadetool/lighting/scene.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

Scene gltf_scene(const GltfDocument& document, const GltfPrimitive& primitive, std::vector<std::string>& notes);

}  // namespace shadetool
#pragma GCC visibility pop
