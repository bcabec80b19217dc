#include "slice/slicer.h"

#include "emit/file_writer.h"
#include "support/stopwatch.h"
#include "surfaces/input_error.h"
#include "validate/block_checks.h"
#include "validate/share_range.h"
#include "validate/wall_choice.h"
#include "wall/parallel_blocks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <tuple>

namespace offsetgen::slice {
namespace {

// The marching grid: the thinnest wall spans this many pixels, so every row and column of pixels that
// crosses a wall holds a sample inside it (a wall cut by a layer is at least its thickness wide).
constexpr double kPixelsPerWall = 3;

std::string extension_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// A --layer-range share's part file: this first line, "share I N", the lines every share of the request
// has alike (the key), "end"; then each layer as "layer K TOP SLICE AREA BYTES" (the numbers hexadecimal
// floats, exact) and its BYTES encoded bytes, as the whole run's writer encodes it.
constexpr const char* kPartMagic = "offsetgen slice part 1";
constexpr const char* kPartSuffix = ".part";

bool is_part_name(const std::string& path) {
  std::string tail = path.size() >= 5 ? path.substr(path.size() - 5) : path;
  std::transform(tail.begin(), tail.end(), tail.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return tail == kPartSuffix;
}

// The file whose format a request writes: a share's NAME.EXT.part writes EXT's layers.
std::string format_name_of(const SliceRequest& r) {
  return !r.layer_range.empty() && is_part_name(r.output) ? r.output.substr(0, r.output.size() - 5) : r.output;
}

double first_layer_of(const SliceRequest& r) { return r.first_layer ? *r.first_layer : r.layer_height; }

// Layer k's cut and top, mm.
double cut_height(const SliceRequest& r, size_t k) {
  const double f = first_layer_of(r);
  return k == 0 ? 0.5 * f : f + (double(k) - 0.5) * r.layer_height;
}
double top_height(const SliceRequest& r, size_t k) { return first_layer_of(r) + double(k) * r.layer_height; }

size_t layer_count(const SliceRequest& r) {
  const double height = r.cells[2] * r.cell_size;
  size_t n = 0;
  while (cut_height(r, n) < height) ++n;
  return n;
}

std::optional<Screen> screen_of(SliceFormat f) {
  if (f == SliceFormat::Sl1) return sl1_screen();
  if (f == SliceFormat::Sl1s) return sl1s_screen();
  return std::nullopt;
}

std::string format_name(SliceFormat f) {
  switch (f) {
    case SliceFormat::CliBinary:
      return "CLI, binary";
    case SliceFormat::CliAscii:
      return "CLI, ASCII";
    case SliceFormat::Svg:
      return "SVG";
    case SliceFormat::Sl1:
      return "Prusa SL1";
    case SliceFormat::Sl1s:
      return "Prusa SL1S";
  }
  return "?";
}

size_t peak_memory() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return static_cast<size_t>(std::stoull(line.substr(6))) * 1024;
  return 0;
}

std::unique_ptr<LayerWriter> make_writer(SliceFormat f, const std::string& path, const PartLayout& part) {
  if (const auto screen = screen_of(f)) return make_sl1_writer(path, part, *screen);
  if (f == SliceFormat::Svg) return make_svg_writer(path, part);
  return make_cli_writer(path, part, f == SliceFormat::CliAscii);
}

// What makes two shares parts of one run: the format, the part's layout and everything that shapes
// its contours.
std::string part_key(SliceFormat f, const PartLayout& part, const SliceRequest& r, int pixels_per_cell) {
  const GenerationRequest& g = r.wall.generation;
  std::string params;
  for (const auto& [k, v] : g.params) params += k + "=" + v + ";";
  return fmt::format(
      "format {}\nlabel {}\nsize {:a} {:a} {:a}\nlayers {}\nheights {:a} {:a}\ntolerance {:a}\npixels {}\n"
      "surface {}\nexpression {}\nparams {}\nmethod {} {}\nthickness {}|{}\ndensity {}|{}\nnetwork {}\n",
      static_cast<int>(f), part.label, part.size[0], part.size[1], part.size[2], part.layers, part.layer_height,
      part.first_layer, r.tolerance, pixels_per_cell, g.surface, g.expression, params, g.method, g.order,
      r.wall.thickness, g.thickness.value_or(""), g.density ? fmt::format("{:a}", *g.density) : "",
      g.density_field.value_or(""), r.wall.network ? 1 : 0);
}

std::string wall_text(const wall::WallRequest& w) {
  const GenerationRequest& g = w.generation;
  if (w.network) return g.density ? fmt::format("network rho={}", *g.density) : "network h=" + w.thickness;
  if (g.density) return fmt::format("rho={}", *g.density);
  if (g.density_field) return "rho=" + *g.density_field;
  return "t=" + w.thickness;
}

}  // namespace

SliceFormat format_for_output(const SliceRequest& r) {
  const std::string ext = extension_of(format_name_of(r));
  SliceFormat f;
  if (ext == ".cli")
    f = r.cli_ascii ? SliceFormat::CliAscii : SliceFormat::CliBinary;
  else if (ext == ".svg")
    f = SliceFormat::Svg;
  else if (ext == ".sl1")
    f = SliceFormat::Sl1;
  else if (ext == ".sl1s")
    f = SliceFormat::Sl1s;
  else
    throw InputError(
        fmt::format("-o '{}': unknown extension '{}'; slice writes .cli (CLI), .svg, .sl1 or .sl1s", r.output, ext));
  if (r.cli_ascii && ext != ".cli")
    throw InputError(fmt::format("--cli-ascii writes CLI: -o '{}' is not .cli", r.output));
  if (!r.printer.empty()) {
    if (r.printer != "sl1" && r.printer != "sl1s")
      throw InputError(fmt::format("--printer '{}': the printers are sl1 and sl1s", r.printer));
    if (f != SliceFormat::Sl1 && f != SliceFormat::Sl1s)
      throw InputError(
          fmt::format("--printer {} sets a resin printer's screen: -o '{}' is not .sl1 or .sl1s", r.printer, r.output));
    if ((r.printer == "sl1") != (f == SliceFormat::Sl1))
      throw InputError(fmt::format("--printer {} writes .{}: -o '{}' has the other printer's extension", r.printer,
                                   r.printer, r.output));
  }
  return f;
}

void validate(const SliceRequest& r) {
  check_wall_choice(!r.wall.thickness.empty(), r.wall.generation.density.has_value(),
                    r.wall.generation.density_field.has_value(), WallNeed::Required);
  check_block(r.cells, r.cell_size);
  if (!positive_length(r.layer_height))
    throw InputError(fmt::format("--layer-height {} is not a positive length (mm)", r.layer_height));
  if (r.layer_height > r.cell_size)
    throw InputError(fmt::format("--layer-height {:g} mm is above a cell ({:g} mm): a layer would skip walls",
                                 r.layer_height, r.cell_size));
  if (r.first_layer && !positive_length(*r.first_layer))
    throw InputError(fmt::format("--first-layer {} is not a positive length (mm)", *r.first_layer));
  if (r.first_layer && *r.first_layer > r.cell_size)
    throw InputError(fmt::format("--first-layer {:g} mm is above a cell ({:g} mm)", *r.first_layer, r.cell_size));
  if (!positive_length(r.tolerance))
    throw InputError(fmt::format("--tolerance {} is not a positive length (mm)", r.tolerance));
  if (r.pixels_per_cell < 0) throw InputError("the marching grid's pixels per cell must be positive");
  if (r.output.empty()) throw InputError("no output file: use -o part.cli (or .svg, .sl1, .sl1s)");
  if (!r.layer_range.empty()) {
    parse_layer_range(r.layer_range);
    if (!is_part_name(r.output))
      throw InputError(fmt::format(
          "--layer-range {} writes a share for --merge: -o '{}' must be NAME.EXT.part, EXT the merged file's "
          "format (.cli, .svg, .sl1 or .sl1s), e.g. -o share0.cli.part",
          r.layer_range, r.output));
  }
  const SliceFormat f = format_for_output(r);
  if (const auto screen = screen_of(f)) {
    const double x = r.cells[0] * r.cell_size, y = r.cells[1] * r.cell_size;
    if (x > std::min(screen->width, screen->bed[0]) || y > std::min(screen->height, screen->bed[1]))
      throw InputError(fmt::format(
          "the part ({:g} x {:g} mm) is larger than the {} screen ({:g} x {:g} mm): use fewer --cells or a smaller "
          "--cell-size",
          x, y, screen->model, screen->width, screen->height));
  }
  if (layer_count(r) > 0xfff0 && screen_of(f))
    throw InputError(fmt::format("{} layers: an SL1 archive holds at most 65520", layer_count(r)));
  try {
    require_writable(r.output);
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }
}

SliceSummary run_slice(const SliceRequest& r, const SliceProgress& progress) {
  const auto start = std::chrono::steady_clock::now();
  validate(r);
  const SliceFormat format = format_for_output(r);
  auto report = [&](const std::string& stage, double f) {
    if (progress) progress(stage, f);
  };
  SliceSummary m;
  m.output = r.output;
  m.format = format_name(format);
  m.cells = r.cells;
  m.cell_size = r.cell_size;
  m.layer_height = r.layer_height;
  m.first_layer = first_layer_of(r);
  m.tolerance = r.tolerance;
  m.wall = wall_text(r.wall);

  report("generating the functions", -1);
  wall::WallField field(r.wall);
  m.surface = field.generation().surface.name;
  m.generate_seconds = field.generate_seconds();
  const auto range = field.thickness_range(r.cells);
  const wall::WallExtent extent = field.extent(range);
  m.pixels_per_cell = r.pixels_per_cell > 0
                          ? r.pixels_per_cell
                          : std::max(16, static_cast<int>(std::ceil(kPixelsPerWall / extent.thinnest - 1e-9)));
  if (double(m.pixels_per_cell) * std::max(r.cells[0], r.cells[1]) > 65536)
    throw InputError(
        fmt::format("{} pixels per cell over {} cells: the layer grid is too large (walls too thin for "
                    "the block)",
                    m.pixels_per_cell, std::max(r.cells[0], r.cells[1])));
  report("compiling the functions", -1);
  field.compile();
  m.compile_seconds = field.compile_seconds();

  const int threads = r.threads > 0 ? r.threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const std::optional<Screen> screen = screen_of(format);
  PartLayout part;
  part.label = fmt::format("offsetgen {} {} {}x{}x{} cells of {:g} mm", m.surface, m.wall, r.cells[0], r.cells[1],
                           r.cells[2], r.cell_size);
  part.job = std::filesystem::path(r.output).stem().string();
  part.size = {r.cells[0] * r.cell_size, r.cells[1] * r.cell_size, r.cells[2] * r.cell_size};
  part.layers = layer_count(r);
  part.layer_height = r.layer_height;
  part.first_layer = m.first_layer;
  // A share writes its layers, encoded by the format's writer, to a part file (kPartMagic).
  size_t begin = 0, end = part.layers;
  std::optional<StreamedFile> part_file;
  if (!r.layer_range.empty()) {
    const auto [index, count] = parse_layer_range(r.layer_range);
    std::tie(begin, end) = layer_share(part.layers, index, count);
    m.share = begin < end ? fmt::format("{}/{}: layers {} to {} of {}", index, count, begin, end - 1, part.layers)
                          : fmt::format("{}/{}: none of the {} layers", index, count, part.layers);
    m.format = format_name(format) + " layers, a share for --merge";
    part_file.emplace(r.output);
    part_file->append(fmt::format("{}\nshare {} {}\n{}end\n", kPartMagic, index, count,
                                  part_key(format, part, r, m.pixels_per_cell)));
  }
  m.layers = end - begin;
  std::unique_ptr<LayerWriter> writer = make_writer(format, part_file ? std::string() : r.output, part);

  LayerSetup setup;
  setup.cells = {r.cells[0], r.cells[1]};
  setup.cell_size = r.cell_size;
  setup.pixels_per_cell = m.pixels_per_cell;
  setup.tolerance = r.tolerance;
  // Loops with less area than a pixel (the screen's, or the marching grid's) are dropped and counted.
  const double pixel = screen ? screen->width / screen->pixels_x : r.cell_size / m.pixels_per_cell;
  setup.tiny_area = pixel * pixel;
  m.tiny_area = setup.tiny_area;
  setup.reach = extent.reach;
  // M bounds |grad F| over the unit cell; catalog surfaces repeat it, user expressions need not.
  setup.use_field_bound = field.generation().surface.from_catalog || r.cells == std::array<int, 3>{1, 1, 1};
  setup.threads = 1;

  // Layers in chunks, a layer per thread at a time, written in order.
  const size_t chunk = static_cast<size_t>(std::max(1, threads)) * 4;
  for (size_t first = begin; first < end; first += chunk) {
    const size_t count = std::min(chunk, end - first);
    std::vector<LayerContours> contours(count);
    std::vector<std::string> encoded(count);
    wall::for_each_block(
        count, threads,
        [&](double f) { report("slicing", (double(first - begin) + f * double(count)) / double(end - begin)); },
        [] { return 0; },
        [&](int&, size_t i) {
          const size_t k = first + i;
          LayerSetup s = setup;
          s.z = cut_height(r, k) / r.cell_size;
          contours[i] = layer_contours(field, s);
          encoded[i] = writer->encode_layer({k, top_height(r, k), cut_height(r, k), &contours[i].loops});
        });
    for (size_t i = 0; i < count; ++i) {
      const size_t k = first + i;
      const LayerContours& c = contours[i];
      double area = 0;
      for (const Loop& loop : c.loops) area += loop.area;
      const LayerData layer{k, top_height(r, k), cut_height(r, k), &c.loops, area};
      if (part_file) {
        part_file->append(
            fmt::format("layer {} {:a} {:a} {:a} {}\n", k, layer.top, layer.slice, layer.area, encoded[i].size()));
        part_file->append(encoded[i]);
      } else {
        writer->append_layer(layer, encoded[i]);
      }
      m.loops += c.loops.size();
      m.vertices += c.vertices;
      m.tiny_loops += c.tiny_loops;
      m.unverified_chords += c.unverified_chords;
      m.max_deviation = std::max(m.max_deviation, c.max_deviation);
      m.samples += c.samples;
      m.refine_evaluations += c.refine_evaluations;
    }
  }
  report("writing " + r.output, -1);
  if (part_file) {
    m.file_bytes = part_file->size();
    part_file->commit();
  } else {
    writer->finish();
    m.file_bytes = writer->bytes();
  }
  m.slice_seconds = seconds_since(start) - m.generate_seconds - m.compile_seconds;
  m.peak_memory_bytes = peak_memory();
  return m;
}

std::string format_summary(const SliceSummary& m) {
  std::string s;
  s += fmt::format("offsetgen slice: {} written ({}, {:.1f} MB)\n", m.output, m.format, double(m.file_bytes) / 1e6);
  if (!m.share.empty()) s += fmt::format("  share:      {} (join the shares with --merge)\n", m.share);
  s += fmt::format("  block:      {} {} {}x{}x{} cells of {:g} mm\n", m.surface, m.wall, m.cells[0], m.cells[1],
                   m.cells[2], m.cell_size);
  s += fmt::format("  layers:     {} of {:g} mm (first {:g} mm), cut at mid-height\n", m.layers, m.layer_height,
                   m.first_layer);
  s += fmt::format("  contours:   {} loops, {} vertices; {} loops under {:.3g} mm^2 dropped\n", m.loops, m.vertices,
                   m.tiny_loops, m.tiny_area);
  s += fmt::format(
      "  accuracy:   vertices on the wall's zero set; largest chord deviation measured {:.4g} mm "
      "(--tolerance {:g} mm){}\n",
      m.max_deviation, m.tolerance,
      m.unverified_chords ? fmt::format(", {} chords not measured", m.unverified_chords) : std::string());
  s += fmt::format("  evaluation: {} pixels per cell, {} samples, {} refinement evaluations\n", m.pixels_per_cell,
                   m.samples, m.refine_evaluations);
  s += fmt::format(
      "  time:       {:.2f} s (generate {:.2f} s, compile {:.2f} s, slice {:.2f} s); peak memory {:.0f} MB\n",
      m.generate_seconds + m.compile_seconds + m.slice_seconds, m.generate_seconds, m.compile_seconds, m.slice_seconds,
      double(m.peak_memory_bytes) / 1e6);
  return s;
}

std::pair<int, int> parse_layer_range(const std::string& text) { return parse_share(text, "--layer-range"); }

std::pair<size_t, size_t> layer_share(size_t layers, int index, int count) { return share_of(layers, index, count); }

namespace {

struct PartHead {
  int index = -1, count = 0;
  std::string key;
  std::streamoff records = 0;  // where the layers start
};

PartHead read_part_head(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("--merge: cannot read '{}'", path));
  const auto not_a_part = [&] {
    return InputError(fmt::format("--merge: '{}' is not a share written by offsetgen slice --layer-range", path));
  };
  std::string line;
  if (!std::getline(in, line) || line != kPartMagic) throw not_a_part();
  PartHead h;
  if (!std::getline(in, line) || std::sscanf(line.c_str(), "share %d %d", &h.index, &h.count) != 2 || h.count < 1 ||
      h.index < 0 || h.index >= h.count)
    throw not_a_part();
  while (std::getline(in, line) && line != "end") h.key += line + "\n";
  if (!in) throw not_a_part();
  h.records = in.tellg();
  return h;
}

// A line "NAME VALUE" of a part's key.
std::string key_value(const std::string& key, const std::string& name) {
  std::istringstream lines(key);
  std::string line;
  while (std::getline(lines, line))
    if (line.rfind(name + " ", 0) == 0) return line.substr(name.size() + 1);
  throw InputError(fmt::format("--merge: the parts have no '{}' line", name));
}

}  // namespace

