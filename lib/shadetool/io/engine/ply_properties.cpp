// ply_properties.cpp: PLY property names to Mesh arrays (see ply_properties.h).
#include <shadetool/io/engine/ply_properties.h>

#include <shadetool/core/error.h>

namespace shadetool::io::ply {

namespace {

void map_vertex_properties(Element& vertex, PlyLayout& layout, const std::string& name) {
  for (auto& prop : vertex.props) {
    if (prop.is_list) continue;
    const std::string& n = prop.name;
    Target t = Target::Skip;
    if (n == "x") t = Target::X;
    else if (n == "y") t = Target::Y;
    else if (n == "z") t = Target::Z;
    else if (n == "nx") t = Target::NX;
    else if (n == "ny") t = Target::NY;
    else if (n == "nz") t = Target::NZ;
    else if (n == "red" || n == "diffuse_red" || n == "r") t = Target::R;
    else if (n == "green" || n == "diffuse_green" || n == "g") t = Target::G;
    else if (n == "blue" || n == "diffuse_blue" || n == "b") t = Target::B;
    else if (n == "alpha" || n == "diffuse_alpha" || n == "a") t = Target::A;
    else if (n == "s" || n == "u" || n == "texture_u" || n == "texture_s") t = Target::U;
    else if (n == "t" || n == "v" || n == "texture_v" || n == "texture_t") t = Target::V;
    else if (n == "quality" && !layout.vquality) t = Target::Quality, layout.vquality = true;
    prop.target = t;
    if (t >= Target::X && t <= Target::NZ) {
      if (t >= Target::NX) layout.vnormal[int(t) - int(Target::NX)] = true;
      if (prop.type == Type::Float64 || prop.type == Type::Int32 || prop.type == Type::UInt32) layout.any_double = true;
    }
    if (t >= Target::R && t <= Target::A) {
      layout.vcolor[int(t) - int(Target::R)] = true;
      if (is_float_type(prop.type)) layout.colors_float = true;
    }
    if (t == Target::U || t == Target::V) {
      layout.vtex[t == Target::V] = true;
      if (prop.type == Type::Float64) layout.any_double = true;
    }
  }
  bool xyz[3] = {false, false, false};
  for (auto& prop : vertex.props)
    if (prop.target >= Target::X && prop.target <= Target::Z) xyz[int(prop.target) - int(Target::X)] = true;
  if (!(xyz[0] && xyz[1] && xyz[2])) fail(name, vertex.line, "vertex element has no x, y and z properties");
}

void map_face_properties(Element& face, PlyLayout& layout, const std::string& name) {
  for (auto& prop : face.props) {
    const std::string& n = prop.name;
    if (prop.is_list) {
      if ((n == "vertex_indices" || n == "vertex_index") && !is_float_type(prop.type)) {
        bool taken = false;
        for (auto& q : face.props) taken = taken || q.target == Target::Indices;
        if (!taken) prop.target = Target::Indices;
      } else if (n == "texcoord" && is_float_type(prop.type)) {
        prop.target = Target::TexcoordList;
        layout.face_texcoords = true;
        if (prop.type == Type::Float64) layout.any_double = true;
      }
      continue;
    }
    Target t = Target::Skip;
    if (n == "nx") t = Target::NX;
    else if (n == "ny") t = Target::NY;
    else if (n == "nz") t = Target::NZ;
    else if (n == "red" || n == "diffuse_red") t = Target::R;
    else if (n == "green" || n == "diffuse_green") t = Target::G;
    else if (n == "blue" || n == "diffuse_blue") t = Target::B;
    else if (n == "alpha" || n == "diffuse_alpha") t = Target::A;
    else if (n == "quality" && !layout.fquality) t = Target::Quality, layout.fquality = true;
    prop.target = t;
    if (t >= Target::NX && t <= Target::NZ) {
      layout.fnormal[int(t) - int(Target::NX)] = true;
      if (prop.type == Type::Float64) layout.any_double = true;
    }
    if (t >= Target::R && t <= Target::A) {
      layout.fcolor[int(t) - int(Target::R)] = true;
      if (is_float_type(prop.type)) layout.colors_float = true;
    }
  }
  bool indices = false;
  for (auto& prop : face.props) indices = indices || prop.target == Target::Indices;
  if (!indices) fail(name, face.line, "face element has no vertex_indices list");
  if (!layout.vertex && face.count > 0) fail(name, face.line, "faces but no vertex element");
}

// Every scalar property of `e` that no Mesh array took (an unknown name, a second `quality`, the
// components of an attribute declared incompletely, e.g. nx ny without nz) becomes an extra
// property, kept by name and type (Mesh::vertex_properties / face_properties).
std::vector<std::string> mark_extras(Element& e, bool is_vertex, const PlyLayout& layout) {
  std::vector<std::string> names;
  for (auto& prop : e.props) {
    if (prop.is_list) continue;
    const Target t = prop.target;
    bool kept = t == Target::Quality || t == Target::X || t == Target::Y || t == Target::Z;
    if (t >= Target::NX && t <= Target::NZ) kept = is_vertex ? layout.has_vnormals() : layout.has_fnormals();
    if (t >= Target::R && t <= Target::A) kept = is_vertex ? layout.has_vcolors() : layout.has_fcolors();
    if (t == Target::U || t == Target::V) kept = layout.has_vtex();
    if (kept) continue;
    prop.target = Target::Extra;
    prop.extra = int(names.size());
    names.push_back(prop.name);
  }
  return names;
}

}  // namespace

PlyLayout map_ply_properties(std::vector<Element>& elements, const std::string& name) {
  PlyLayout layout;
  for (auto& e : elements) {
    if (e.name == "vertex" && !layout.vertex) layout.vertex = &e;
    if (e.name == "face" && !layout.face) layout.face = &e;
  }
  if (!layout.face)
    for (auto& e : elements)
      if (e.name == "tristrips" && !layout.strips)
        for (auto& prop : e.props)
          if (prop.is_list && prop.name == "vertex_indices" && !is_float_type(prop.type) && !layout.strips) {
            prop.target = Target::Indices;
            layout.strips = &e;
          }
  if (layout.strips && !layout.vertex && layout.strips->count > 0)
    fail(name, layout.strips->line, "triangle strips but no vertex element");
  if (layout.vertex) map_vertex_properties(*layout.vertex, layout, name);
  if (layout.face) map_face_properties(*layout.face, layout, name);
  if (layout.vertex) layout.vertex_extras = mark_extras(*layout.vertex, true, layout).size();
  if (layout.face) layout.face_extras = mark_extras(*layout.face, false, layout).size();
  return layout;
}

}  // namespace shadetool::io::ply
