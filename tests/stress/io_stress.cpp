// Values at the edges of float's and double's ranges through the readers and writers. Text values
// are kept exactly as parsed; the precision hint (what binary writers store) must be Double when
// float cannot hold a value at all (1e300 would become Inf, 1e-50 zero), so that no binary output
// holds an Inf or a 0 the input did not.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <shadetool/core/mesh.h>
#include <shadetool/files/mesh_files.h>
#include "stress/stress_util.h"

using namespace shadetool;

namespace {

// Literal -> the double it denotes (strtod rounds correctly, like fast_float).
double value(const char* literal) { return std::strtod(literal, nullptr); }

const char* kLiterals[] = {"1e300", "-1e-300", "1e-50", "3.5e38", "1.7976931348623157e308", "4.9406564584124654e-324",
                           "1e-45", "1e-40", "1e-38", "3.4e38", "0"};

// Float holds it (exactly or to the nearest float, never Inf or 0 for a non-zero value).
bool float_can_hold(double x) {
  const float f = float(x);
  return std::isfinite(f) && (x == 0 || f != 0);
}

}  // namespace

TEST_CASE("stress io: coordinates beyond float's range are read exactly and written without Inf or 0", "[stress][io]") {
  // One triangle per literal, the literal as its first vertex's x. Expected: x == strtod(literal)
  // exactly in OBJ, OFF and ascii STL; the hint is Double whenever float cannot hold x; written as
  // OBJ, OFF and binary PLY and read back: exactly x again, except that a binary PLY of a mesh
  // whose every value float can hold stores floats (documented narrowing: x to the nearest float).
  for (const char* lit : kLiterals) {
    const std::string l(lit);
    const std::string obj = "v " + l + " 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n";
    const std::string off = "OFF\n3 1 0\n" + l + " 0 0\n0 1 0\n0 0 1\n3 0 1 2\n";
    const std::string stl = "solid s\nfacet normal 0 0 0\nouter loop\nvertex " + l +
                            " 0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\nendfacet\nendsolid s\n";
    const double x = value(lit);
    for (const auto& [text, format] :
         std::vector<std::pair<std::string, Format>>{{obj, Format::Obj}, {off, Format::Off}, {stl, Format::Stl}}) {
      INFO(lit << " in " << format_extension(format));
      const Mesh m = read_mesh_from_memory(text, format, std::string("edge.") + format_extension(format));
      REQUIRE(m.num_vertices() == 3);
      CHECK(m.positions[0] == x);
      if (!float_can_hold(x)) CHECK(m.precision == ValuePrecision::Double);
      for (Format out : {Format::Obj, Format::Off, Format::Ply}) {
        WriteOptions wo;
        wo.format = out;
        const Mesh back = read_mesh_from_memory(write_mesh_to_memory(m, wo), out, "back");
        INFO("written as " << format_extension(out));
        CHECK(std::isfinite(back.positions[0]));
        CHECK((x == 0) == (back.positions[0] == 0));
        if (out == Format::Ply && m.precision == ValuePrecision::Float) CHECK(back.positions[0] == double(float(x)));
        else CHECK(back.positions == m.positions);
      }
    }
  }
}
