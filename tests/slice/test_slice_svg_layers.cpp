// `offsetgen slice -o DIR/`: a directory of SVGs, one per layer (layer_00000.svg ...), each a whole SVG
// holding the single file's group of that layer; an existing empty directory is filled the same way;
// --layer-range shares of .svg merge into a directory too; a directory that is not empty, a file in
// the way, --layer-range with DIR/, and an interrupted run leave nothing of the run behind.
#include "offsetgen_test_support.h"
#include "slice/layer_writer.h"
#include "slice_cli_cases.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <regex>
#include <set>

namespace offsetgen::slice {
namespace {

namespace fs = std::filesystem;
using test_support::read_file;
using test_support::run_offsetgen;
using test_support::scratch_dir;

std::vector<std::string> block(const std::vector<std::string>& extra) { return test::small_block(extra); }

// The single SVG's groups, in order.
std::vector<std::string> groups_of(const std::string& svg) {
  std::vector<std::string> groups;
  for (size_t at = svg.find("<g "); at != std::string::npos; at = svg.find("<g ", at + 1))
    groups.push_back(svg.substr(at, svg.find("</g>\n", at) + 5 - at));
  return groups;
}

std::set<std::string> names_in(const std::string& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

// DIR holds layer_00000.svg ... one per group of the single file, each a whole SVG with that group.
void expect_layer_files(const std::string& dir, const std::vector<std::string>& groups) {
  ASSERT_EQ(names_in(dir).size(), groups.size());
  for (size_t k = 0; k < groups.size(); ++k) {
    const std::string text = read_file(fmt::format("{}/layer_{:05d}.svg", dir, k));
    ASSERT_FALSE(text.empty()) << "layer " << k;
    EXPECT_EQ(text.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"", 0),
              0u);
    EXPECT_NE(text.find("viewBox=\"0 -4.000000 4.000000 4.000000\""), std::string::npos);
    const std::vector<std::string> own = groups_of(text);
    ASSERT_EQ(own.size(), 1u) << "layer " << k;
    EXPECT_EQ(own[0], groups[k]) << "layer " << k;
    EXPECT_EQ(text.substr(text.size() - 7), "</svg>\n");
  }
}

TEST(SliceSvgLayers, DirectoryHoldsOneWholeSvgPerLayerWithTheSingleFilesGroup) {
  const std::string dir = scratch_dir("slice-svg-layers");
  ASSERT_EQ(run_offsetgen(block({"-o", dir + "/single.svg"})).exit_code, 0);
  const std::vector<std::string> groups = groups_of(read_file(dir + "/single.svg"));
  ASSERT_EQ(groups.size(), 20u);
  const auto r = run_offsetgen({"slice", "--surface", "gyroid", "--density", "0.2", "--cells", "1", "--cell-size", "4",
                                "--layer-height", "0.2", "-o", dir + "/layers/"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("(SVG, a file per layer"), std::string::npos) << r.output;
  expect_layer_files(dir + "/layers", groups);
  // Nothing else beside it: the temporary directory was renamed into place.
  EXPECT_EQ(names_in(dir), (std::set<std::string>{"single.svg", "layers"}));
  // An existing empty directory, named without the slash, is filled the same way.
  fs::create_directory(dir + "/empty");
  ASSERT_EQ(run_offsetgen(block({"-o", dir + "/empty"})).exit_code, 0);
  expect_layer_files(dir + "/empty", groups);
}

TEST(SliceSvgLayers, SvgSharesMergeIntoADirectoryOfTheSingleRunsFiles) {
  const std::string dir = scratch_dir("slice-svg-layers-merge");
  ASSERT_EQ(run_offsetgen(block({"-o", dir + "/single/"})).exit_code, 0);
  const auto r = test::slice_shares_and_merge(block, dir, 3, "svg", dir + "/merged/");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::set<std::string> names = names_in(dir + "/single");
  ASSERT_EQ(names.size(), 20u);
  EXPECT_EQ(names_in(dir + "/merged"), names);
  for (const std::string& name : names)
    EXPECT_TRUE(read_file(dir + "/single/" + name) == read_file(dir + "/merged/" + name)) << name;
}

TEST(SliceSvgLayers, NonEmptyDirectoryFileInTheWayOrLayerRangeExit2AndLeaveNothing) {
  const std::string dir = scratch_dir("slice-svg-layers-bad");
  fs::create_directory(dir + "/full");
  test_support::write_file(dir + "/full/keep.txt", "mine\n");
  test_support::write_file(dir + "/file", "a file\n");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"-o", dir + "/full/"}, "is not empty"},
      {{"-o", dir + "/full"}, "is not empty"},
      {{"-o", dir + "/file/"}, "is not a directory"},
      {{"-o", dir + "/missing/layers/"}, "does not exist"},
      {{"--layer-range", "0/2", "-o", dir + "/shares/"}, "--merge them into -o"},
      {{"--cli-ascii", "-o", dir + "/ascii/"}, "--cli-ascii writes CLI"},
      {{"--printer", "sl1", "-o", dir + "/sl1/"}, "is not .sl1 or .sl1s"},
  };
  for (const auto& [extra, reason] : cases) {
    const auto r = run_offsetgen(block(extra));
    EXPECT_EQ(r.exit_code, 2) << extra.back() << "\n" << r.output;
    EXPECT_NE(r.output.find(reason), std::string::npos) << r.output;
  }
  EXPECT_EQ(names_in(dir), (std::set<std::string>{"full", "file"}));
  EXPECT_EQ(names_in(dir + "/full"), (std::set<std::string>{"keep.txt"}));
  EXPECT_EQ(read_file(dir + "/full/keep.txt"), "mine\n");
}

