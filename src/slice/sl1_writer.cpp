// Prusa SL1 / SL1S archives (docs/slice.md): a zip of config.ini, prusaslicer.ini and one 8-bit grey
// PNG per layer (<job>00000.png ...), as PrusaSlicer writes them, with no creation time stamp. The
// part's box is centred on the bed's centre, or on --center; pixels follow PrusaSlicer's portrait
// layout with x mirrored: the centre of pixel (col, row) lies at bed x = (rows - row - 1/2) p,
// y = (col + 1/2) p. Each pixel is the exact area of the layer's polygons inside it
// (coverage_raster.h), 0 dark, 255 lit.
#include "slice/coverage_raster.h"
#include "slice/layer_writer.h"
#include "slice/png_encoder.h"
#include "slice/zip_stream.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace offsetgen::slice {
namespace {

constexpr int kFadedLayers = 10;
constexpr double kTiltSeconds = 5;  // PrusaSlicer's fast_tilt_time, for the print time estimate

std::string number(double v) { return fmt::format("{:g}", v); }

// Every key PrusaSlicer 2.5 writes into an SLA archive's prusaslicer.ini, sorted; the screen's and the
// layers' values ours, the others its defaults (no supports, no pad, no hollowing).
std::string prusaslicer_ini(const Screen& s, const PartLayout& part) {
  std::map<std::string, std::string> k{
      {"absolute_correction", "0"},
      {"area_fill", "50"},
      {"bed_shape", fmt::format("0x0,{0}x0,{0}x{1},0x{1}", number(s.bed[0]), number(s.bed[1]))},
      {"bottle_cost", "0"},
      {"bottle_volume", "1000"},
      {"bottle_weight", "1"},
      {"display_height", number(s.height)},
      {"display_mirror_x", "1"},
      {"display_mirror_y", "0"},
      {"display_orientation", "portrait"},
      {"display_pixels_x", std::to_string(s.pixels_x)},
      {"display_pixels_y", std::to_string(s.pixels_y)},
      {"display_width", number(s.width)},
      {"elefant_foot_compensation", "0"},
      {"elefant_foot_min_width", "0.2"},
      {"exposure_time", number(s.exposure)},
      {"faded_layers", std::to_string(kFadedLayers)},
      {"fast_tilt_time", number(kTiltSeconds)},
      {"gamma_correction", "1"},
      {"high_viscosity_tilt_time", "10"},
      {"hollowing_closing_distance", "2"},
      {"hollowing_enable", "0"},
      {"hollowing_min_thickness", "3"},
      {"hollowing_quality", "0.5"},
      {"initial_exposure_time", number(s.first_exposure)},
      {"initial_layer_height", number(part.first_layer)},
      {"layer_height", number(part.layer_height)},
      {"material_correction", "1,1,1"},
      {"material_correction_x", "1"},
      {"material_correction_y", "1"},
      {"material_correction_z", "1"},
      {"material_density", "1"},
      {"material_print_speed", "fast"},
      {"max_exposure_time", "100"},
      {"max_initial_exposure_time", "150"},
      {"max_print_height", "200"},
      {"min_exposure_time", "0"},
      {"min_initial_exposure_time", "0"},
      {"output_filename_format", "[input_filename_base]." + std::string(s.model == "SL1S" ? "sl1s" : "sl1")},
      {"pad_around_object", "0"},
      {"pad_around_object_everywhere", "0"},
      {"pad_brim_size", "1.6"},
      {"pad_enable", "0"},
      {"pad_max_merge_distance", "50"},
      {"pad_object_connector_penetration", "0.3"},
      {"pad_object_connector_stride", "10"},
      {"pad_object_connector_width", "0.5"},
      {"pad_object_gap", "1"},
      {"pad_wall_height", "0"},
      {"pad_wall_slope", "90"},
      {"pad_wall_thickness", "2"},
      {"physical_printer_settings_id", ""},
      {"printer_model", s.model},
      {"printer_settings_id", ""},
      {"printer_technology", "SLA"},
      {"relative_correction", "1,1"},
      {"relative_correction_x", "1"},
      {"relative_correction_y", "1"},
      {"relative_correction_z", "1"},
      {"sla_material_settings_id", ""},
      {"sla_print_settings_id", ""},
      {"slice_closing_radius", "0"},
      {"slicing_mode", "regular"},
      {"slow_tilt_time", "8"},
      {"support_base_diameter", "4"},
      {"support_base_height", "1"},
      {"support_base_safety_distance", "1"},
      {"support_buildplate_only", "0"},
      {"support_critical_angle", "45"},
      {"support_head_front_diameter", "0.4"},
      {"support_head_penetration", "0.2"},
      {"support_head_width", "1"},
      {"support_max_bridge_length", "15"},
      {"support_max_bridges_on_pillar", "3"},
      {"support_max_pillar_link_distance", "10"},
      {"support_object_elevation", "5"},
      {"support_pillar_connection_mode", "dynamic"},
      {"support_pillar_diameter", "1"},
      {"support_pillar_widening_factor", "0"},
      {"support_points_density_relative", "100"},
      {"support_points_minimal_distance", "1"},
      {"support_small_pillar_diameter_percent", "50%"},
      {"supports_enable", "0"},
  };
  std::string out;
  for (const auto& [key, value] : k) out += key + " = " + value + "\n";
  return out;
}

class Sl1Writer : public LayerWriter {
 public:
  Sl1Writer(const std::string& path, const PartLayout& part, const Screen& screen) : part_(part), screen_(screen) {
    p_x_ = screen.width / screen.pixels_x;
    p_y_ = screen.height / screen.pixels_y;
    shift_ = part_shift(screen, part);
    // The part's box in pixels (columns along y, rows along x), one pixel of margin.
    col_lo_ = std::max(0, static_cast<int>(std::floor(shift_[1] / p_y_)) - 1);
    col_hi_ = std::min(screen.pixels_y, static_cast<int>(std::ceil((shift_[1] + part.size[1]) / p_y_)) + 1);
    row_lo_ = std::max(0, static_cast<int>(std::floor(screen.pixels_x - (shift_[0] + part.size[0]) / p_x_)) - 1);
    row_hi_ = std::min(screen.pixels_x, static_cast<int>(std::ceil(screen.pixels_x - shift_[0] / p_x_)) + 1);
    if (path.empty()) return;
    zip_.emplace(path);
    config_ = zip_->add("config.ini", config_ini(0, 0));
    zip_->add("prusaslicer.ini", prusaslicer_ini(screen, part));
  }

