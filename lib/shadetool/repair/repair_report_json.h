// repair_report_json.h: a RepairReport as the JSON object `shadetool repair --report` writes, key
// for key (the Python module's `repair` returns the same object as a dict): one home for its keys.
//
// Inputs:  report     what repair_mesh returned
//          weld_eps   the weld distance used, or < 0 when no weld was asked for (written as null)
//          weighting  the name of the vertex-normal weighting ("angle", "area", "uniform", "max")
// Output:  compact JSON text of one object (callers add their own keys, e.g. input and output).
#pragma once

#include <string>

#include <shadetool/repair/repair_report.h>

#pragma GCC visibility push(default)  // public API: exported from libshadetool.so
namespace shadetool {

std::string repair_report_json(const RepairReport& report, double weld_eps, const std::string& weighting);

}  // namespace shadetool
#pragma GCC visibility pop
