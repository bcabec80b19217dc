// The file check: that the bytes export wrote hold the whole solid it measured, and
// `offsetgen check part.step`, a written file read back and measured again.
#pragma once

#include "step/step_request.h"
#include "step/step_summary.h"

#include <TopoDS_Shape.hxx>

#include <functional>
#include <string>

namespace offsetgen::step {

// "" when the STEP text holds a MANIFOLD_SOLID_BREP for each solid of `solid` and an ADVANCED_FACE for
// each face (the translation lost nothing), else what is missing.
std::string file_holds_the_solid(const std::string& bytes, const TopoDS_Shape& solid);

// `offsetgen check part.step`: a file of `offsetgen step`, measured again against the walls its header
// names (step_metadata.h): valid closed solids, the exact walls within its tolerance of the faces, its
// volume against the exact wall volume; summary.passed when all hold. Throws InputError for a file
// that is not a STEP file of offsetgen's.
struct StepCheck {
  StepRequest request;  // as the header gives it
  StepSummary summary;
};
StepCheck check_step_file(const std::string& path, const std::function<void(const std::string&)>& progress);
std::string format_check_summary(const StepCheck& check, const std::string& path);

}  // namespace offsetgen::step
