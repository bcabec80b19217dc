// One SVG file, a group per layer (id "layerK", data-z its cut height in mm), each loop a path with
// fill-rule evenodd, in millimetres with y up (the group flips the SVG's downward y).
#include "emit/file_writer.h"
#include "slice/layer_writer.h"

#include <fmt/format.h>

#include <optional>

namespace offsetgen::slice {
namespace {

class SvgWriter : public LayerWriter {
 public:
  SvgWriter(const std::string& path, const PartLayout& part) {
    if (path.empty()) return;
    file_.emplace(path);
    file_->append(fmt::format(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:.6f}mm\" height=\"{1:.6f}mm\" "
        "viewBox=\"{5:.6f} {2:.6f} {0:.6f} {1:.6f}\">\n"
        "<!-- {3}: {4} layers, mm, y up -->\n",
        part.size[0], part.size[1], -(part.corner[1] + part.size[1]), part.label, part.layers, part.corner[0]));
  }

  std::string encode_layer(const LayerData& layer) const override {
    std::string out =
        fmt::format("<g id=\"layer{}\" data-z=\"{:.6f}\" transform=\"scale(1,-1)\">\n<path fill-rule=\"evenodd\" d=\"",
                    layer.index, layer.slice);
    for (const Loop& loop : *layer.loops) {
      for (size_t k = 0; k < loop.points.size(); ++k)
        out += fmt::format("{}{:.6f} {:.6f}", k == 0 ? "M" : " L", loop.points[k][0], loop.points[k][1]);
      out += " Z ";
    }
    out += "\"/>\n</g>\n";
    return out;
  }
  void append_layer(const LayerData&, const std::string& encoded) override { file_->append(encoded); }
  void finish() override {
    file_->append("</svg>\n");
    file_->commit();
  }
  size_t bytes() const override { return file_ ? file_->size() : 0; }

 private:
  std::optional<StreamedFile> file_;
};

}  // namespace

std::unique_ptr<LayerWriter> make_svg_writer(const std::string& path, const PartLayout& part) {
  return std::make_unique<SvgWriter>(path, part);
}

}  // namespace offsetgen::slice
