#include "cli/generate_command.h"

#include "cli/command_line.h"
#include "cli/density_command.h"
#include "emit/backend.h"
#include "emit/emitted_api.h"
#include "emit/file_writer.h"
#include "pipeline/generate.h"
#include "surfaces/expression_input.h"
#include "surfaces/lattice_map.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>

namespace offsetgen {
namespace fs = std::filesystem;

void add_generate_command(CLI::App& app, GenerateOptions& o) {
  auto* cmd =
      app.add_subcommand("generate", "Generate offset functions for the targets of --lang (C header by default)");
  cmd->add_option("-s,--surface", o.surface, "Catalog surface (see `offsetgen list`)");
  cmd->add_option("-e,--expr", o.expression,
                  "Your own F(x, y[, z]) in cell units, e.g. \"cos(2*Pi*x)*cos(2*Pi*y) + a*sin(2*Pi*z)\". Accepted: " +
                      accepted_syntax_summary() + "; decimals are exact");
  cmd->add_option("-p,--param", o.params, "Constant parameter NAME=VALUE of --expr/--thickness (repeatable)");
  cmd->add_option("-n,--name", o.name, "Function prefix (default <surface>_o<order>; required with --expr)");
  std::string orders;
  for (const OffsetMethod* m : offset_methods())
    orders += fmt::format("{}{} 1-{}", orders.empty() ? "" : ", ", m->name(), m->max_order());
  cmd->add_option("-M,--method", o.method,
                  "Offset construction (default " + std::string(kDefaultMethod) + "):" + method_help_lines())
      ->capture_default_str();
  cmd->add_option("-m,--order", o.order, "Approximation order m (" + orders + ")")->capture_default_str();
  cmd->add_option("-l,--lang", o.lang, "Output languages, a comma list of " + backend_names() + ", or all")
      ->capture_default_str();
  cmd->add_option("--precision", o.precision, "C precision: double, float (f-suffixed names) or both")
      ->check(CLI::IsMember({"double", "float", "both"}))
      ->capture_default_str();
  cmd->add_option("-t,--thickness", o.thickness,
                  "Graded wall: total thickness t(x, y, z) > 0 in cell units; adds <prefix>_graded")
      ->each([&o](const std::string&) { o.thickness_given = true; });
  cmd->add_option("--map", o.map,
                  "Conforming lattice: the lattice coordinates of a physical point, \"U; V; W\" (expressions of x, y, "
                  "z), or a preset: " +
                      map_presets_summary() +
                      ". Walls are then exactly --thickness thick in physical units; needs --domain (docs/maps.md)");
  cmd->add_option("--domain", o.domain,
                  "X0,Y0,Z0:X1,Y1,Z1: the box (physical units) where a mapped lattice is bounded and checked");
  cmd->add_flag("--density-functions", o.density_functions,
                "Add <prefix>_density(t), _thickness_for_density(rho), _network_density(h) and "
                "_offset_for_density(rho) (periodic 3D surfaces; docs/density.md)");
  cmd->add_option("--density", o.density,
                  "Relative density rho of the sheet: adds <prefix>_wall(x, y, z), the shell of that density "
                  "(implies --density-functions)")
      ->each([&o](const std::string&) { o.density_given = true; });
  cmd->add_option("--density-field", o.density_field,
                  "Graded density rho(x, y, z): adds <prefix>_graded with t(p) = thickness_for_density(rho(p)) "
                  "(implies --density-functions)")
      ->each([&o](const std::string&) { o.density_field_given = true; });
  cmd->add_option("-o,--output", o.output,
                  "Output file of the first language (in the order " + backend_names() +
                      "); the others go beside it with their own extension; - for stdout")
      ->each([&o](const std::string&) { o.output_given = true; });
  cmd->add_option("--out-dir", o.out_dir,
                  "Directory for the <prefix>.<extension> files when -o is not given (created if missing)")
      ->each([&o](const std::string&) { o.out_dir_given = true; });
  cmd->add_flag("-q,--quiet", o.quiet, "Print nothing on success");
}

namespace {

std::string replace_extension(const std::string& path, const std::string& extension) {
  return fs::path(path).replace_extension(extension).string();
}

// Checks --out-dir without creating anything: it is a directory, or it is missing and its nearest
// existing ancestor is a writable directory. Returns true when it must be created. A file on the way
// is named ("'gen' exists and is not a directory"), so a missing directory never reads like a file.
bool out_dir_must_be_created(const std::string& given) {
  for (fs::path at = given;; at = at.parent_path()) {
    if (at.empty()) at = ".";
    std::error_code ec;
    const fs::file_status st = fs::status(at, ec);  // follows symlinks; ENOENT and ENOTDIR read not_found
    if (fs::exists(st)) {
      if (!fs::is_directory(st))
        throw InputError(fmt::format("--out-dir: '{}' exists and is not a directory", at.string()));
      if (at == fs::path(given)) return false;
      if (::access(at.c_str(), W_OK | X_OK) != 0)
        throw InputError(
            fmt::format("--out-dir: cannot create '{}': directory '{}' is not writable", given, at.string()));
      return true;
    }
    if (st.type() != fs::file_type::not_found)
      throw InputError(fmt::format("--out-dir: cannot use '{}': {}", at.string(), ec.message()));
    // create_directories() would fail on a dangling symlink: say what it is instead.
    if (fs::is_symlink(fs::symlink_status(at, ec)))
      throw InputError(fmt::format("--out-dir: '{}' is a symbolic link to a missing path", at.string()));
    if (at == at.parent_path() || at == ".")
      throw InputError(fmt::format("--out-dir: cannot use '{}': no existing directory above it", given));
  }
}

}  // namespace

int run_generate(const GenerateOptions& o, const std::vector<std::string>& args) {
  const auto start = std::chrono::steady_clock::now();
  GenerationRequest request = generation_request(o);
  const std::vector<const Backend*> languages = parse_languages(o.lang);
  request.languages.clear();
  for (const Backend* b : languages) request.languages.push_back(b->name());
  if (o.precision == "double") request.precisions = {Precision::Double};
  if (o.precision == "float") request.precisions = {Precision::Float};
  if (o.precision == "both") request.precisions = {Precision::Double, Precision::Float};
  if (o.thickness_given) request.thickness = o.thickness;
  request.map = o.map;
  if (!o.domain.empty()) request.domain = parse_domain(o.domain);
  request.density_functions = o.density_functions;
  if (o.density_given) request.density = parse_density_value("--density", o.density);
  if (o.density_field_given) request.density_field = o.density_field;
  request.command = banner_command(args);
  if (!o.quiet) request.notice = [](const std::string& message) { fmt::print(stderr, "offsetgen: {}\n", message); };
  if (o.output_given && o.output.empty()) throw InputError("-o: the file name is empty (use -o - for stdout)");
  if (o.out_dir_given && o.out_dir.empty())
    throw InputError("--out-dir: the directory name is empty (use --out-dir .)");
  if (o.output_given && o.out_dir_given) throw InputError("give either -o or --out-dir, not both");
  if (o.output == "-" && languages.size() > 1)
    throw InputError(fmt::format("-o - (stdout) takes one language, not --lang {}", o.lang));
  // A missing --out-dir is created, but only after the request has been generated, right before the
  // files are written: a bad request leaves nothing behind.
  const bool create_out_dir = o.out_dir_given && out_dir_must_be_created(o.out_dir);

  // Resolve the prefix first: default file names depend on it.
  std::string prefix = o.name;
  if (prefix.empty()) prefix = default_prefix(request);
  const std::string dir = o.out_dir.empty() ? "" : o.out_dir;
  // -o names the first language's file; the others go beside it, with their own extensions.
  std::vector<std::string> paths;
  for (const Backend* b : languages) {
    const std::string own = prefix + "." + b->extension();
    paths.push_back(o.output.empty() ? (fs::path(dir) / own).string()
                    : paths.empty()  ? o.output
                                     : replace_extension(o.output, "." + b->extension()));
    request.file_names[b->name()] = fs::path(paths.back()).filename().string();
  }
  // Fail on an unwritable destination, or two outputs on one file, before any work and before any
  // file is touched.
  std::vector<std::string> destinations;
  for (const auto& path : paths)
    if (path != "-") destinations.push_back(path);
  try {
    // Files in a directory still to be created are new files there; the directory was checked above.
    if (!create_out_dir)
      for (const auto& path : destinations) require_writable(path);
    require_distinct(destinations);
  } catch (const std::runtime_error& e) {
    for (size_t i = 1; i < paths.size(); ++i)
      if (paths[i] == paths[0])
        throw InputError(fmt::format(
            "-o {0} with --lang {1} would write the {2} file and the {3} file both to '{0}' (the others go beside "
            "the first, each with its own extension); name the {2} file, e.g. -o {4}",
            o.output, o.lang, languages[0]->title(), languages[i]->title(),
            replace_extension(o.output, "." + languages[0]->extension())));
    throw InputError(e.what());
  }

  Generation g = generate(request);
  if (create_out_dir) {
    std::error_code ec;
    fs::create_directories(o.out_dir, ec);
    if (ec) throw std::runtime_error(fmt::format("--out-dir: cannot create '{}': {}", o.out_dir, ec.message()));
  }
  std::vector<std::pair<std::string, std::string>> files;
  for (size_t i = 0; i < languages.size(); ++i) files.emplace_back(paths[i], g.file(languages[i]->name()));
  std::vector<std::string> report;
  for (const auto& [path, text] : files) {
    if (path == "-") {
      std::fwrite(text.data(), 1, text.size(), stdout);
      continue;
    }
    bool written = write_file_if_changed(path, text);
    report.push_back(fmt::format("{} {}", path, written ? "written" : "unchanged"));
  }
  if (!o.quiet && o.output != "-") {
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    std::string ops;
    for (const auto& f : emitted_functions(g))
      ops += fmt::format("{}{} {}", ops.empty() ? "" : ", ", f.suffix, count_ops(*f.program));
    const MethodFacts& method = g.method();
    const std::string rounded =
        method.order != method.requested_order
            ? fmt::format(" (order {} rounded up: {} builds even orders)", method.requested_order, method.method)
            : "";
    fmt::print("offsetgen: {} — {}, {} order {}{}, {}D, max|grad F| = {:.6g} (natural units)\n",
               fmt::join(report, "; "), g.surface.title, method.method, method.order, rounded, g.surface.dims,
               g.construction->bounds().gradient);
    fmt::print("offsetgen: ops after CSE: {}; generated in {:.1f} ms\n", ops, ms);
  }
  return kExitOk;
}

}  // namespace offsetgen
