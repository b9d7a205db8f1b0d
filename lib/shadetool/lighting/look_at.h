// look_at.h: the view matrix of a camera at `eye` looking at `target` (gluLookAt).
//
// Inputs:  eye, target, up   world-space points / direction, double
// Output:  camera_from_world V, rigid: rows s, u, -f of the rotation with
//          f = normalize(target - eye), s = normalize(f x up), u = s x f, and t = -R eye,
//          so the eye maps to the origin and the target onto the -z axis (OpenGL convention).
// Degenerate input: target == eye (no view direction) or up parallel to f -> returns false and
//          leaves `view` untouched (lengths are checked before every division).
#pragma once

#include <shadetool/core/affine.h>
#include <shadetool/core/vec3.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

bool look_at(const Vec3d& eye, const Vec3d& target, const Vec3d& up, Affine3d& view);

}  // namespace shadetool
#pragma GCC visibility pop
