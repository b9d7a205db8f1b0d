// encode_color.h: linear colours -> what is stored: sRGB encoding and 8-bit quantisation.
//
//   srgb_encode(c)   IEC 61966-2-1: 12.92 c for c <= 0.0031308, else 1.055 c^(1/2.4) - 0.055
//                    (applied to unclamped values too, for HDR: the curve continues above 1)
//   quantize_8bit(c) round(255 * clamp(c, 0, 1)); NaN -> 0
//
// encode_colors: #P by 3 linear doubles -> #P by 3 floats.
//   hdr:   the (optionally sRGB-encoded) values, unclamped, as float
//   8-bit: quantize_8bit of the (optionally sRGB-encoded) value, stored as k / 255 in float so
//          that a writer's round(255 * c) gives back exactly k (255 * float(k/255) is within
//          2^-16 of k).
//
// The colour convention (one rule for the CLI and Python; man shadetool, COLOUR): lighting is
// linear; 8-bit outputs (PLY/OFF/OBJ byte colours, PNG) are sRGB-encoded, as viewers (Blender,
// MeshLab, three.js) read 8-bit colours; float outputs (--hdr) and glTF COLOR_0 (linear in every
// component type, glTF 2.0 3.7.2.1) are linear; `linear` (--linear) asks for linear bytes, the
// OpenGL 2.1 look, for comparisons with GL.
//   output_color_encoding(eight_bit, gltf, linear) = {hdr: !eight_bit, srgb: eight_bit && !gltf && !linear}
//
// clamp_displayable(c): clamp(c, 0, 1), NaN -> 0: the range OpenGL 2.1 clamps a vertex colour to
// before interpolating it (render's Gouraud shading).
#pragma once

#include <cstdint>
#include <vector>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

double srgb_encode(double linear);
std::uint8_t quantize_8bit(double c);

struct ColorEncoding {
  bool hdr = false;   // float output, unclamped
  bool srgb = false;  // encode with the sRGB curve first
};

// The encoding of a colour output: 8-bit or float, glTF COLOR_0 or not, linear bytes asked for.
ColorEncoding output_color_encoding(bool eight_bit, bool gltf, bool linear);

double clamp_displayable(double c);

std::vector<float> encode_colors(const std::vector<double>& linear_rgb, const ColorEncoding& encoding);

}  // namespace shadetool
#pragma GCC visibility pop
