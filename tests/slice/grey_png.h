// A PNG read as 8-bit grey (libpng's simplified API: colour is converted, alpha composed on black), and
// a member of a zip archive extracted with Python's zipfile: for reading SL1 layers and Chromium's
// screenshots back in the tests.
#pragma once

#include "offsetgen_test_support.h"

#include <png.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace offsetgen::slice::test {

struct GreyImage {
  int width = 0, height = 0;
  std::vector<uint8_t> pixels;  // row by row, top row first
  uint8_t at(int col, int row) const { return pixels[size_t(row) * size_t(width) + size_t(col)]; }
};

inline GreyImage read_grey_png(const std::string& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_file(&image, path.c_str()) == 0)
    throw std::runtime_error("cannot read PNG " + path + ": " + image.message);
  image.format = PNG_FORMAT_GRAY;
  GreyImage out;
  out.width = static_cast<int>(image.width);
  out.height = static_cast<int>(image.height);
  out.pixels.resize(PNG_IMAGE_SIZE(image));
  png_color black{0, 0, 0};
  if (png_image_finish_read(&image, &black, out.pixels.data(), 0, nullptr) == 0) {
    png_image_free(&image);
    throw std::runtime_error("cannot decode PNG " + path + ": " + image.message);
  }
  return out;
}

// Writes member `name` of the zip at `archive` to `path`.
inline void extract_zip_member(const std::string& archive, const std::string& name, const std::string& path) {
  const auto r = test_support::run_command(
      {"python3", "-c",
       "import sys, zipfile; open(sys.argv[3], 'wb').write(zipfile.ZipFile(sys.argv[1]).read(sys.argv[2]))", archive,
       name, path});
  if (r.exit_code != 0) throw std::runtime_error("cannot extract " + name + " from " + archive + ": " + r.output);
}

}  // namespace offsetgen::slice::test
