// NumPy modules: python3 imports the module and evaluates its functions over arrays, in float64
// (numpy_module.h).
#include "run/numpy_module.h"
#include "run/process.h"
#include "run/runner.h"
#include "surfaces/input_error.h"

#include <stdexcept>

namespace offsetgen::run {
namespace {

// Each function's arguments as columns: x, y[, z], then h or t where it takes one.
Lane python_lane(const std::string& python, const std::string& path, const FileMetadata& meta) {
  Lane lane;
  lane.label = "numpy";
  lane.is_float = false;
  lane.graded = meta.thickness.has_value();
  lane.evaluate = [python, path, meta](const std::string& function, const std::vector<Sample>& points, int components) {
    const bool with_distance = function == "offset" || function == "shell" || function == "normal";
    std::vector<std::vector<double>> columns(static_cast<size_t>(meta.dims + (with_distance ? 1 : 0)),
                                             std::vector<double>(points.size()));
    for (size_t i = 0; i < points.size(); ++i)
      for (size_t k = 0; k < columns.size(); ++k) columns[k][i] = points[i][k];
    return numpy::run(python, path, meta.prefix + "_" + function, columns, components);
  };
  return lane;
}

class NumpyRunner final : public Runner {
 public:
  std::string backend() const override { return "numpy"; }
  std::string how() const override { return "python3 with NumPy imports and runs it"; }
  ValueWords words() const override {
    return {"values under NumPy", "the module under python3 (NumPy, float64)", "cannot run the module"};
  }

  Prepared prepare(const std::string& path, const std::string&, const FileMetadata& meta,
                   const ProgressFn&) const override {
    Prepared p;
    p.listing = Listing::Import;
    p.json_key = "python";
    const std::string python = find_python();
    try {
      p.toolchain = numpy::describe_python(python);
      numpy::import_module(python, path);
      p.outcomes.push_back({"import", true, "python3 imports the module"});
      p.ready = true;
      p.lanes.push_back(python_lane(python, path, meta));
    } catch (const ToolMissing&) {
      throw;  // no python3 with NumPy: not checked, rather than failed
    } catch (const std::runtime_error& e) {
      p.outcomes.push_back({"import", false, e.what()});
    }
    if (meta.has_density)
      p.warnings.push_back(
          "the density relations of a NumPy module are not checked (check the C header of the same generation)");
    return p;
  }
};

}  // namespace

const Runner& numpy_runner() {
  static const NumpyRunner instance;
  return instance;
}

}  // namespace offsetgen::run
