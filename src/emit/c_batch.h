// The batch (array) API of the C header: <prefix>_offset_n and <prefix>_shell_n (and their float
// twins), loops written to vectorise. The text skeleton is templates/c/c_batch.in.
#pragma once

#include "emit/dialect.h"
#include "emit/emitted_api.h"

#include <string>
#include <vector>

namespace offsetgen {

// The batch section of a C header: the loop pragma macro, the vectorisable sin/cos/sqrt helpers of
// each requested precision, and one `_n` function per batched scalar function (offset and shell).
// Returns "" when `functions` holds nothing to batch.
std::string emit_c_batch(const FileFacts& facts, const std::vector<EmittedFunction>& functions,
                         const std::vector<Precision>& precisions);

// Argument ranges (radians) where the inline sin/cos helpers' Cody-Waite reduction is exact
// (templates/c/c_batch.in, templates/c/c_scalar_trig.in).
inline constexpr const char* kTrigRangeDouble = "1.0e8";
inline constexpr const char* kTrigRangeFloat = "8192.0";

// Replaces calls of the functions `names` (and their float spellings, name + "f") in printed C by
// prefix + the name, e.g. names {"sin", "sqrt"} with prefix "offsetgen_batch_": offsetgen_batch_sin(f),
// offsetgen_batch_sqrt(f); other text (asin, sinh, _tsin, ...) is untouched.
std::string rename_calls(const std::string& code, const std::vector<std::string>& names, const std::string& prefix);

// rename_calls for sin and cos.
std::string rename_trig_calls(const std::string& code, const std::string& prefix);

}  // namespace offsetgen
