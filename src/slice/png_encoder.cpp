#include "slice/png_encoder.h"

#include <png.h>
#include <zlib.h>

#include <stdexcept>

namespace offsetgen::slice {
namespace {

void write_bytes(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::string*>(png_get_io_ptr(png));
  out->append(reinterpret_cast<const char*>(data), length);
}
void flush_bytes(png_structp) {}

[[noreturn]] void png_failed(png_structp, png_const_charp message) {
  throw std::runtime_error(std::string("PNG encoding failed: ") + message);
}

}  // namespace

std::string encode_grey_png(int width, int height, const std::function<void(int, std::vector<uint8_t>&)>& row) {
  std::string out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, png_failed, nullptr);
  if (!png) throw std::runtime_error("PNG encoding failed: out of memory");
  png_infop info = png_create_info_struct(png);
  try {
    if (!info) throw std::runtime_error("PNG encoding failed: out of memory");
    png_set_write_fn(png, &out, write_bytes, flush_bytes);
    // Runs of equal bytes (the dark screen, the lit inside) are what a layer is made of.
    png_set_compression_level(png, 6);
    png_set_compression_strategy(png, Z_RLE);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
    png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8, PNG_COLOR_TYPE_GRAY,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
    png_write_info(png, info);
    std::vector<uint8_t> line;
    for (int r = 0; r < height; ++r) {
      row(r, line);
      png_write_row(png, line.data());
    }
    png_write_end(png, nullptr);
  } catch (...) {
    png_destroy_write_struct(&png, &info);
    throw;
  }
  png_destroy_write_struct(&png, &info);
  return out;
}

}  // namespace offsetgen::slice
