// triangle_quadrature.cpp: see triangle_quadrature.h.
#include <shadetool/fit/triangle_quadrature.h>

#include <cmath>

namespace shadetool {

namespace {

// The three points (a, b, b), (b, a, b), (b, b, a) with weight w each.
void add_orbit3(std::vector<QuadraturePoint>& rule, double a, double b, double w) {
  rule.push_back({{a, b, b}, w});
  rule.push_back({{b, a, b}, w});
  rule.push_back({{b, b, a}, w});
}

// The six permutations of (a, b, c) with weight w each.
void add_orbit6(std::vector<QuadraturePoint>& rule, double a, double b, double c, double w) {
  rule.push_back({{a, b, c}, w});
  rule.push_back({{a, c, b}, w});
  rule.push_back({{b, a, c}, w});
  rule.push_back({{b, c, a}, w});
  rule.push_back({{c, a, b}, w});
  rule.push_back({{c, b, a}, w});
}

}  // namespace

bool triangle_quadrature_supported(int points) { return triangle_quadrature_degree(points) > 0; }

int triangle_quadrature_degree(int points) {
  switch (points) {
    case 1: return 1;
    case 3: return 2;
    case 6: return 4;
    case 12: return 6;
    default: return 0;  // an int, not a library enum: any other count has no rule
  }
}

std::vector<QuadraturePoint> triangle_quadrature(int points) {
  std::vector<QuadraturePoint> rule;
  if (points == 1) {
    rule.push_back({{1.0 / 3, 1.0 / 3, 1.0 / 3}, 1.0});
  } else if (points == 3) {
    add_orbit3(rule, 0.0, 0.5, 1.0 / 3);  // the edge midpoints
  } else if (points == 6) {  // Dunavant degree 4
    add_orbit3(rule, 0.108103018168070, 0.445948490915965, 0.223381589678011);
    add_orbit3(rule, 0.816847572980459, 0.091576213509771, 0.109951743655322);
  } else if (points == 12) {  // Dunavant degree 6
    add_orbit3(rule, 0.501426509658179, 0.249286745170910, 0.116786275726379);
    add_orbit3(rule, 0.873821971016996, 0.063089014491502, 0.050844906370207);
    add_orbit6(rule, 0.053145049844817, 0.310352451033784, 0.636502499121399, 0.082851075618374);
  }
  return rule;
}

std::vector<GaussPoint> gauss_legendre_unit(int n) {
  if (n == 1) return {{0.5, 1.0}};
  if (n == 2) {
    const double d = 0.5 / std::sqrt(3.0);
    return {{0.5 - d, 0.5}, {0.5 + d, 0.5}};
  }
  if (n == 3) {
    const double d = 0.5 * std::sqrt(0.6);
    return {{0.5 - d, 5.0 / 18}, {0.5, 8.0 / 18}, {0.5 + d, 5.0 / 18}};
  }
  return {};
}

}  // namespace shadetool
