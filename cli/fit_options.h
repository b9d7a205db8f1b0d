// fit_options.h: the options of lib/shadetool/fit shared by bake-lighting and occlusion
// (`--fit point|least-squares`, `--fit-regularization λ`, `--fit-samples N`), their allowed values
// from the library's vocabulary (fit/vertex_fit.h), and the --stats keys of a fit.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "driver.h"
#include <shadetool/fit/least_squares_fit.h>
#include <shadetool/fit/triangle_quadrature.h>
#include <shadetool/fit/vertex_fit.h>

namespace shadetool_cli {

struct FitCliOptions {
  std::string method = shadetool::vertex_fit_name(shadetool::VertexFit::Point);
  double regularization = shadetool::LeastSquaresFitOptions{}.regularization;
  int samples = 3;
};

// Adds the three options to `sub`; `what` names the signal in the help ("lit colour", "open fraction").
inline void add_fit_options(CLI::App& sub, FitCliOptions& o, const std::string& what) {
  sub.add_option("--fit", o.method,
                 "Per-vertex values: point (the " + what + " at each vertex, default) or least-squares (the values whose "
                 "Gouraud interpolation is closest in L2 over the surface to the " + what + " at every point; Kavan, "
                 "Bargteil & Sloan 2011)")
      ->check(CLI::IsMember(shadetool::vertex_fit_names()))
      ->type_name("METHOD");
  sub.add_option("--fit-regularization", o.regularization,
                 "With --fit least-squares: weight λ of the regulariser (squared gradient jumps across edges; 0: the "
                 "plain least-squares solution; default " + CLI::detail::to_string(o.regularization) + ")")
      ->check(CLI::NonNegativeNumber)
      ->type_name("λ");
  sub.add_option("--fit-samples", o.samples,
                 "With --fit least-squares: quadrature points per triangle, 1, 3 (default) or 6 (exact to degree 1, 2, 4; "
                 "3: the edge midpoints, each computed once for the two triangles of its edge; quads 1x1, 2x2, 3x3 "
                 "Gauss points)")
      ->check(CLI::IsMember({1, 3, 6}))
      ->type_name("N");
}

inline shadetool::VertexFit fit_method(const FitCliOptions& o) {
  return shadetool::parse_vertex_fit(o.method).value_or(shadetool::VertexFit::Point);  // checked by IsMember
}

// The library's options of a least-squares fit (no clamp: each caller sets its bounds). The errors
// are measured only for --stats and --json, the only outputs that show them.
inline shadetool::VertexFitOptions vertex_fit_options(const FitCliOptions& o, const IoOptions& io) {
  shadetool::VertexFitOptions v;
  v.method = fit_method(o);
  v.samples = o.samples;
  v.solve.regularization = o.regularization;
  v.measure_error = io.stats || io.json;
  return v;
}

// The --stats keys of a least-squares fit.
inline void report_fit(FileResult& r, const shadetool::LeastSquaresFit& s, double error_fit, double error_point,
                       std::size_t points, const FitCliOptions& o) {
  r.stats["fit"] = o.method;
  r.setting("fit_regularization", o.regularization);
  r.setting("fit_samples", o.samples);
  r.stats["fit_quadrature_points"] = points;
  r.stats["fit_error"] = error_fit;
  r.stats["point_error"] = error_point;
  r.stats["fit_clamped"] = s.clamped;
  r.stats["fit_fallback_nodes"] = s.fallback_nodes;
  r.stats["fit_regularized_edges"] = s.regularized_edges;
  r.stats["fit_cg_iterations"] = s.iterations;
  r.stats["fit_cg_residual"] = s.residual;
  if (!s.converged)
    r.notes.push_back("least-squares fit: conjugate gradient stopped at relative residual " +
                      CLI::detail::to_string(s.residual) + " before the tolerance");
}

}  // namespace shadetool_cli
