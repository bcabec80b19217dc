#include "png_io.h"

#include <png.h>

#include <stdexcept>

namespace offsetgen::png {

// libpng's "simplified API" (png_image, libpng >= 1.6) needs no setjmp error handling.

void write_rgba(const std::string& path, const Image& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() !=
          static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4) {
    throw std::runtime_error("write_rgba: image size does not match its pixel buffer");
  }
  png_image info{};
  info.version = PNG_IMAGE_VERSION;
  info.width = static_cast<png_uint_32>(image.width);
  info.height = static_cast<png_uint_32>(image.height);
  info.format = PNG_FORMAT_RGBA;
  if (png_image_write_to_file(&info, path.c_str(), 0, image.rgba.data(), 0, nullptr) == 0) {
    throw std::runtime_error("cannot write PNG " + path + ": " + info.message);
  }
}

Image read_rgba(const std::string& path) {
  png_image info{};
  info.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_file(&info, path.c_str()) == 0) {
    throw std::runtime_error("cannot read PNG " + path + ": " + info.message);
  }
  info.format = PNG_FORMAT_RGBA;
  Image image;
  image.width = static_cast<int>(info.width);
  image.height = static_cast<int>(info.height);
  image.rgba.resize(PNG_IMAGE_SIZE(info));
  if (png_image_finish_read(&info, nullptr, image.rgba.data(), 0, nullptr) == 0) {
    png_image_free(&info);
    throw std::runtime_error("cannot decode PNG " + path + ": " + info.message);
  }
  return image;
}

}  // namespace offsetgen::png
