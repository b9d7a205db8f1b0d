// validate.cpp: require_finite_positions (validate.h).
#include <shadetool/core/validate.h>

#include <cmath>
#include <vector>

#include <shadetool/core/engine/parallel.h>

namespace shadetool {

void require_finite_positions(const MeshView& mesh, const std::string& name) {
  const double* positions = mesh.positions;
  const std::size_t bad = engine::count_over_ranges(3 * mesh.num_vertices(), [positions](std::size_t b, std::size_t e) {
    std::size_t n = 0;
    for (std::size_t i = b; i < e; ++i) n += !std::isfinite(positions[i]);
    return n;
  }, std::size_t(1) << 16);
  if (bad == 0) return;
  // Rare: the vertices (not coordinates) and the first of them, serially.
  std::size_t bad_vertices = 0, first = 0;
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    const double* p = mesh.positions + 3 * v;
    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))) {
      if (bad_vertices++ == 0) first = v;
    }
  }
  // Which of them a face uses: when none does (Open3D writes NaN into the vertices its subdivision
  // left unused), the way out is to remove them, and the message says how.
  std::vector<char> used(mesh.num_vertices(), 0);
  for (std::size_t c = 0; c < mesh.corner_count; ++c)
    if (mesh.corner_vertex[c] < used.size()) used[mesh.corner_vertex[c]] = 1;
  std::size_t bad_used = 0;
  for (std::size_t v = 0; v < mesh.num_vertices(); ++v) {
    const double* p = mesh.positions + 3 * v;
    bad_used += used[v] && !(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
  }
  const std::string fix = bad_used == 0 ? std::string("; no face uses ") + (bad_vertices == 1 ? "it" : "them") +
                                              ": `shadetool repair --remove-unreferenced` removes them"
                          : bad_used < bad_vertices ? "; " + std::to_string(bad_vertices - bad_used) + " of them used by no face" +
                                                 " (`shadetool repair --remove-unreferenced` removes those)"
                                           : std::string();
  fail(name, 0, std::to_string(bad_vertices) + (bad_vertices == 1 ? " vertex has" : " vertices have") +
                    " NaN or Inf coordinates (first: vertex " + std::to_string(first) + ")" + fix);
}

}  // namespace shadetool
