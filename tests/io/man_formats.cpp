// The man page's table of which attribute survives which format (man/shadetool.1, "What survives
// which format") is the format table's: each "written" cell equals FormatEntry::holds, and each
// "read from" format is one of the table (format_table.cpp's test checks that holds matches what
// the writers and readers actually carry, format by format).
#include <shadetool/files/format_table.h>

#include "io_test_util.h"

using namespace shadetool;
using namespace shadetool::iotest;

namespace {

std::vector<std::string> split_tabs(const std::string& line) {
  std::vector<std::string> out;
  std::size_t b = 0;
  for (;;) {
    const std::size_t t = line.find('\t', b);
    out.push_back(line.substr(b, t == std::string::npos ? std::string::npos : t - b));
    if (t == std::string::npos) return out;
    b = t + 1;
  }
}

const char* holds_word(Holds h) {
  switch (h) {
    case Holds::No: return "no";
    case Holds::Yes: return "yes";
    case Holds::Converted: return "converted";
  }
  return "?";
}

Holds FormatAttributes::*field_of(const std::string& attribute) {
  if (attribute == "vertex normals") return &FormatAttributes::vertex_normals;
  if (attribute == "corner normals") return &FormatAttributes::corner_normals;
  if (attribute == "face normals") return &FormatAttributes::face_normals;
  if (attribute == "texcoords") return &FormatAttributes::texcoords;
  if (attribute == "vertex colours") return &FormatAttributes::vertex_colors;
  if (attribute == "face colours") return &FormatAttributes::face_colors;
  if (attribute == "groups") return &FormatAttributes::groups;
  return nullptr;
}

}  // namespace

TEST_CASE("man page: the table of what survives which format is the format table's", "[format_table][man]") {
  const std::string page = read_file(std::string(SHADETOOL_SOURCE_DIR) + "/man/shadetool.1");
  const std::size_t b = page.find("survives-table-begin"), e = page.find(".\\\" survives-table-end");
  REQUIRE(b != std::string::npos);
  REQUIRE(e != std::string::npos);
  std::istringstream rows(page.substr(page.find('\n', b) + 1, e - page.find('\n', b) - 1));
  std::string line;
  REQUIRE(std::getline(rows, line));
  const std::vector<std::string> header = split_tabs(line);
  REQUIRE(header.size() == 2 + mesh_formats().size());
  for (std::size_t k = 0; k < mesh_formats().size(); ++k) {
    std::string upper = mesh_formats()[k].name;
    for (char& c : upper) c = char(std::toupper(static_cast<unsigned char>(c)));
    CHECK(header[2 + k] == upper);
  }
  std::size_t attributes = 0;
  while (std::getline(rows, line)) {
    const std::vector<std::string> cells = split_tabs(line);
    REQUIRE(cells.size() == header.size());
    INFO(line);
    const auto field = field_of(cells[0]);
    REQUIRE(field != nullptr);
    ++attributes;
    for (std::size_t k = 0; k < mesh_formats().size(); ++k) CHECK(cells[2 + k] == holds_word(mesh_formats()[k].holds.*field));
    // every format named as a reader of the attribute is a format of the table
    std::istringstream readers(cells[1]);
    std::string name;
    while (readers >> name) CHECK(find_format(name) != nullptr);
  }
  CHECK(attributes == 7);
}
