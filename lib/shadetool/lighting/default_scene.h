// default_scene.h: the scene `render` and `bake-lighting` use when no --scene is given, and the
// camera that frames a mesh (bake-lighting's eye without --scene, and --camera frame), so that any
// mesh, whatever its size and position, is seen and lit instead of being a dot or off-screen.
//
// Inputs:  mesh           positions #V by 3 (object space; only finite positions count)
//          scene          (frame_camera) a built scene: its world_from_object places the mesh and its
//                         lens (fov_y, or orthographic) is kept
// Outputs: default_scene  Phong, a grey material (diffuse 0.8, specular 0.25, shininess 32,
//                         ambient 0), no global ambient, no camera (render frames the mesh itself:
//                         render/camera.h), and two lights, Y up (glTF's, Blender's OBJ export,
//                         three.js), for a viewer on +z looking down -z (render's framing camera):
//                           a sky light: radiance 0.1 above the horizon of +Y, 0.03 below, no
//                           specular (a surface facing up gets kd * 0.1 * pi = 0.25 from it);
//                           a key light: directional, white 0.75, from over the viewer's right
//                           shoulder: it travels along normalize(-0.5, -0.5, -1).
//          frame_camera   the scene's camera replaced by render's framing one: looking down -z at the
//                         centre c of the mesh's world bounding box from c + (0, 0, d), up +Y, with
//                         d = 1.1 r / sin(fov_y / 2) so that the bounding sphere (radius r = half the
//                         box's diagonal) fits the vertical field of view with a 10% margin
//                         (orthographic: d = 2 r); near/far fitted.
// Degenerate input: no finite position -> Error; a box of zero size (one point) takes r = 1.
// Errors:  shadetool::Error with `what` naming the caller's context.
#pragma once

#include <string>
#include <vector>

#include <shadetool/core/mesh_view.h>
#include <shadetool/lighting/scene.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

Scene default_scene();

// --camera: the scene's own camera (`scene`, the default) or the framing one (`frame`).
enum class CameraChoice { Scene, Frame };
CameraChoice parse_camera_choice(const std::string& text, const std::string& what);
const char* camera_choice_name(CameraChoice choice);
std::vector<std::string> camera_choice_names();
void frame_camera(const MeshView& mesh, Scene& scene, const std::string& what);

}  // namespace shadetool
#pragma GCC visibility pop