  std::string encode_layer(const LayerData& layer) const override {
    CoverageRaster raster(col_hi_ - col_lo_, row_hi_ - row_lo_);
    for (const Loop& loop : *layer.loops)
      for (size_t k = 0; k < loop.points.size(); ++k)
        raster.add_edge(image(loop.points[k]), image(loop.points[(k + 1) % loop.points.size()]));
    // Counter-clockwise in (x, y) stays counter-clockwise in (column, row) (a rotation), where the
    // running sum of an outer loop's inside is negative.
    return encode_grey_png(screen_.pixels_y, screen_.pixels_x, [&](int r, std::vector<uint8_t>& out) {
      out.assign(static_cast<size_t>(screen_.pixels_y), 0);
      if (r < row_lo_ || r >= row_hi_) return;
      raster.row(r - row_lo_, -1.0, line_);
      std::copy(line_.begin(), line_.end(), out.begin() + col_lo_);
    });
  }

  void append_layer(const LayerData& layer, const std::string& encoded) override {
    used_ml_ += layer.area * (layer.index == 0 ? part_.first_layer : part_.layer_height) / 1000;
    zip_->add(fmt::format("{}{:05d}.png", part_.job, layer.index), encoded);
  }

  void finish() override {
    zip_->replace(config_, config_ini(used_ml_, print_seconds()));
    zip_->finish();
  }
  size_t bytes() const override { return zip_ ? zip_->bytes() : 0; }

