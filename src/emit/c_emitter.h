// Emits a self-contained C99/C++ header from the lowered programs.
#pragma once

#include "emit/dialect.h"
#include "emit/emitted_api.h"

#include <string>
#include <vector>

namespace offsetgen {

std::string emit_c_header(const FileFacts& facts, const std::vector<EmittedFunction>& functions,
                          const std::vector<Precision>& precisions);

}  // namespace offsetgen
