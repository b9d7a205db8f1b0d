// weighting.cpp: the vocabularies of weighting.h's Weighting and Precision (core/vocabulary.h).
#include <shadetool/normals/weighting.h>

#include <shadetool/core/vocabulary.h>

namespace shadetool {

namespace {
const NamedValue<Weighting> kWeightings[] = {
    {Weighting::Uniform, "uniform"},
    {Weighting::Area, "area"},
    {Weighting::Angle, "angle"},
    {Weighting::Max, "max"},
};
const NamedValue<RankedWeighting> kRankedWeightings[] = {
    {RankedWeighting::FaceArea, "face-area"},
    {RankedWeighting::CornerAngle, "corner-angle"},
    {RankedWeighting::FaceAreaAngle, "face-area-angle"},
};
const NamedValue<Precision> kPrecisions[] = {
    {Precision::Double, "double"},
    {Precision::Float, "float"},
};
}  // namespace

Weighting parse_weighting(std::string_view text, const std::string& what) { return parse_named(kWeightings, text, what); }
const char* weighting_name(Weighting weighting) { return name_of(kWeightings, weighting); }
std::vector<std::string> weighting_names() { return names_of(kWeightings); }

std::optional<RankedWeighting> find_ranked_weighting(std::string_view text) {
  for (const NamedValue<RankedWeighting>& entry : kRankedWeightings)
    if (text == entry.name) return entry.value;
  return std::nullopt;
}
const char* ranked_weighting_name(RankedWeighting weighting) { return name_of(kRankedWeightings, weighting); }
std::vector<std::string> ranked_weighting_names() { return names_of(kRankedWeightings); }

Precision parse_precision(std::string_view text, const std::string& what) { return parse_named(kPrecisions, text, what); }
const char* precision_name(Precision precision) { return name_of(kPrecisions, precision); }
std::vector<std::string> precision_names() { return names_of(kPrecisions); }

}  // namespace shadetool
