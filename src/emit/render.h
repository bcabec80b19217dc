// The one renderer of every target: the functions of each precision through the backend's printer
// hooks into the function skeleton, then the whole file into the file skeleton (templates/<lang>/).
#pragma once

#include "emit/backend.h"
#include "emit/emitted_api.h"

#include <string>
#include <vector>

namespace offsetgen {

std::string render_file(const Backend& backend, const FileFacts& facts, const std::vector<EmittedFunction>& functions,
                        const std::vector<Precision>& precisions);

}  // namespace offsetgen