 private:
  // Image coordinates (column, row) of a point of the part, mm, in the raster of the part's box.
  std::array<double, 2> image(const Point2& p) const {
    const double bx = p[0] - part_.corner[0] + shift_[0], by = p[1] - part_.corner[1] + shift_[1];
    return {by / p_y_ - col_lo_, screen_.pixels_x - bx / p_x_ - row_lo_};
  }
  double print_seconds() const {
    double t = 0;
    for (size_t k = 0; k < part_.layers; ++k) {
      const double fade = std::min(1.0, double(k) / kFadedLayers);
      t += (1 - fade) * screen_.first_exposure + fade * screen_.exposure + kTiltSeconds;
    }
    return t;
  }
  // Totals at a fixed width, so that the entry can be rewritten in place at the end.
  std::string config_ini(double used_ml, double seconds) const {
    std::string s;
    s += "action = print\n";
    s += fmt::format("expTime = {:g}\n", screen_.exposure);
    s += fmt::format("expTimeFirst = {:g}\n", screen_.first_exposure);
    s += "expUserProfile = 0\n";
    s += "hollow = 0\n";
    s += fmt::format("jobDir = {}\n", part_.job);
    s += fmt::format("layerHeight = {:g}\n", part_.layer_height);
    s += "materialName = \n";
    s += fmt::format("numFade = {}\n", kFadedLayers);
    s += fmt::format("numFast = {}\n", part_.layers);
    s += "numSlow = 0\n";
    s += "printProfile = \n";
    s += fmt::format("printTime = {:015.6f}\n", seconds);
    s += fmt::format("printerModel = {}\n", screen_.model);
    s += "printerProfile = \n";
    s += "printerVariant = default\n";
    s += fmt::format("prusaSlicerVersion = offsetgen-{}\n", OFFSETGEN_VERSION);
    s += fmt::format("usedMaterial = {:015.6f}\n", used_ml);
    return s;
  }

  std::optional<ZipStream> zip_;
  PartLayout part_;
  Screen screen_;
  double p_x_ = 0, p_y_ = 0;
  std::array<double, 2> shift_{};
  int col_lo_ = 0, col_hi_ = 0, row_lo_ = 0, row_hi_ = 0;
  size_t config_ = 0;
  double used_ml_ = 0;
  static thread_local std::vector<uint8_t> line_;
};

thread_local std::vector<uint8_t> Sl1Writer::line_;

}  // namespace

std::array<double, 2> part_shift(const Screen& screen, const PartLayout& part) {
  if (part.size[0] > screen.width || part.size[1] > screen.height)
    throw InputError(fmt::format("the part ({:g} x {:g} mm) is larger than the {} screen ({:g} x {:g} mm)",
                                 part.size[0], part.size[1], screen.model, screen.width, screen.height));
  // The part's box centred on the bed's centre, as PrusaSlicer places it, or on --center.
  const std::array<double, 2> c = part.center.value_or(std::array<double, 2>{0.5 * screen.bed[0], 0.5 * screen.bed[1]});
  const std::array<double, 2> shift{c[0] - 0.5 * part.size[0], c[1] - 0.5 * part.size[1]};
  if (!(shift[0] >= 0 && shift[1] >= 0 && shift[0] + part.size[0] <= screen.width &&
        shift[1] + part.size[1] <= screen.height)) {
    if (!part.center)
      throw InputError(
          fmt::format("the part ({:g} x {:g} mm) centred on the bed does not fit the {} screen ({:g} x {:g} mm)",
                      part.size[0], part.size[1], screen.model, screen.width, screen.height));
    throw InputError(fmt::format(
        "--center {:g},{:g}: the part ({:g} x {:g} mm) would cover x {:g} to {:g}, y {:g} to {:g} mm, off the {} "
        "screen (x 0 to {:g}, y 0 to {:g} mm): its centre must lie within x {:g} to {:g}, y {:g} to {:g} mm",
        c[0], c[1], part.size[0], part.size[1], shift[0], shift[0] + part.size[0], shift[1], shift[1] + part.size[1],
        screen.model, screen.width, screen.height, 0.5 * part.size[0], screen.width - 0.5 * part.size[0],
        0.5 * part.size[1], screen.height - 0.5 * part.size[1]));
  }
  return shift;
}

Screen sl1_screen() { return Screen{"SL1", 2560, 1440, 120.96, 68.04, 10, 15, {120, 68}}; }
Screen sl1s_screen() { return Screen{"SL1S", 2560, 1620, 128, 81, 10, 15, {128, 81}}; }

std::unique_ptr<LayerWriter> make_sl1_writer(const std::string& path, const PartLayout& part, const Screen& screen) {
  return std::make_unique<Sl1Writer>(path, part, screen);
}

}  // namespace offsetgen::slice
