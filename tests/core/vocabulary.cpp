// Tests of core/vocabulary.h and of every option's vocabulary table beside its enum (issue 26,
// item 2): each table is complete (every enum value, listed here from the enum's definition,
// round-trips through its name), its names are the documented spellings (man pages, scene
// schema), and a bad name fails with one message naming who asked and every accepted name.
#include <shadetool/core/vocabulary.h>

#include <catch2/catch.hpp>

#include <shadetool/core/mesh.h>
#include <shadetool/lighting/bake_lighting.h>
#include <shadetool/lighting/scene.h>
#include <shadetool/lighting/shading_space.h>
#include <shadetool/normals/weighting.h>
#include <shadetool/render/render_mesh.h>
#include <shadetool/transform/transform_mesh.h>

using namespace shadetool;

namespace {

// Every value has a distinct name that parses back to it; the list has one name per value, in
// the order given (the documented order, which help and messages print).
template <class E, class Parse, class Name, class Names>
void check_vocabulary(const std::vector<E>& values, const std::vector<std::string>& documented, Parse parse, Name name,
                      Names names) {
  REQUIRE(names() == documented);
  for (std::size_t i = 0; i < values.size(); ++i) {
    INFO("value " << i);
    CHECK(std::string(name(values[i])) == documented[i]);
    CHECK(parse(documented[i], "test") == values[i]);
  }
  std::string list;
  for (const std::string& n : documented) list += (list.empty() ? "" : ", ") + n;
  CHECK_THROWS_WITH(parse("nonsense", "--flag"), "--flag: 'nonsense' is not one of " + list);
  CHECK_THROWS_AS(parse(documented[0] + " ", "x"), Error);  // exact: no trimming
  CHECK_THROWS_AS(parse("", "x"), Error);
}

}  // namespace

TEST_CASE("parse_named: exact names, one message listing every name", "[core][vocabulary]") {
  enum class Colour { Red, Green };
  const NamedValue<Colour> table[] = {{Colour::Red, "red"}, {Colour::Green, "green"}};
  CHECK(parse_named(table, "green", "c") == Colour::Green);
  CHECK_THROWS_WITH(parse_named(table, "Red", "$.colour"), "$.colour: 'Red' is not one of red, green");
  CHECK(std::string(name_of(table, Colour::Red)) == "red");
  CHECK(names_of(table) == std::vector<std::string>{"red", "green"});
  CHECK(joined_names(table, "|") == "red|green");
}

TEST_CASE("Every option's vocabulary is complete and spelled as documented", "[core][vocabulary]") {
  check_vocabulary<ShadingModel>({ShadingModel::Lambert, ShadingModel::Phong, ShadingModel::BlinnPhong},
                                 {"lambert", "phong", "blinn-phong"}, parse_shading_model, shading_model_name,
                                 shading_model_names);
  check_vocabulary<ShadingSpace>({ShadingSpace::Auto, ShadingSpace::World, ShadingSpace::Camera, ShadingSpace::Object},
                                 {"auto", "world", "camera", "object"}, parse_shading_space, shading_space_name,
                                 shading_space_names);
  check_vocabulary<ShadingFrequency>({ShadingFrequency::PerVertex, ShadingFrequency::PerFace}, {"vertex", "face"},
                                     parse_shading_frequency, shading_frequency_name, shading_frequency_names);
  check_vocabulary<RenderShading>({RenderShading::Flat, RenderShading::Gouraud, RenderShading::Phong},
                                  {"flat", "gouraud", "phong"}, parse_render_shading, render_shading_name,
                                  render_shading_names);
  check_vocabulary<Weighting>({Weighting::Uniform, Weighting::Area, Weighting::Angle, Weighting::Max},
                              {"uniform", "area", "angle", "max"}, parse_weighting, weighting_name, weighting_names);
  check_vocabulary<Precision>({Precision::Double, Precision::Float}, {"double", "float"}, parse_precision,
                              precision_name, precision_names);
  check_vocabulary<NormalsPolicy>({NormalsPolicy::Transform, NormalsPolicy::Recompute, NormalsPolicy::Drop},
                                  {"transform", "recompute", "drop"}, parse_normals_policy, normals_policy_name,
                                  normals_policy_names);
  check_vocabulary<ValuePrecision>({ValuePrecision::Double, ValuePrecision::Float}, {"double", "float"},
                                   parse_value_precision, value_precision_name, value_precision_names);
}
