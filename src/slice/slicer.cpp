#include "slice/slicer.h"

#include "emit/file_writer.h"
#include "slice/body_layer.h"
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

// The layers of a part `height` mm tall, from its bottom.
struct LayerStack {
  double first = 0, step = 0, height = 0;  // mm
  LayerStack(const SliceRequest& r, double part_height)
      : first(first_layer_of(r)), step(r.layer_height), height(part_height) {}
  // Layer k's cut and top, mm.
  double cut(size_t k) const { return k == 0 ? 0.5 * first : first + (double(k) - 0.5) * step; }
  double top(size_t k) const { return first + double(k) * step; }
  size_t count() const {
    size_t n = 0;
    while (cut(n) < height) ++n;
    return n;
  }
};

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
    case SliceFormat::SvgLayers:
      return "SVG, a file per layer";
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
  if (f == SliceFormat::SvgLayers) return make_svg_layers_writer(path, part);
  return make_cli_writer(path, part, f == SliceFormat::CliAscii);
}

std::string body_text(const SliceRequest& r) {
  if (!r.body) return "";
  const body::BodyRequest& b = *r.body;
  return fmt::format("{} scale {:a} skin {:a} fillet {:a} origin {} repair {}", b.path, b.scale, b.skin, b.fillet,
                     b.origin ? fmt::format("{:a},{:a},{:a}", (*b.origin)[0], (*b.origin)[1], (*b.origin)[2]) : "box",
                     b.repair ? 1 : 0);
}

// What makes two shares parts of one run: the format, the part's layout and everything that shapes
// its contours.
std::string part_key(SliceFormat f, const PartLayout& part, const SliceRequest& r, int pixels_per_cell) {
  const GenerationRequest& g = r.wall.generation;
  std::string params;
  for (const auto& [k, v] : g.params) params += k + "=" + v + ";";
  return fmt::format(
      "format {}\nlabel {}\nsize {:a} {:a} {:a}\ncorner {:a} {:a} {:a}\nlayers {}\nheights {:a} {:a}\ntolerance "
      "{:a}\npixels {}\n"
      "surface {}\nexpression {}\nparams {}\nmethod {} {}\nthickness {}|{}\ndensity {}|{}\nnetwork {}\nbody {}\n",
      static_cast<int>(f), part.label, part.size[0], part.size[1], part.size[2], part.corner[0], part.corner[1],
      part.corner[2], part.layers, part.layer_height, part.first_layer, r.tolerance, pixels_per_cell, g.surface,
      g.expression, params, g.method, g.order, r.wall.thickness, g.thickness.value_or(""),
      g.density ? fmt::format("{:a}", *g.density) : "", g.density_field.value_or(""), r.wall.network ? 1 : 0,
      body_text(r));
}

std::string wall_text(const wall::WallRequest& w) {
  const GenerationRequest& g = w.generation;
  if (w.network) return g.density ? fmt::format("network rho={}", *g.density) : "network h=" + w.thickness;
  if (g.density) return fmt::format("rho={}", *g.density);
  if (g.density_field) return "rho=" + *g.density_field;
  return "t=" + w.thickness;
}

// A part of this size on the printer's screen, and its layers in an SL1 archive.
void check_part_fits(const SliceRequest& r, SliceFormat f, const std::array<double, 3>& size) {
  const auto screen = screen_of(f);
  if (!screen) return;
  if (size[0] > std::min(screen->width, screen->bed[0]) || size[1] > std::min(screen->height, screen->bed[1]))
    throw InputError(
        fmt::format("the part ({:g} x {:g} mm) is larger than the {} screen ({:g} x {:g} mm): {}", size[0], size[1],
                    screen->model, screen->width, screen->height,
                    r.body ? "scale the body down (--scale)" : "use fewer --cells or a smaller --cell-size"));
  const size_t layers = LayerStack(r, size[2]).count();
  if (layers > 0xfff0) throw InputError(fmt::format("{} layers: an SL1 archive holds at most 65520", layers));
}

