// vertex_fit.cpp: see vertex_fit.h.
#include <shadetool/fit/vertex_fit.h>

namespace shadetool {

const char* vertex_fit_name(VertexFit fit) {
  switch (fit) {
    case VertexFit::Point: return "point";
    case VertexFit::LeastSquares: return "least-squares";
  }
  return "point";  // unreachable: every enumerator is named above
}

std::vector<std::string> vertex_fit_names() {
  return {vertex_fit_name(VertexFit::Point), vertex_fit_name(VertexFit::LeastSquares)};
}

std::optional<VertexFit> parse_vertex_fit(const std::string& name) {
  for (VertexFit f : {VertexFit::Point, VertexFit::LeastSquares})
    if (name == vertex_fit_name(f)) return f;
  return std::nullopt;
}

}  // namespace shadetool
