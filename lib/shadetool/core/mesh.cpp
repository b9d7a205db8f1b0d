// mesh.cpp: the vocabulary of mesh.h's ValuePrecision (see core/vocabulary.h).
#include <shadetool/core/mesh.h>

#include <shadetool/core/vocabulary.h>

namespace shadetool {

namespace {
const NamedValue<ValuePrecision> kValuePrecisions[] = {
    {ValuePrecision::Double, "double"},
    {ValuePrecision::Float, "float"},
};
}  // namespace

ValuePrecision parse_value_precision(std::string_view text, const std::string& what) {
  return parse_named(kValuePrecisions, text, what);
}
const char* value_precision_name(ValuePrecision precision) { return name_of(kValuePrecisions, precision); }
std::vector<std::string> value_precision_names() { return names_of(kValuePrecisions); }

}  // namespace shadetool
