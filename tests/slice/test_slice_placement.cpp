// `offsetgen slice --center X,Y` (SL1/SL1S): the part's centre on the printer's bed. The bed's centre
// given as --center writes the default's bytes; moving the centre by whole pixels moves every layer's
// image by those pixels; the lit pixels lie in the part's box where the screen's layout puts it; a
// centre that takes the part off the screen, a bad value, or a non-SL1 output exit 2 and write nothing.
#include "grey_png.h"
#include "offsetgen_test_support.h"
#include "slice_cli_cases.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>

namespace offsetgen::slice {
namespace {

namespace fs = std::filesystem;
using test_support::read_file;
using test_support::run_offsetgen;
using test_support::scratch_dir;

std::vector<std::string> block(const std::vector<std::string>& extra) { return test::small_block(extra); }

TEST(SliceCenter, TheBedsCentreGivenAsCenterWritesTheDefaultsBytes) {
  const std::string dir = scratch_dir("slice-center-default");
  ASSERT_EQ(run_offsetgen(block({"-o", dir + "/a.sl1"})).exit_code, 0);
  fs::create_directory(dir + "/c");
  ASSERT_EQ(run_offsetgen(block({"--center", "60,34", "-o", dir + "/c/a.sl1"})).exit_code, 0);
  EXPECT_TRUE(read_file(dir + "/a.sl1") == read_file(dir + "/c/a.sl1"));
  fs::create_directory(dir + "/s");
  ASSERT_EQ(run_offsetgen(block({"-o", dir + "/s/a.sl1s"})).exit_code, 0);
  fs::create_directory(dir + "/sc");
  ASSERT_EQ(run_offsetgen(block({"--center", "64,40.5", "-o", dir + "/sc/a.sl1s"})).exit_code, 0);
  EXPECT_TRUE(read_file(dir + "/s/a.sl1s") == read_file(dir + "/sc/a.sl1s"));
}

TEST(SliceCenter, MovingTheCentreByWholePixelsMovesEveryLayerByThosePixelsInsideThePartsBox) {
  const std::string dir = scratch_dir("slice-center-move");
  const double p = 0.04725;  // SL1: 1440 x 2560 pixels of 0.04725 mm
  const int rows = 2560, d_col = 40, d_row = 60;
  const double ax = 30, ay = 20, bx = ax + d_row * p, by = ay + d_col * p;
  ASSERT_EQ(run_offsetgen(block({"--center", fmt::format("{},{}", ax, ay), "-o", dir + "/a.sl1"})).exit_code, 0);
  ASSERT_EQ(run_offsetgen(block({"--center", fmt::format("{:.17g},{:.17g}", bx, by), "-o", dir + "/b.sl1"})).exit_code,
            0);
  for (const int layer : {0, 7, 19}) {
    const std::string name = fmt::format("{:05d}.png", layer);
    test::extract_zip_member(dir + "/a.sl1", "a" + name, dir + "/a" + name);
    test::extract_zip_member(dir + "/b.sl1", "b" + name, dir + "/b" + name);
    const test::GreyImage a = test::read_grey_png(dir + "/a" + name), b = test::read_grey_png(dir + "/b" + name);
    ASSERT_EQ(a.width, 1440);
    ASSERT_EQ(a.height, rows);
    // Bed (x, y) is at column y / p, row rows - x / p: x moves rows up, y moves columns right.
    size_t lit = 0, differ = 0;
    const int col_lo = int(std::floor((ay - 2) / p)), col_hi = int(std::ceil((ay + 2) / p));
    const int row_lo = int(std::floor(rows - (ax + 2) / p)), row_hi = int(std::ceil(rows - (ax - 2) / p));
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < a.width; ++c) {
        const uint8_t v = a.at(c, r);
        if (v > 0) {
          ++lit;
          EXPECT_TRUE(c >= col_lo && c < col_hi && r >= row_lo && r < row_hi)
              << "lit pixel (" << c << ", " << r << ") outside the part's box";
        }
        const int bc = c + d_col, br = r - d_row;
        if (bc < a.width && br >= 0 && std::abs(int(b.at(bc, br)) - int(v)) > 1) ++differ;
      }
    EXPECT_GT(lit, 1000u) << "layer " << layer;
    EXPECT_EQ(differ, 0u) << "layer " << layer << ": pixels that did not move with the centre";
  }
}

TEST(SliceCenter, OffTheScreenBadValuesOrNonSl1OutputExit2AndWriteNothing) {
  const std::string dir = scratch_dir("slice-center-bad");
  const std::vector<test::RefusedCase> cases = {
      {{"--center", "1,1", "-o", dir + "/a.sl1"}, "off the SL1 screen"},
      {{"--center", "119,34", "-o", dir + "/a.sl1"}, "off the SL1 screen"},
      {{"--center", "60,66.5", "-o", dir + "/a.sl1"}, "off the SL1 screen"},
      {{"--center", "127,40", "-o", dir + "/a.sl1s"}, "off the SL1S screen"},
      {{"--center", "60", "-o", dir + "/a.sl1"}, "give X,Y"},
      {{"--center", "60,y", "-o", dir + "/a.sl1"}, "give X,Y"},
      {{"--center", "60,34", "-o", dir + "/a.cli"}, "is not .sl1 or .sl1s"},
      {{"--center", "60,34", "-o", dir + "/a.svg"}, "is not .sl1 or .sl1s"},
  };
  test::expect_refused(cases, block, dir);
}

}  // namespace
}  // namespace offsetgen::slice
