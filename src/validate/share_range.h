// A run split over machines: `--tile-range I/N` (mesh) and `--layer-range I/N` (slice) name share I of
// N, counted from 0; share I holds items [total I / N, total (I + 1) / N).
#pragma once

#include <cstddef>
#include <string>
#include <utility>

namespace offsetgen {

// "I/N" -> {I, N}; throws InputError naming `option` unless 0 <= I < N.
std::pair<int, int> parse_share(const std::string& text, const std::string& option);

// The items [first, last) of share `index` of `count`.
std::pair<size_t, size_t> share_of(size_t total, int index, int count);

}  // namespace offsetgen
