// A reader of CLI files written for the tests, apart from the writer (slice/cli_writer.cpp): the ASCII
// header up to $$HEADEREND, then binary long records (127 layer, 130 polyline; anything else is an
// error; 132 hatches long: int32 id, n, 4n float32, after SLICE.md, not 131 as one public reader has
// it) or ASCII commands ($$LAYER, $$POLYLINE, $$HATCHES). Coordinates times $$UNITS, in mm.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

namespace offsetgen::slice::test {

struct Polyline {
  int id = 0, dir = 0;
  std::vector<std::array<double, 2>> points;  // mm, as in the file (closed: last = first)
};
struct HatchLine {
  std::array<double, 2> start, end;  // mm
};
struct CliLayer {
  double z = 0;
  std::vector<Polyline> polylines;
  std::vector<HatchLine> hatches;  // every hatches record of the layer, in order
  size_t hatch_records = 0;
};
struct CliFile {
  bool binary = false;
  double units = 0;
  long header_layers = -1;
  std::vector<CliLayer> layers;
  bool ended = false;  // ASCII: $$GEOMETRYEND seen
};

// The header's commands, one per line, up to $$HEADEREND; the geometry after it.
inline CliFile read_cli(const std::string& bytes) {
  CliFile f;
  const std::string end = "$$HEADEREND";
  const size_t he = bytes.find(end);
  if (bytes.rfind("$$HEADERSTART", 0) != 0 || he == std::string::npos) throw std::runtime_error("no CLI header");
  std::stringstream header(bytes.substr(0, he));
  std::string line;
  while (std::getline(header, line)) {
    if (line == "$$BINARY") f.binary = true;
    if (line.rfind("$$UNITS/", 0) == 0) f.units = std::stod(line.substr(8));
    if (line.rfind("$$LAYERS/", 0) == 0) f.header_layers = std::stol(line.substr(9));
  }
  size_t at = he + end.size();
  if (f.binary) {
    auto need = [&](size_t n) {
      if (at + n > bytes.size()) throw std::runtime_error("a record runs past the end");
    };
    auto u16 = [&] {
      need(2);
      const auto v = static_cast<uint16_t>(uint8_t(bytes[at]) | uint8_t(bytes[at + 1]) << 8);
      at += 2;
      return v;
    };
    auto i32 = [&] {
      need(4);
      uint32_t v = 0;
      for (int k = 3; k >= 0; --k) v = v << 8 | uint8_t(bytes[at + size_t(k)]);
      at += 4;
      return static_cast<int32_t>(v);
    };
    auto f32 = [&] {
      const auto bits = static_cast<uint32_t>(i32());
      float v = 0;
      std::memcpy(&v, &bits, 4);
      return double(v);
    };
    while (at < bytes.size()) {
      const uint16_t command = u16();
      if (command == 127) {
        f.layers.emplace_back();
        f.layers.back().z = f32() * f.units;
      } else if (command == 130) {
        if (f.layers.empty()) throw std::runtime_error("a polyline before the first layer");
        Polyline p;
        p.id = i32();
        p.dir = i32();
        const int32_t n = i32();
        for (int32_t k = 0; k < n; ++k) {
          const double x = f32() * f.units;
          const double y = f32() * f.units;
          p.points.push_back({x, y});
        }
        f.layers.back().polylines.push_back(p);
      } else if (command == 132) {
        if (f.layers.empty()) throw std::runtime_error("hatches before the first layer");
        i32();  // id
        const int32_t n = i32();
        if (n <= 0) throw std::runtime_error("an empty hatches record");
        for (int32_t k = 0; k < n; ++k) {
          HatchLine h;
          h.start[0] = f32() * f.units;
          h.start[1] = f32() * f.units;
          h.end[0] = f32() * f.units;
          h.end[1] = f32() * f.units;
          f.layers.back().hatches.push_back(h);
        }
        ++f.layers.back().hatch_records;
      } else {
        throw std::runtime_error(fmt::format("unexpected binary record {}", command));
      }
    }
    return f;
  }
  std::stringstream geometry(bytes.substr(at));
  while (std::getline(geometry, line)) {
    if (line.empty() || line == "$$GEOMETRYSTART") continue;
    if (line == "$$GEOMETRYEND") {
      f.ended = true;
      continue;
    }
    if (line.rfind("$$LAYER/", 0) == 0) {
      f.layers.emplace_back();
      f.layers.back().z = std::stod(line.substr(8)) * f.units;
    } else if (line.rfind("$$POLYLINE/", 0) == 0) {
      std::vector<double> v;
      std::stringstream in(line.substr(11));
      std::string item;
      while (std::getline(in, item, ',')) v.push_back(std::stod(item));
      Polyline p;
      p.id = int(v.at(0));
      p.dir = int(v.at(1));
      const auto n = static_cast<size_t>(v.at(2));
      if (v.size() != 3 + 2 * n) throw std::runtime_error("$$POLYLINE: n does not match its coordinates");
      for (size_t k = 0; k < n; ++k) p.points.push_back({v[3 + 2 * k] * f.units, v[4 + 2 * k] * f.units});
      if (f.layers.empty()) throw std::runtime_error("a polyline before the first layer");
      f.layers.back().polylines.push_back(p);
    } else if (line.rfind("$$HATCHES/", 0) == 0) {
      std::vector<double> v;
      std::stringstream in(line.substr(10));
      std::string item;
      while (std::getline(in, item, ',')) v.push_back(std::stod(item));
      const auto n = static_cast<size_t>(v.at(1));
      if (n == 0 || v.size() != 2 + 4 * n) throw std::runtime_error("$$HATCHES: n does not match its coordinates");
      if (f.layers.empty()) throw std::runtime_error("hatches before the first layer");
      for (size_t k = 0; k < n; ++k) {
        const double* q = &v[2 + 4 * k];
        f.layers.back().hatches.push_back({{q[0] * f.units, q[1] * f.units}, {q[2] * f.units, q[3] * f.units}});
      }
      ++f.layers.back().hatch_records;
    } else {
      throw std::runtime_error("unexpected line: " + line.substr(0, 40));
    }
  }
  return f;
}

inline double signed_area(const std::vector<std::array<double, 2>>& p) {
  double a = 0;
  for (size_t k = 0; k + 1 < p.size(); ++k) a += p[k][0] * p[k + 1][1] - p[k + 1][0] * p[k][1];
  return 0.5 * a;
}

}  // namespace offsetgen::slice::test
