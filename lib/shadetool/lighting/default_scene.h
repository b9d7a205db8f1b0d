// default_scene.h: the scene `render` and `bake-lighting` use when no --scene is given, and the
// camera that frames a mesh (--camera frame), so that any mesh, whatever its size and position,
// fills the picture instead of being a dot or off-screen.
//
// Inputs:  mesh           positions #V by 3 (object space; only finite positions count)
//          scene          (frame_camera) a built scene: its world_from_object places the mesh and its
//                         lens.fov_y_degrees (or orthographic_height's absence) is kept
// Outputs: default_scene  Blinn-Phong, a grey material (diffuse 0.8, specular 0.25, shininess 32,
//                         ambient 0), no global ambient, and two lights, Y up (glTF's, Blender's OBJ
//                         export, three.js):
//                           a sky light: sky 0.3 above the horizon of +Y, ground 0.1 below
//                           a key light: directional, white 0.9, from over the viewer's right
//                           shoulder: it travels along -(v + 0.5 u + 0.5 r) normalised, v the
//                           direction from the target to the eye, u up, r the camera's right
//                         and the framing camera below, lens fov_y 40 degrees, near/far fitted.
//          frame_camera   the scene's camera replaced by one looking at the centre c of the mesh's
//                         world bounding box from the direction v = normalize(0.6, 0.45, 1) (front,
//                         right, above), at the distance d = 1.1 r / sin(fov_y / 2) that puts the
//                         bounding sphere (radius r = half the box's diagonal) inside the vertical
//                         field of view with a 10% margin (orthographic: height 2.2 r); up +Y.
// Degenerate input: no finite position -> Error; a box of zero size (one point) takes r = 1.
// Errors:  shadetool::Error with `what` naming the caller's context.
#pragma once

#include <string>

#include <shadetool/core/mesh_view.h>
#include <shadetool/lighting/scene.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

Scene default_scene(const MeshView& mesh, const std::string& what);
void frame_camera(const MeshView& mesh, Scene& scene, const std::string& what);

}  // namespace shadetool
#pragma GCC visibility pop
