// A run split over machines: `--tile-range I/N` (mesh) and `--layer-range I/N` (slice) name share I of
// N, counted from 0; share I holds items [total I / N, total (I + 1) / N). `--merge` joins the shares'
// part files into the single run's file.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace offsetgen {

// "I/N" -> {I, N}; throws InputError naming `option` unless 0 <= I < N.
std::pair<int, int> parse_share(const std::string& text, const std::string& option);

// The items [first, last) of share `index` of `count`.
std::pair<size_t, size_t> share_of(size_t total, int index, int count);

// --merge's paths: at least one part, and no two of the parts and `output` the same file (the output
// would overwrite a part while it is read). Throws InputError.
void check_merge_paths(const std::vector<std::string>& parts, const std::string& output);

}  // namespace offsetgen