LayerMergeReport merge_layer_parts(const std::vector<std::string>& parts, const std::string& output) {
  if (output.empty()) throw InputError("--merge: no output file: use -o part.cli (or .svg, .sl1, .sl1s)");
  check_merge_paths(parts, output);
  std::vector<PartHead> heads;
  for (size_t i = 0; i < parts.size(); ++i) {
    heads.push_back(read_part_head(parts[i]));
    const PartHead& h = heads.back();
    if (h.key != heads.front().key)
      throw InputError(fmt::format("--merge: '{}' is a share of another run than '{}' (their requests differ)",
                                   parts[i], parts.front()));
    if (h.count != static_cast<int>(parts.size()))
      throw InputError(
          fmt::format("--merge: '{}' is share {} of {}, but {} parts were given: give all {} shares, "
                      "in order",
                      parts[i], h.index, h.count, parts.size(), h.count));
    if (h.index != static_cast<int>(i))
      throw InputError(
          fmt::format("--merge: '{}' is share {} of {}, given as share {}: give the shares in order, "
                      "0 to {}, each once",
                      parts[i], h.index, h.count, i, h.count - 1));
  }
  const std::string& key = heads.front().key;
  PartLayout part;
  part.label = key_value(key, "label");
  std::sscanf(key_value(key, "size").c_str(), "%la %la %la", &part.size[0], &part.size[1], &part.size[2]);
  part.layers = std::stoull(key_value(key, "layers"));
  std::sscanf(key_value(key, "heights").c_str(), "%la %la", &part.layer_height, &part.first_layer);
  part.job = std::filesystem::path(output).stem().string();
  const auto format = static_cast<SliceFormat>(std::stoi(key_value(key, "format")));
  SliceRequest target;
  target.output = output;
  target.cli_ascii = format == SliceFormat::CliAscii;
  if (format_for_output(target) != format)
    throw InputError(fmt::format("--merge: the shares hold {} layers: -o '{}' has another format's extension",
                                 format_name(format), output));
  try {
    require_writable(output);
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }

  std::unique_ptr<LayerWriter> writer = make_writer(format, output, part);
  size_t next = 0;
  std::string line, encoded;
  for (size_t i = 0; i < parts.size(); ++i) {
    const auto [begin, end] = layer_share(part.layers, heads[i].index, heads[i].count);
    const auto damaged = [&](const std::string& why) {
      return InputError(fmt::format("--merge: '{}' is damaged: {}", parts[i], why));
    };
    std::ifstream in(parts[i], std::ios::binary);
    in.seekg(heads[i].records);
    for (size_t k = begin; k < end; ++k) {
      if (!std::getline(in, line)) throw damaged(fmt::format("layer {} is missing", k));
      size_t index = 0, bytes = 0;
      LayerData layer;
      if (std::sscanf(line.c_str(), "layer %zu %la %la %la %zu", &index, &layer.top, &layer.slice, &layer.area,
                      &bytes) != 5 ||
          index != k)
        throw damaged(fmt::format("layer {} is not where it belongs", k));
      layer.index = index;
      encoded.resize(bytes);
      if (!in.read(encoded.data(), static_cast<std::streamsize>(bytes)))
        throw damaged(fmt::format("layer {} is cut short", k));
      writer->append_layer(layer, encoded);
      ++next;
    }
    if (in.peek() != std::char_traits<char>::eof()) throw damaged("bytes follow its last layer");
  }
  writer->finish();
  LayerMergeReport report;
  report.format = format_name(format);
  report.layers = next;
  report.bytes = writer->bytes();
  return report;
}

}  // namespace offsetgen::slice