bool is_cli(SliceFormat f) { return f == SliceFormat::CliBinary || f == SliceFormat::CliAscii; }

// At most this many hatch lines across a layer (the block's diagonal over the spacing).
constexpr double kMaxHatchLines = 1e6;

// --hatch and --beam-offset (CLI), --center (SL1/SL1S) and -o DIR/ (a file per layer): their values
// and what each goes with.
void validate_extras(const SliceRequest& r) {
  const SliceFormat f = format_for_output(r);
  if (!r.hatch.empty()) {
    if (!is_cli(f)) throw InputError(fmt::format("--hatch writes CLI hatches: -o '{}' is not .cli", r.output));
    const HatchPattern h = parse_hatch(r.hatch);
    // A body's size is known once it is read: the hatches' count is then bounded by the layer's loops.
    const double lines = r.body ? 0 : std::hypot(r.cells[0], r.cells[1]) * r.cell_size / h.spacing;
    if (lines > kMaxHatchLines)
      throw InputError(
          fmt::format("--hatch {}: {:.3g} lines across a {:g} mm layer, more than {:g}: use a larger "
                      "spacing",
                      r.hatch, lines, std::hypot(r.cells[0], r.cells[1]) * r.cell_size, kMaxHatchLines));
  }
  if (r.beam_offset) {
    if (!is_cli(f)) throw InputError(fmt::format("--beam-offset offsets CLI contours: -o '{}' is not .cli", r.output));
    if (!(std::isfinite(*r.beam_offset) && *r.beam_offset >= 0))
      throw InputError(fmt::format("--beam-offset {} is not a length >= 0 (mm)", *r.beam_offset));
  }
  if (!r.center.empty()) {
    const std::optional<Screen> screen = screen_of(f);
    if (!screen)
      throw InputError(
          fmt::format("--center places the part on a resin printer's bed: -o '{}' is not .sl1 or .sl1s", r.output));
    parse_center(r.center);
    if (r.body) return;  // its size is known once it is read: the SL1 writer places it then
    PartLayout part;
    part.size = {r.cells[0] * r.cell_size, r.cells[1] * r.cell_size, r.cells[2] * r.cell_size};
    part.center = parse_center(r.center);
    part_shift(*screen, part);
  }
  if (f == SliceFormat::SvgLayers && !r.layer_range.empty())
    throw InputError(fmt::format(
        "--layer-range {} with -o '{}' (a directory of SVGs): a share is one part file; write the shares as "
        "-o shareI.svg.part and --merge them into -o '{}'",
        r.layer_range, r.output, r.output));
}

// What part_key leaves out that changes the encoded layers: hatches, beam offset, an SL1's centre.
std::string extras_key(const SliceRequest& r) {
  return fmt::format("hatch {}\nbeam offset {}\ncenter {}\n", r.hatch,
                     r.beam_offset ? fmt::format("{:a}", *r.beam_offset) : "", r.center);
}

ScanSetup scan_setup(const SliceRequest& r, double min_area) {
  ScanSetup s;
  if (!r.hatch.empty()) s.hatch = parse_hatch(r.hatch);
  s.beam_offset = r.beam_offset.value_or(0);
  s.tolerance = r.tolerance;
  s.min_area = min_area;
  return s;
}

std::string scan_text(const SliceRequest& r) {
  std::string s;
  if (!r.hatch.empty()) {
    const HatchPattern h = parse_hatch(r.hatch);
    s = fmt::format("hatches {:g} mm apart at {:g} deg, {:+g} deg a layer", h.spacing, h.angle, h.rotation);
  }
  if (r.beam_offset && *r.beam_offset > 0)
    s += fmt::format("{}contours offset {:g} mm inward (Clipper, arcs within {:.3g} mm)", s.empty() ? "" : "; ",
                     *r.beam_offset, 0.25 * r.tolerance);
  return s;
}

}  // namespace

