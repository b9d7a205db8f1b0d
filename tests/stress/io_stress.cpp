// Values at the edges of float's and double's ranges through the readers and writers: text that
// float cannot hold keeps the mesh in double (so 1e300 is not read as Inf, 1e-45 not as a float
// subnormal), and every format that stores double gives the value back bit for bit.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "core/mesh.h"
#include "io/mesh_io.h"
#include "stress/stress_util.h"

using namespace shadetool;

namespace {

// Literal -> the double it denotes (strtod rounds correctly, like fast_float).
double value(const char* literal) { return std::strtod(literal, nullptr); }

const char* kLiterals[] = {"1e300", "-1e-300", "1e-45", "3.4028235e38", "3.5e38", "1.7976931348623157e308",
                           "4.9406564584124654e-324", "1e-38", "0"};

}  // namespace

TEST_CASE("stress io: coordinates beyond float's range are read exactly, never as Inf or 0", "[stress][io]") {
  // One triangle per literal, the literal as its first vertex's x. Expected: the mesh is read in
  // double (precision Double) and x == strtod(literal) exactly, in OBJ, OFF and ascii STL.
  for (const char* lit : kLiterals) {
    const std::string l(lit);
    const std::string obj = "v " + l + " 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n";
    const std::string off = "OFF\n3 1 0\n" + l + " 0 0\n0 1 0\n0 0 1\n3 0 1 2\n";
    const std::string stl = "solid s\nfacet normal 0 0 0\nouter loop\nvertex " + l +
                            " 0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\nendfacet\nendsolid s\n";
    for (const auto& [text, format] :
         std::vector<std::pair<std::string, Format>>{{obj, Format::Obj}, {off, Format::Off}, {stl, Format::Stl}}) {
      INFO(lit << " in " << format_extension(format));
      const Mesh m = read_mesh_from_memory(text, format, std::string("edge.") + format_extension(format));
      REQUIRE(m.num_vertices() == 3);
      CHECK(m.positions[0] == value(lit));
      CHECK(std::isfinite(m.positions[0]));
      const bool float_holds = value(lit) == double(float(value(lit))) && std::isfinite(float(value(lit))) &&
                               (value(lit) == 0 || std::fabs(value(lit)) >= std::numeric_limits<float>::min());
      if (!float_holds) CHECK(m.precision == ValuePrecision::Double);
      // Written back (text: shortest round trip; PLY binary: double) and read again: same bits.
      for (Format out : {Format::Obj, Format::Off, Format::Ply}) {
        WriteOptions wo;
        wo.format = out;
        const Mesh back = read_mesh_from_memory(write_mesh_to_memory(m, wo), out, "back");
        CHECK(back.positions == m.positions);
      }
    }
  }
}

TEST_CASE("stress io: float-sized text stays float-sized; the narrowing is exact float rounding", "[stress][io]") {
  // Nine significant digits or fewer and inside float's normal range: the file was written from
  // float data; each value is stored as the float it denotes (double(float(x))).
  const Mesh m = read_mesh_from_memory("v 0.1 0.2 0.3\nv 1e-30 1e30 -2.5\nv 0 1 0\nf 1 2 3\n", Format::Obj, "f.obj");
  CHECK(m.precision == ValuePrecision::Float);
  const double expected[] = {0.1, 0.2, 0.3, 1e-30, 1e30, -2.5, 0, 1, 0};
  for (int i = 0; i < 9; ++i) CHECK(m.positions[std::size_t(i)] == double(float(expected[i])));
}
