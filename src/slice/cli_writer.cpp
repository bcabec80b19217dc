// Common Layer Interface 2.0 (docs/slice.md): an ASCII header, then the layers as binary long records
// (127 layer: float32 z; 130 polyline: int32 id, dir, n, then n float32 pairs, little-endian) or as
// ASCII commands ($$LAYER/z, $$POLYLINE/id,dir,n,x1,y1,...). Units: 1 mm. A closed polyline repeats
// its first point as its last; dir 1 counter-clockwise (an outer boundary), 0 clockwise (a hole), seen
// looking down -z. $$LAYER is the layer's top. A layer's hatches (--hatch, scan_paths.h), if any, follow
// its polylines as one record: binary 132 (hatches long: int32 id, n, then n float32 quadruples
// sx, sy, ex, ey), ASCII $$HATCHES/id,n,sx,sy,ex,ey,...; a layer without hatches has no such record.
#include "emit/file_writer.h"
#include "slice/layer_writer.h"

#include <fmt/format.h>

#include <cstdint>
#include <cstring>
#include <optional>

namespace offsetgen::slice {
namespace {

void put_u16(std::string& out, uint16_t v) {
  out.push_back(static_cast<char>(v & 0xff));
  out.push_back(static_cast<char>(v >> 8));
}
void put_i32(std::string& out, int32_t v) {
  const auto u = static_cast<uint32_t>(v);
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((u >> (8 * k)) & 0xff));
}
void put_f32(std::string& out, double v) {
  const auto f = static_cast<float>(v);
  uint32_t u = 0;
  std::memcpy(&u, &f, 4);
  for (int k = 0; k < 4; ++k) out.push_back(static_cast<char>((u >> (8 * k)) & 0xff));
}

class CliWriter : public LayerWriter {
 public:
  CliWriter(const std::string& path, const PartLayout& part, bool ascii) : ascii_(ascii) {
    if (path.empty()) return;
    file_.emplace(path);
    std::string header = "$$HEADERSTART\n";
    header += ascii ? "$$ASCII\n" : "$$BINARY\n";
    header += "$$UNITS/00000001.000000\n$$VERSION/200\n";
    header += fmt::format("$$LABEL/1,{}\n", part.label);
    header += fmt::format("$$DIMENSION/{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f}\n", part.corner[0], part.corner[1],
                          0.0, part.corner[0] + part.size[0], part.corner[1] + part.size[1], part.size[2]);
    header += fmt::format("$$LAYERS/{}\n", part.layers);
    header += ascii ? "$$HEADEREND\n$$GEOMETRYSTART\n" : "$$HEADEREND";
    file_->append(header);
  }

  std::string encode_layer(const LayerData& layer) const override {
    std::string out;
    if (ascii_) {
      out += fmt::format("$$LAYER/{:.6f}\n", layer.top);
      for (const Loop& loop : *layer.loops) {
        out += fmt::format("$$POLYLINE/1,{},{}", loop.area > 0 ? 1 : 0, loop.points.size() + 1);
        // 7 decimals: 5e-8 mm of rounding.
        for (size_t k = 0; k <= loop.points.size(); ++k) {
          const Point2& p = loop.points[k % loop.points.size()];
          out += fmt::format(",{:.7f},{:.7f}", p[0], p[1]);
        }
        out += '\n';
      }
      if (layer.hatches && !layer.hatches->empty()) {
        out += fmt::format("$$HATCHES/1,{}", layer.hatches->size());
        for (const Hatch& h : *layer.hatches)
          out += fmt::format(",{:.7f},{:.7f},{:.7f},{:.7f}", h.start[0], h.start[1], h.end[0], h.end[1]);
        out += '\n';
      }
      return out;
    }
    put_u16(out, 127);
    put_f32(out, layer.top);
    for (const Loop& loop : *layer.loops) {
      put_u16(out, 130);
      put_i32(out, 1);
      put_i32(out, loop.area > 0 ? 1 : 0);
      put_i32(out, static_cast<int32_t>(loop.points.size() + 1));
      for (size_t k = 0; k <= loop.points.size(); ++k) {
        const Point2& p = loop.points[k % loop.points.size()];
        put_f32(out, p[0]);
        put_f32(out, p[1]);
      }
    }
    if (layer.hatches && !layer.hatches->empty()) {
      put_u16(out, 132);
      put_i32(out, 1);
      put_i32(out, static_cast<int32_t>(layer.hatches->size()));
      for (const Hatch& h : *layer.hatches)
        for (const double v : {h.start[0], h.start[1], h.end[0], h.end[1]}) put_f32(out, v);
    }
    return out;
  }
  void append_layer(const LayerData&, const std::string& encoded) override { file_->append(encoded); }
  void finish() override {
    if (ascii_) file_->append("$$GEOMETRYEND\n");
    file_->commit();
  }
  size_t bytes() const override { return file_ ? file_->size() : 0; }

 private:
  std::optional<StreamedFile> file_;
  bool ascii_;
};

}  // namespace

std::unique_ptr<LayerWriter> make_cli_writer(const std::string& path, const PartLayout& part, bool ascii) {
  return std::make_unique<CliWriter>(path, part, ascii);
}

}  // namespace offsetgen::slice
