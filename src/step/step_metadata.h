// The request as a file's header carries it (FILE_DESCRIPTION: a line for people, then
// kMetadataTag and JSON), so that `offsetgen check` builds the same walls again.
#pragma once

#include "step/step_request.h"
#include "step/step_summary.h"

#include <string>

namespace offsetgen::step {

// The header's description of the file export writes (the summary gives the surface, the thickness
// as given and the solids expected).
std::string file_description(const StepRequest& request, const StepSummary& summary);

// The request a file's header describes, and in `solids` the solids export expected; InputError
// naming what is missing or out of range. `path` names the file in the messages.
StepRequest request_from_description(const std::string& description, const std::string& path, int& solids);

}  // namespace offsetgen::step
