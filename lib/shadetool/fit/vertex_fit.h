// vertex_fit.h: how per-vertex (Gouraud) values are chosen from a per-point signal f, and the
// option vocabulary the CLI derives its allowed values from (`--fit point|least-squares`).
//
//   point          c_i = f(x_i): the signal sampled at each vertex (what every baker does)
//   least-squares  c = argmin  integral over S of (sum_i c_i phi_i(x) - f(x))^2 dA + lambda R(c)
//                  (Kavan, Bargteil & Sloan 2011, "Least Squares Vertex Baking";
//                  fit/least_squares_fit.h): the values whose interpolation is closest to f
#pragma once

#include <optional>
#include <string>
#include <vector>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

enum class VertexFit { Point, LeastSquares };

// "point", "least-squares"
const char* vertex_fit_name(VertexFit fit);
// The inverse of vertex_fit_name; nullopt for any other text.
std::optional<VertexFit> parse_vertex_fit(const std::string& name);
// Every name, in enum order (the CLI's allowed values).
std::vector<std::string> vertex_fit_names();

}  // namespace shadetool
#pragma GCC visibility pop
