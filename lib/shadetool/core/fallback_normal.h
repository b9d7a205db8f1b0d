// fallback_normal.h: the one normal written where no normal can be computed (an isolated or
// unreferenced vertex, a vertex whose faces are all degenerate, a degenerate face): +z, unit.
// Every module that writes a normal it could not compute writes this one, so that no written
// normal is ever zero or NaN (man shadetool-normals, "Degenerate input").
#pragma once

namespace shadetool {

constexpr double kFallbackNormal[3] = {0.0, 0.0, 1.0};

}  // namespace shadetool