std::array<double, 2> parse_center(const std::string& text) {
  std::array<double, 2> c{};
  const size_t comma = text.find(',');
  bool ok = comma != std::string::npos;
  for (int k = 0; ok && k < 2; ++k) {
    const std::string field = k == 0 ? text.substr(0, comma) : text.substr(comma + 1);
    size_t used = 0;
    try {
      c[k] = std::stod(field, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    ok = used > 0 && used == field.size() && std::isfinite(c[k]);
  }
  if (!ok)
    throw InputError(fmt::format("--center '{}': give X,Y in millimetres on the bed, e.g. --center 60,34", text));
  return c;
}

SliceFormat format_for_output(const SliceRequest& r) {
  const std::string ext = extension_of(format_name_of(r));
  SliceFormat f;
  if (is_layer_directory(format_name_of(r)))
    f = SliceFormat::SvgLayers;
  else if (ext == ".cli")
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
  if (r.cli_ascii && !is_cli(f)) throw InputError(fmt::format("--cli-ascii writes CLI: -o '{}' is not .cli", r.output));
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
  if (r.body)
    body::validate_body(*r.body, r.output);
  else
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
  validate_extras(r);
  if (!r.layer_range.empty()) {
    parse_layer_range(r.layer_range);
    if (!is_part_name(r.output))
      throw InputError(fmt::format(
          "--layer-range {} writes a share for --merge: -o '{}' must be NAME.EXT.part, EXT the merged file's "
          "format (.cli, .svg, .sl1 or .sl1s), e.g. -o share0.cli.part",
          r.layer_range, r.output));
  }
  const SliceFormat f = format_for_output(r);
  if (!r.body) check_part_fits(r, f, {r.cells[0] * r.cell_size, r.cells[1] * r.cell_size, r.cells[2] * r.cell_size});
  if (f == SliceFormat::SvgLayers) return require_layer_directory(r.output);
  try {
    require_writable(r.output);
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }
}

SliceSummary run_slice(const SliceRequest& r, const SliceProgress& progress, const body::BodyWarning& warn) {
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

  // The body first: a bad file fails before anything is generated.
  std::optional<body::LoadedBody> body;
  std::array<double, 3> origin{0, 0, 0};  // the lattice's origin, mm
  PartLayout part;
  part.size = {r.cells[0] * r.cell_size, r.cells[1] * r.cell_size, r.cells[2] * r.cell_size};
  if (r.body) {
    report("reading the body", -1);
    body = body::load_body(*r.body, warn);
    body::check_body_size(body->box, r.cell_size, r.body->skin);
    origin = r.body->origin ? *r.body->origin : body->box[0];
    for (size_t a = 0; a < 3; ++a) {
      part.corner[a] = body->box[0][a];
      part.size[a] = body->box[1][a] - body->box[0][a];
    }
    part.corner[2] = 0;  // heights from the body's lowest point
    check_part_fits(r, format, part.size);
    m.body =
        fmt::format("{}, {} triangles{}, box {:.4g} x {:.4g} x {:.4g} mm, skin {:g} mm{}", r.body->path,
                    body->mesh.triangles.size(), body->repaired.empty() ? "" : " (repaired: " + body->repaired + ")",
                    part.size[0], part.size[1], part.size[2], r.body->skin,
                    r.body->fillet > 0 ? fmt::format(", fillet {:g} mm", r.body->fillet) : std::string());
  }
  const double bottom = body ? body->box[0][2] : 0.0;  // mm: the part's lowest point
  const LayerStack stack(r, part.size[2]);

  report("generating the functions", -1);
  wall::WallField field(r.wall);
  m.surface = field.generation().surface.name;
  m.generate_seconds = field.generate_seconds();
  // The wall's thickness over the part's box, in cells from the origin.
  std::array<double, 3> lo{}, hi{};
  for (size_t a = 0; a < 3; ++a) {
    const double from = (a == 2 ? bottom : part.corner[a]) - origin[a];
    lo[a] = from / r.cell_size;
    hi[a] = (from + part.size[a]) / r.cell_size;
  }
  const auto range = field.thickness_range(lo, hi);
  const wall::WallExtent extent = field.extent(range);
  int per_cell = std::max(16, static_cast<int>(std::ceil(kPixelsPerWall / extent.thinnest - 1e-9)));
  // A skin spans as many pixels as the thinnest wall.
  if (r.body && r.body->skin > 0)
    per_cell = std::max(per_cell, static_cast<int>(std::ceil(kPixelsPerWall * r.cell_size / r.body->skin - 1e-9)));
  m.pixels_per_cell = r.pixels_per_cell > 0 ? r.pixels_per_cell : per_cell;
  const double longest_cells = std::max(part.size[0], part.size[1]) / r.cell_size;
  if (double(m.pixels_per_cell) * longest_cells > 65536)
    throw InputError(
        fmt::format("{} pixels per cell over {:.4g} cells: the layer grid is too large (walls too thin for "
                    "the part)",
                    m.pixels_per_cell, longest_cells));
  report("compiling the functions", -1);
  field.compile();
  m.compile_seconds = field.compile_seconds();

  const int threads = r.threads > 0 ? r.threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const std::optional<Screen> screen = screen_of(format);
  part.label = r.body ? fmt::format("offsetgen {} {} in {}, skin {:g} mm, cells of {:g} mm", m.surface, m.wall,
                                    std::filesystem::path(r.body->path).filename().string(), r.body->skin, r.cell_size)
                      : fmt::format("offsetgen {} {} {}x{}x{} cells of {:g} mm", m.surface, m.wall, r.cells[0],
                                    r.cells[1], r.cells[2], r.cell_size);
  part.job = std::filesystem::path(r.output).stem().string();
  part.layers = stack.count();
  part.layer_height = r.layer_height;
  part.first_layer = m.first_layer;
  if (!r.center.empty()) part.center = parse_center(r.center);
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
                                  part_key(format, part, r, m.pixels_per_cell) + extras_key(r)));
  }
  m.layers = end - begin;
  std::unique_ptr<LayerWriter> writer = make_writer(format, part_file ? std::string() : r.output, part);

  std::optional<BodyLayer> body_layer;
  if (body) {
    report("indexing the body's facets", -1);
    body_layer.emplace(body->mesh, origin, r.cell_size, m.pixels_per_cell, r.body->skin, r.body->fillet);
  }
  LayerSetup setup;
  setup.cells = {r.cells[0], r.cells[1]};
  setup.body = body_layer ? &*body_layer : nullptr;
  setup.cell_size = r.cell_size;
  setup.pixels_per_cell = m.pixels_per_cell;
  setup.tolerance = r.tolerance;
  // Loops with less area than a pixel (the screen's, or the marching grid's) are dropped and counted.
  const double pixel = screen ? screen->width / screen->pixels_x : r.cell_size / m.pixels_per_cell;
  setup.tiny_area = pixel * pixel;
  m.tiny_area = setup.tiny_area;
  setup.reach = extent.reach;
  // M bounds |grad F| over the unit cell; catalog surfaces repeat it, user expressions need not.
  setup.use_field_bound =
      field.generation().surface.from_catalog || (!r.body && r.cells == std::array<int, 3>{1, 1, 1});
  setup.threads = 1;
  const ScanSetup scan = scan_setup(r, setup.tiny_area);
  m.scan = scan_text(r);

  // Layers in chunks, a layer per thread at a time, written in order.
  const size_t chunk = static_cast<size_t>(std::max(1, threads)) * 4;
  for (size_t first = begin; first < end; first += chunk) {
    const size_t count = std::min(chunk, end - first);
    std::vector<LayerContours> contours(count);
    std::vector<std::string> encoded(count);
    std::vector<std::vector<Hatch>> hatches(count);
    wall::for_each_block(
        count, threads,
        [&](double f) { report("slicing", (double(first - begin) + f * double(count)) / double(end - begin)); },
        [] { return 0; },
        [&](int&, size_t i) {
          const size_t k = first + i;
          LayerSetup s = setup;
          s.z = (bottom + stack.cut(k) - origin[2]) / r.cell_size;
          contours[i] = layer_contours(field, s);
          // A body's loops in its own millimetres (layer_contours measures from the lattice's origin).
          if (body)
            for (Loop& loop : contours[i].loops)
              for (Point2& p : loop.points) p = {p[0] + origin[0], p[1] + origin[1]};
          hatches[i] = scan_layer(scan, k, contours[i]);
          encoded[i] = writer->encode_layer({k, stack.top(k), stack.cut(k), &contours[i].loops, 0, &hatches[i]});
        });
    for (size_t i = 0; i < count; ++i) {
      const size_t k = first + i;
      const LayerContours& c = contours[i];
      double area = 0;
      for (const Loop& loop : c.loops) area += loop.area;
      const LayerData layer{k, stack.top(k), stack.cut(k), &c.loops, area};
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
      m.hatches += hatches[i].size();
      for (const Hatch& h : hatches[i]) m.hatch_length += std::hypot(h.end[0] - h.start[0], h.end[1] - h.start[1]);
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
  if (!m.body.empty()) {
    s += fmt::format("  body:       {}\n", m.body);
    s += fmt::format("  lattice:    {} {}, cells of {:g} mm\n", m.surface, m.wall, m.cell_size);
  } else {
    s += fmt::format("  block:      {} {} {}x{}x{} cells of {:g} mm\n", m.surface, m.wall, m.cells[0], m.cells[1],
                     m.cells[2], m.cell_size);
  }
  s += fmt::format("  layers:     {} of {:g} mm (first {:g} mm), cut at mid-height\n", m.layers, m.layer_height,
                   m.first_layer);
  s += fmt::format("  contours:   {} loops, {} vertices; {} loops under {:.3g} mm^2 dropped\n", m.loops, m.vertices,
                   m.tiny_loops, m.tiny_area);
  s += fmt::format(
      "  accuracy:   vertices on the {}; largest chord deviation measured {:.4g} mm "
      "(--tolerance {:g} mm){}\n",
      m.body.empty() ? "wall's zero set" : "part's boundary (the wall, the body or the core)", m.max_deviation,
      m.tolerance,
      m.unverified_chords ? fmt::format(", {} chords not measured", m.unverified_chords) : std::string());
  if (!m.scan.empty())
    s += fmt::format("  scan:       {}: {} hatches, {:.3f} m of them\n", m.scan, m.hatches, m.hatch_length / 1000);
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
  std::sscanf(key_value(key, "corner").c_str(), "%la %la %la", &part.corner[0], &part.corner[1], &part.corner[2]);
  part.layers = std::stoull(key_value(key, "layers"));
  std::sscanf(key_value(key, "heights").c_str(), "%la %la", &part.layer_height, &part.first_layer);
  part.job = std::filesystem::path(output).stem().string();
  const auto format = static_cast<SliceFormat>(std::stoi(key_value(key, "format")));
  SliceRequest target;
  target.output = output;
  target.cli_ascii = format == SliceFormat::CliAscii;
  // SVG shares merge into one file or into a directory of a file per layer (the same groups).
  const SliceFormat written = format_for_output(target);
  if (written != format && !(format == SliceFormat::Svg && written == SliceFormat::SvgLayers))
    throw InputError(fmt::format("--merge: the shares hold {} layers: -o '{}' has another format's extension",
                                 format_name(format), output));
  if (written == SliceFormat::SvgLayers) {
    require_layer_directory(output);
  } else {
    try {
      require_writable(output);
    } catch (const std::runtime_error& e) {
      throw InputError(e.what());
    }
  }

  std::unique_ptr<LayerWriter> writer = make_writer(written, output, part);
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
