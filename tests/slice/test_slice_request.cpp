// slice/slicer.h as a library: validate() refuses bad requests with InputError before anything is
// generated or written, and run_slice's summary agrees with its file read back (layers, loops,
// vertices, size); an SVG holds a group per layer and a path per layer's loops.
#include "cli_reader.h"
#include "offsetgen_test_support.h"
#include "slice/slicer.h"
#include "slice_test_support.h"
#include "surfaces/input_error.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace offsetgen::slice {
namespace {

namespace fs = std::filesystem;

SliceRequest small_block(const std::string& output) {
  SliceRequest r;
  r.wall = test::gyroid_request();
  r.cells = {2, 2, 1};
  r.cell_size = 8;
  r.layer_height = 0.5;
  r.output = output;
  r.threads = 2;
  return r;
}

TEST(SliceRequest, BadRequestsThrowInputErrorAndWriteNothing) {
  const std::string dir = test_support::scratch_dir("slice-request-bad");
  auto refused = [&](const std::function<void(SliceRequest&)>& change) {
    SliceRequest r = small_block(dir + "/part.cli");
    change(r);
    EXPECT_THROW(validate(r), InputError);
    EXPECT_THROW(run_slice(r), InputError);
  };
  refused([](SliceRequest& r) { r.layer_height = 0; });
  refused([](SliceRequest& r) { r.layer_height = -1; });
  refused([](SliceRequest& r) { r.layer_height = 8.5; });
  refused([](SliceRequest& r) { r.first_layer = 0; });
  refused([](SliceRequest& r) { r.tolerance = 0; });
  refused([](SliceRequest& r) { r.tolerance = -0.01; });
  refused([&](SliceRequest& r) { r.output = dir + "/part.stl"; });
  refused([&](SliceRequest& r) { r.output = dir + "/part"; });
  refused([&](SliceRequest& r) {
    r.output = dir + "/part.sl1";
    r.cells = {2, 9, 1};  // 72 mm across the screen's short side (68.04 mm)
  });
  refused([&](SliceRequest& r) {
    r.output = dir + "/part.sl1s";
    r.cells = {17, 2, 1};  // 136 mm along the SL1S's long side (128 mm)
  });
  refused([&](SliceRequest& r) { r.output = dir + "/no/such/dir/part.cli"; });
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(SliceRequest, SummaryAgreesWithTheFileReadBack) {
  const std::string dir = test_support::scratch_dir("slice-request-summary");
  SliceRequest r = small_block(dir + "/part.cli");
  r.cli_ascii = true;
  const SliceSummary m = run_slice(r);
  const std::string bytes = test_support::read_file(r.output);
  EXPECT_EQ(m.file_bytes, bytes.size());
  const test::CliFile f = test::read_cli(bytes);
  EXPECT_EQ(m.layers, f.layers.size());
  EXPECT_EQ(m.layers, 16u);
  size_t loops = 0, vertices = 0;
  for (const auto& layer : f.layers)
    for (const auto& p : layer.polylines) {
      ++loops;
      vertices += p.points.size() - 1;  // the first point repeated
    }
  EXPECT_EQ(m.loops, loops);
  EXPECT_EQ(m.vertices, vertices);
  EXPECT_LE(m.max_deviation, r.tolerance);
  EXPECT_GT(m.max_deviation, 0);
  EXPECT_EQ(m.unverified_chords, 0u);
}

TEST(SliceRequest, SvgHoldsAGroupPerLayer) {
  const std::string dir = test_support::scratch_dir("slice-request-svg");
  const SliceSummary m = run_slice(small_block(dir + "/part.svg"));
  const std::string svg = test_support::read_file(dir + "/part.svg");
  auto count = [&](const std::string& what) {
    size_t n = 0;
    for (size_t at = svg.find(what); at != std::string::npos; at = svg.find(what, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("<g id=\"layer"), m.layers);
  EXPECT_EQ(count("fill-rule=\"evenodd\""), m.layers);
  EXPECT_EQ(count(" Z"), m.loops);
  EXPECT_EQ(svg.rfind("</svg>\n"), svg.size() - 7);
}

}  // namespace
}  // namespace offsetgen::slice
