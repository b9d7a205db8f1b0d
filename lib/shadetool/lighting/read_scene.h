// read_scene.h: a lighting scene from JSON, every field validated.
//
// Inputs:  path (read_scene) or the JSON text and a name for messages (parse_scene)
// Output:  Scene (lighting/scene.h); positions and directions in world space, angles in degrees as
//          written (cutoff), matrices row-major 4x4 with bottom row 0 0 0 1.
// Errors:  throws shadetool::Error with ONE line naming the file, the JSON path and the problem:
//            scene.json: $.lights[1].cutoff: must be in [0, 90] degrees or 180 (no cone), got 95
//            scene.json: $.material.colour: unknown key (expected one of: ambient, diffuse, ...)
//            scene.json:3: invalid JSON at column 7: syntax error while parsing value - ...
//          Checked: unknown and duplicate keys, missing required keys, wrong JSON types, numbers
//          that are not finite, negative colours, intensities, shininess, exponents or attenuation
//          coefficients, attenuation [0,0,0], zero-length directions, cutoff outside [0,90] u {180},
//          matrices that are not affine or whose 3x3 part is singular, a camera whose target is its
//          eye or whose up is parallel to the view direction.
//
// The format (defaults in parentheses; see man/shadetool-bake-lighting.1):
//   model             "lambert" | "phong" | "blinn-phong"        ("blinn-phong")
//   world_from_object 16 numbers, row-major                       (identity)
//   camera            {"eye": P, "target": P, "up": D ([0,1,0])} or {"view": 16 numbers}
//                     (absent: eye at the world origin, OpenGL's default); a top-level "view"
//                     is accepted in place of "camera": {"view": ...}
//   ambient           global ambient colour                       ([0.2,0.2,0.2])
//   two_sided         true | false                                (false)
//   material          {ambient ([0.2]*3), diffuse ([0.8]*3), specular ([0]*3), emission ([0]*3),
//                      shininess (0)}
//   lights            array of {"type": "ambient"|"directional"|"point"|"spot", ...}; each may
//                     have color ([1,1,1]) and intensity (1), from which diffuse and specular
//                     default to color*intensity, and ambient (black); directional: direction;
//                     point: position, attenuation ([1,0,0]); spot: position, direction, cutoff,
//                     exponent (0), attenuation. An "ambient" light has only color and intensity.
//                     "area" (issue 16): shape "rect" (center, u, v), "polygon" (vertices: 3..64,
//                     planar, convex, counter-clockwise seen from the emitting side) or "sphere"
//                     (center, radius > 0); color, intensity (L = color * intensity), two_sided
//                     (false), ambient. "sky": up ([0,1,0]), sky ([1,1,1]), ground ([0,0,0]),
//                     intensity (1), ambient. "environment": image (a Radiance .hdr, relative to
//                     the scene file's folder; read here, lighting/environment_map.h), rotation
//                     ([degrees, ax, ay, az], none), intensity (1), ambient. Each kind is one
//                     entry of read_scene.cpp's light table.
//          Also checked: color * intensity beyond double's range (issue 21), polygons that are
//          non-planar (1e-9 of their size), non-convex, self-winding or of zero area, a rect with
//          u parallel to v, a zero sky up, an environment image that cannot be opened, is not a
//          Radiance .hdr or ends early, a rotation with a zero axis.
#pragma once

#include <string>
#include <string_view>

#include <shadetool/lighting/scene.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

Scene read_scene(const std::string& path);
Scene parse_scene(std::string_view json_text, const std::string& name);

}  // namespace shadetool
#pragma GCC visibility pop