TEST(SliceSvgLayers, SigtermWhileWritingRemovesTheUnfinishedDirectoryAndExits143) {
  const std::string dir = scratch_dir("slice-svg-layers-interrupt");
  // 960 layers: still writing when the signal comes.
  test_support::BackgroundCommand run(
      {test_support::offsetgen_executable(), "slice", "--surface", "gyroid", "--density", "0.2", "--cells", "6",
       "--cell-size", "8", "--layer-height", "0.05", "-o", dir + "/layers/"},
      scratch_dir("slice-svg-layers-interrupt-log") + "/log");
  const std::string temporary = test_support::wait_for_entry(dir, ".layers.tmp-", run, 60);
  ASSERT_FALSE(temporary.empty()) << "no temporary directory appeared:\n" << run.wait().output;
  run.signal_group(SIGTERM);
  const test_support::CommandResult r = run.wait();
  EXPECT_EQ(r.exit_code, 143) << r.output;
  EXPECT_TRUE(fs::is_empty(dir)) << "left behind: " << *names_in(dir).begin();
}

TEST(SliceSvgLayers, FileNamesHaveEnoughDigitsForTheLayerCount) {
  const std::string dir = scratch_dir("slice-svg-layers-digits");
  for (const auto& [layers, name] : std::vector<std::pair<size_t, std::string>>{
           {1, "layer_00000.svg"}, {100000, "layer_00000.svg"}, {100001, "layer_000000.svg"}}) {
    PartLayout part;
    part.label = "test";
    part.size = {1, 1, 1};
    part.layers = layers;
    const std::string out = fmt::format("{}/n{}", dir, layers);
    auto writer = make_svg_layers_writer(out + "/", part);
    const std::vector<Loop> loops = {Loop{{{0, 0}, {1, 0}, {0, 1}}, 0.5}};
    LayerData layer{0, 0.1, 0.05, &loops, 0.5, nullptr};
    writer->append_layer(layer, writer->encode_layer(layer));
    writer->finish();
    EXPECT_EQ(names_in(out), (std::set<std::string>{name})) << layers << " layers";
  }
}

}  // namespace
}  // namespace offsetgen::slice
