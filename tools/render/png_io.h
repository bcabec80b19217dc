// Minimal PNG output/input (8-bit RGBA, top row first) through libpng.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace offsetgen::png {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes, top row first
};

// Throws std::runtime_error naming the path on failure.
void write_rgba(const std::string& path, const Image& image);
Image read_rgba(const std::string& path);

}  // namespace offsetgen::png
