// What every layer format writes through: the part's layout up front, then each layer encoded (on any
// thread: encode_layer is const) and appended in order, then finish() renames the temporary over the
// output (emit/file_writer.h's StreamedFile: a failed or interrupted run leaves nothing).
#pragma once

#include "slice/layer_contours.h"

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace offsetgen::slice {

enum class SliceFormat { CliBinary, CliAscii, Svg, Sl1, Sl1s };

// A resin printer's screen (portrait, x mirrored, as PrusaSlicer's SL1 and SL1S profiles).
struct Screen {
  std::string model;           // "SL1", "SL1S"
  int pixels_x = 2560;         // along the bed's x (the image's rows)
  int pixels_y = 1440;         // along the bed's y (the image's columns)
  double width = 120.96;       // mm, along x
  double height = 68.04;       // mm, along y
  double exposure = 6;         // s
  double first_exposure = 35;  // s
  // The bed's shape: PrusaSlicer centres a part on the bed, not the screen (for SL1 its default bed of
  // 120 x 68 mm, centre (60, 34), on the 120.96 x 68.04 mm screen).
  std::array<double, 2> bed{120, 68};
};
Screen sl1_screen();
Screen sl1s_screen();

struct PartLayout {
  std::string label;             // what the part is, for headers
  std::string job;               // the output's name without its extension (SL1's jobDir)
  std::array<double, 3> size{};  // the part's box: [corner, corner + size], mm (a block's corner is 0)
  std::array<double, 3> corner{};
  size_t layers = 0;
  double layer_height = 0, first_layer = 0;  // mm
};

struct LayerData {
  size_t index = 0;
  double top = 0;    // mm: the layer's top
  double slice = 0;  // mm: where it was cut
  const std::vector<Loop>* loops = nullptr;
  double area = 0;  // mm^2: the loops' signed areas summed in order
};

class LayerWriter {
 public:
  virtual ~LayerWriter() = default;
  virtual std::string encode_layer(const LayerData& layer) const = 0;
  virtual void append_layer(const LayerData& layer, const std::string& encoded) = 0;
  virtual void finish() = 0;         // writes the end and renames the file into place
  virtual size_t bytes() const = 0;  // written so far
};

// An empty path makes an encoder only: encode_layer works, nothing is written (a --layer-range share
// stores the encoded layers in its part file, slicer.h).
std::unique_ptr<LayerWriter> make_cli_writer(const std::string& path, const PartLayout& part, bool ascii);
std::unique_ptr<LayerWriter> make_svg_writer(const std::string& path, const PartLayout& part);
std::unique_ptr<LayerWriter> make_sl1_writer(const std::string& path, const PartLayout& part, const Screen& screen);

}  // namespace offsetgen::slice
