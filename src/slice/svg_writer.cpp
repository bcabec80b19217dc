// SVG (docs/slice.md): one file, a group per layer (id "layerK", data-z its cut height in mm), each
// loop a subpath of one path with fill-rule evenodd, in millimetres with y up (the group flips the SVG's
// downward y); or a directory of files, one per layer, each the same header, that layer's group and
// the end.
#include "emit/file_writer.h"
#include "slice/layer_writer.h"
#include "surfaces/input_error.h"

#include <fmt/format.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>

namespace offsetgen::slice {
namespace {

namespace fs = std::filesystem;

std::string svg_header(const PartLayout& part, const std::string& comment) {
  return fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:.6f}mm\" height=\"{1:.6f}mm\" "
      "viewBox=\"{5} {2:.6f} {0:.6f} {1:.6f}\">\n"
      "<!-- {3}: {4}, mm, y up -->\n",
      part.size[0], part.size[1], -(part.corner[1] + part.size[1]), part.label, comment,
      // A block's box starts at 0 (written so since the first version); a body's where it lies.
      part.corner[0] == 0 ? std::string("0") : fmt::format("{:.6f}", part.corner[0]));
}

std::string svg_group(const LayerData& layer) {
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

constexpr const char* kSvgEnd = "</svg>\n";

class SvgWriter : public LayerWriter {
 public:
  SvgWriter(const std::string& path, const PartLayout& part) {
    if (path.empty()) return;
    file_.emplace(path);
    file_->append(svg_header(part, fmt::format("{} layers", part.layers)));
  }

  std::string encode_layer(const LayerData& layer) const override { return svg_group(layer); }
  void append_layer(const LayerData&, const std::string& encoded) override { file_->append(encoded); }
  void finish() override {
    file_->append(kSvgEnd);
    file_->commit();
  }
  size_t bytes() const override { return file_ ? file_->size() : 0; }

 private:
  std::optional<StreamedFile> file_;
};

// DIR/ or DIR as the directory it names (no trailing slashes).
fs::path directory_path(const std::string& path) {
  std::string p = path;
  while (p.size() > 1 && p.back() == '/') p.pop_back();
  return fs::path(p);
}

class SvgLayersWriter : public LayerWriter {
 public:
  SvgLayersWriter(const std::string& path, const PartLayout& part) : part_(part) {
    size_t last = part.layers > 0 ? part.layers - 1 : 0;
    while (last >= 10) {
      last /= 10;
      ++digits_;
    }
    digits_ = std::max(digits_ + 1, 5);
    if (path.empty()) return;
    target_ = directory_path(path);
    const fs::path parent = target_.has_parent_path() ? target_.parent_path() : fs::path(".");
    // A hidden sibling, new (mkdir fails on an existing name), mode 0777 less the umask as any directory.
    for (int attempt = 0;; ++attempt) {
      temporary_ = parent / fmt::format(".{}.tmp-{}-{}", target_.filename().string(), getpid(), attempt);
      if (mkdir(temporary_.c_str(), 0777) == 0) break;
      if (errno != EEXIST || attempt == 100)
        throw std::runtime_error(
            fmt::format("cannot create the directory '{}': {}", temporary_.string(), std::strerror(errno)));
    }
    tracked_ = RemovedOnInterrupt::directory(temporary_.string());
  }
  ~SvgLayersWriter() override {
    if (temporary_.empty()) return;
    std::error_code ignored;
    fs::remove_all(temporary_, ignored);
    tracked_.release();
  }
  SvgLayersWriter(const SvgLayersWriter&) = delete;
  SvgLayersWriter& operator=(const SvgLayersWriter&) = delete;

  std::string encode_layer(const LayerData& layer) const override { return svg_group(layer); }

  void append_layer(const LayerData& layer, const std::string& encoded) override {
    const std::string text =
        svg_header(part_, fmt::format("layer {} of {}, cut at z = {:.6f}", layer.index, part_.layers, layer.slice)) +
        encoded + kSvgEnd;
    const fs::path file = temporary_ / fmt::format("layer_{:0{}d}.svg", layer.index, digits_);
    std::ofstream out(file, std::ios::binary);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out)
      throw std::runtime_error(fmt::format("cannot write '{}' (the unfinished directory is removed): {}", file.string(),
                                           std::strerror(errno)));
    bytes_ += text.size();
  }

  void finish() override {
    // rename(2) replaces an empty directory, and fails on one that is not empty.
    if (std::rename(temporary_.c_str(), target_.c_str()) != 0)
      throw std::runtime_error(fmt::format("cannot rename '{}' to '{}' (removed): {}", temporary_.string(),
                                           target_.string(), std::strerror(errno)));
    temporary_.clear();
    tracked_.release();
  }
  size_t bytes() const override { return bytes_; }

 private:
  PartLayout part_;
  int digits_ = 0;
  fs::path target_, temporary_;
  RemovedOnInterrupt tracked_;
  size_t bytes_ = 0;
};

}  // namespace

std::unique_ptr<LayerWriter> make_svg_writer(const std::string& path, const PartLayout& part) {
  return std::make_unique<SvgWriter>(path, part);
}

std::unique_ptr<LayerWriter> make_svg_layers_writer(const std::string& path, const PartLayout& part) {
  return std::make_unique<SvgLayersWriter>(path, part);
}

bool is_layer_directory(const std::string& path) {
  std::error_code ignored;
  return (!path.empty() && path.back() == '/') || fs::is_directory(path, ignored);
}

void require_layer_directory(const std::string& path) {
  const fs::path dir = directory_path(path);
  const std::string name = dir.filename().string();
  if (name.empty() || name == "." || name == "..")
    throw InputError(
        fmt::format("-o '{}': name the directory of layers itself (e.g. -o layers/), not '{}'", path, dir.string()));
  std::error_code error;
  const fs::file_status status = fs::symlink_status(dir, error);
  if (fs::exists(status)) {
    if (!fs::is_directory(status))
      throw InputError(fmt::format("-o '{}': '{}' exists and is not a directory", path, dir.string()));
    if (!fs::is_empty(dir, error) || error)
      throw InputError(
          fmt::format("-o '{}': the directory is not empty; slice writes its layers into a new or empty directory only "
                      "(it replaces nothing it did not write)",
                      path));
  }
  const fs::path parent = dir.has_parent_path() ? dir.parent_path() : fs::path(".");
  if (!fs::is_directory(parent, error))
    throw InputError(fmt::format("-o '{}': the directory '{}' does not exist", path, parent.string()));
  if (access(parent.c_str(), W_OK | X_OK) != 0)
    throw InputError(fmt::format("-o '{}': cannot write into '{}'", path, parent.string()));
}

}  // namespace offsetgen::slice
