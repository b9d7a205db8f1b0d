// ply_types.h (engine, not installed): the PLY value types, the header's elements and properties
// as parsed, and loading one binary value of a declared type (either byte order).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace shadetool::io::ply {

enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

inline std::size_t type_size(Type t) {
  switch (t) {
    case Type::Int8: case Type::UInt8: return 1;
    case Type::Int16: case Type::UInt16: return 2;
    case Type::Int32: case Type::UInt32: case Type::Float32: return 4;
    case Type::Float64: return 8;
  }
  return 1;
}

inline bool parse_type(std::string_view s, Type& t) {
  struct Name { const char* name; Type type; };
  static const Name names[] = {{"char", Type::Int8},     {"int8", Type::Int8},       {"uchar", Type::UInt8},
                               {"uint8", Type::UInt8},   {"short", Type::Int16},     {"int16", Type::Int16},
                               {"ushort", Type::UInt16}, {"uint16", Type::UInt16},   {"int", Type::Int32},
                               {"int32", Type::Int32},   {"uint", Type::UInt32},     {"uint32", Type::UInt32},
                               {"float", Type::Float32}, {"float32", Type::Float32}, {"double", Type::Float64},
                               {"float64", Type::Float64}};
  for (const auto& n : names)
    if (s == n.name) {
      t = n.type;
      return true;
    }
  return false;
}

// PLY's own name of a type (the spelling of the original 1994 format, which every reader knows).
inline const char* type_name(Type t) {
  switch (t) {
    case Type::Int8: return "char";
    case Type::UInt8: return "uchar";
    case Type::Int16: return "short";
    case Type::UInt16: return "ushort";
    case Type::Int32: return "int";
    case Type::UInt32: return "uint";
    case Type::Float32: return "float";
    case Type::Float64: return "double";
  }
  return "double";
}

inline bool is_float_type(Type t) { return t == Type::Float32 || t == Type::Float64; }

// What an integer colour channel of this type is divided by to land in [0,1] (uchar: 255).
inline double color_divisor(Type t) {
  switch (t) {
    case Type::UInt16: case Type::Int16: return 65535.0;
    case Type::UInt32: case Type::Int32: return 4294967295.0;
    case Type::Float32: case Type::Float64: return 1.0;
    case Type::UInt8: case Type::Int8: return 255.0;
  }
  return 255.0;
}

enum class Target { Skip, X, Y, Z, NX, NY, NZ, R, G, B, A, U, V, Quality, Indices, TexcoordList, Extra };

struct Property {
  std::string name;
  bool is_list = false;
  Type type = Type::Float32;        // item type for lists
  Type count_type = Type::UInt8;    // lists only
  Target target = Target::Skip;
  int extra = -1;                   // Target::Extra: index into Mesh::vertex_properties / face_properties
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> props;
  std::size_t line = 0;  // header line that declared it
};

enum class Encoding { Ascii, BinaryLE, BinaryBE };

// ---- binary values

template <class T>
inline T load(const char* p, bool swap) {
  T v;
  if (!swap) {
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  char b[sizeof(T)];
  for (std::size_t i = 0; i < sizeof(T); ++i) b[i] = p[sizeof(T) - 1 - i];
  std::memcpy(&v, b, sizeof v);
  return v;
}

inline double load_as_double(const char* p, Type t, bool swap) {
  switch (t) {
    case Type::Int8: return double(load<std::int8_t>(p, swap));
    case Type::UInt8: return double(load<std::uint8_t>(p, swap));
    case Type::Int16: return double(load<std::int16_t>(p, swap));
    case Type::UInt16: return double(load<std::uint16_t>(p, swap));
    case Type::Int32: return double(load<std::int32_t>(p, swap));
    case Type::UInt32: return double(load<std::uint32_t>(p, swap));
    case Type::Float32: return double(load<float>(p, swap));
    case Type::Float64: return load<double>(p, swap);
  }
  return 0;
}

// Integer value of a list count or index; float-typed lists are refused at header time.
inline std::int64_t load_as_int(const char* p, Type t, bool swap) {
  switch (t) {
    case Type::Int8: return load<std::int8_t>(p, swap);
    case Type::UInt8: return load<std::uint8_t>(p, swap);
    case Type::Int16: return load<std::int16_t>(p, swap);
    case Type::UInt16: return load<std::uint16_t>(p, swap);
    case Type::Int32: return load<std::int32_t>(p, swap);
    case Type::UInt32: return load<std::uint32_t>(p, swap);
    case Type::Float32: case Type::Float64: return 0;  // refused at header time
  }
  return 0;
}


inline bool host_is_little() {
  const std::uint16_t one = 1;
  char b;
  std::memcpy(&b, &one, 1);
  return b == 1;
}

}  // namespace shadetool::io::ply
