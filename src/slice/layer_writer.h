// What every layer format writes through: the part's layout up front, then each layer encoded (on any
// thread: encode_layer is const) and appended in order, then finish() renames the temporary over the
// output (emit/file_writer.h's StreamedFile: a failed or interrupted run leaves nothing).
#pragma once

#include "slice/layer_contours.h"
#include "slice/scan_paths.h"

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace offsetgen::slice {

// SvgLayers: a directory of SVGs, one per layer (-o DIR/).
enum class SliceFormat { CliBinary, CliAscii, Svg, Sl1, Sl1s, SvgLayers };

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
  // SL1/SL1S: where the box's centre sits on the bed (bed mm, --center); none: the bed's centre.
  std::optional<std::array<double, 2>> center;
};
// Where the part's box starts on the bed (mm, its lower corner): centred on `center` or else on the
// bed's centre. Throws InputError when the box then leaves the screen.
std::array<double, 2> part_shift(const Screen& screen, const PartLayout& part);

struct LayerData {
  size_t index = 0;
  double top = 0;    // mm: the layer's top
  double slice = 0;  // mm: where it was cut
  const std::vector<Loop>* loops = nullptr;
  double area = 0;                              // mm^2: the loops' signed areas summed in order
  const std::vector<Hatch>* hatches = nullptr;  // CLI: written after the loops (scan_paths.h)
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
// -o DIR/: one SVG per layer, DIR/layer_00000.svg ... (at least 5 digits, more when the layers need
// them), each a whole SVG with the single file's group of that layer. Written into a new hidden
// directory beside DIR and renamed to DIR by finish() (DIR must be missing or empty); a failed or
// interrupted run removes it. The layer encoding is the single SVG's (its --layer-range parts merge
// into either).
std::unique_ptr<LayerWriter> make_svg_layers_writer(const std::string& path, const PartLayout& part);
// Throws InputError unless `path` can become the directory of per-layer SVGs: missing with an
// existing parent directory, or an empty directory (never a file or a directory holding anything).
void require_layer_directory(const std::string& path);
// -o names a directory: it ends with '/' or is an existing directory.
bool is_layer_directory(const std::string& path);
std::unique_ptr<LayerWriter> make_sl1_writer(const std::string& path, const PartLayout& part, const Screen& screen);

}  // namespace offsetgen::slice
