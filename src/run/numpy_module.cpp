#include "run/numpy_module.h"

#include "run/process.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace offsetgen::run::numpy {
namespace {

namespace fs = std::filesystem;

// argv: module path, function name, argument count, point count, input file, output file. The module
// gets a private name so that loading it never picks up another module of the same prefix on sys.path.
constexpr const char* kRunner = R"(import sys, importlib.util
import numpy as np
path, name, count, n, source, target = sys.argv[1:7]
spec = importlib.util.spec_from_file_location("offsetgen_checked_module", path)
module = importlib.util.module_from_spec(spec)
spec.loader.exec_module(module)
if name:
    columns = np.fromfile(source, np.float64).reshape(int(count), int(n))
    with np.errstate(all="ignore"):
        result = getattr(module, name)(*columns)
    if isinstance(result, tuple):
        result = np.stack(np.broadcast_arrays(*result), axis=-1)
    np.ascontiguousarray(result, np.float64).tofile(target)
)";

ProcessResult run_python(const std::string& python, const std::vector<std::string>& args) {
  std::vector<std::string> argv = {python, "-c", kRunner};
  argv.insert(argv.end(), args.begin(), args.end());
  return run_process(argv);
}

}  // namespace

std::string describe_python(const std::string& python) {
  if (python.empty())
    throw ToolMissing("no python3 found: a NumPy module is checked by running it (Debian: python3-numpy)");
  const ProcessResult r = run_process({python, "-c", "import numpy; print(numpy.__version__)"});
  if (!r.started) throw ToolMissing(fmt::format("cannot run {}", python));
  if (r.exit_code != 0)
    throw ToolMissing(
        fmt::format("{} cannot import NumPy (Debian: apt-get install python3-numpy): {}", python, r.output));
  std::string version = r.output;
  while (!version.empty() && (version.back() == '\n' || version.back() == '\r')) version.pop_back();
  return fmt::format("{} with NumPy {}", python, version);
}

void import_module(const std::string& python, const std::string& module_path) {
  const ProcessResult r = run_python(python, {fs::absolute(module_path).string(), "", "0", "0", "", ""});
  if (r.exit_code != 0) throw std::runtime_error(fmt::format("python3 cannot import it:\n{}", r.output));
}

std::vector<double> run(const std::string& python, const std::string& module_path, const std::string& function,
                        const std::vector<std::vector<double>>& columns, int components) {
  const size_t n = columns.empty() ? 0 : columns.front().size();
  ScratchDir dir("offsetgen-numpy");
  const fs::path source = dir.path() / "in.f64", target = dir.path() / "out.f64";
  {
    std::ofstream out(source, std::ios::binary);
    for (const auto& column : columns)
      out.write(reinterpret_cast<const char*>(column.data()), static_cast<std::streamsize>(n * sizeof(double)));
    if (!out) throw std::runtime_error("cannot write " + source.string());
  }
  const ProcessResult r =
      run_python(python, {fs::absolute(module_path).string(), function, std::to_string(columns.size()),
                          std::to_string(n), source.string(), target.string()});
  if (r.exit_code != 0) throw std::runtime_error(fmt::format("python3 failed on {}:\n{}", function, r.output));
  std::vector<double> values(n * static_cast<size_t>(components));
  std::ifstream in(target, std::ios::binary);
  in.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(values.size() * sizeof(double)));
  if (in.gcount() != static_cast<std::streamsize>(values.size() * sizeof(double)) || in.peek() != EOF)
    throw std::runtime_error(
        fmt::format("{} returned {} bytes, expected {} values", function, in.gcount(), values.size()));
  return values;
}

}  // namespace offsetgen::run::numpy
