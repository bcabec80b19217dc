// 8-bit greyscale PNG in memory (libpng): no ancillary chunks, so the bytes depend on the pixels alone.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace offsetgen::slice {

// row(r, out) fills row r (width bytes).
std::string encode_grey_png(int width, int height, const std::function<void(int, std::vector<uint8_t>&)>& row);

}  // namespace offsetgen::slice
