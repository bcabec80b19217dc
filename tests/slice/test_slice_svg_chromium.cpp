// A real SVG client draws our per-layer SVGs as the printer's screen shows the layer: headless Chromium
// renders a layer of `slice -o DIR/` through an HTML page that maps the SVG's millimetres (y up) onto
// the SL1 screen's pixels (portrait, x mirrored: bed x runs up the rows, y along the columns), and the
// screenshot, binarised at 128, agrees with the same layer's PNG in our .sl1 of the same part placed by
// --center on at least 99.5% of the pixels of the part's box. Slow (Chromium starts in seconds); skipped
// only where chromium is not installed.
#include "grey_png.h"
#include "offsetgen_test_support.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <string>

namespace offsetgen::slice {
namespace {

using test_support::run_offsetgen;
using test_support::scratch_dir;

// SL1: 1440 x 2560 pixels of 0.04725 mm. The block is 200 pixels square (2 cells of 4.725 mm) and its
// box starts on whole pixels (600 rows and 400 columns from the bed's origin), so the page's mapping
// is a whole-pixel move and Chromium resamples nothing.
constexpr double kPixel = 0.04725;
constexpr int kRows = 2560, kSide = 200, kShiftRows = 600, kShiftCols = 400, kMargin = 4;

TEST(SlowSliceSvgInChromium, ALayerRenderedByChromiumMatchesTheSl1LayersPixels) {
  const std::string chromium = OFFSETGEN_CHROMIUM;
  if (chromium.empty() || access(chromium.c_str(), X_OK) != 0)
    GTEST_SKIP() << "chromium is not installed (Debian: chromium; tools/install_deps.sh)";
  const std::string dir = scratch_dir("slice-svg-chromium");
  const double side = kSide * kPixel, shift_x = kShiftRows * kPixel, shift_y = kShiftCols * kPixel;
  const std::vector<std::string> part = {"slice",   "-q",    "--surface",   "gyroid", "--density",      "0.2",
                                         "--cells", "2,2,1", "--cell-size", "4.725",  "--layer-height", "0.25"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = part;
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  auto r = run_offsetgen(with({"-o", dir + "/layers/"}));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = run_offsetgen(
      with({"--center", fmt::format("{:.17g},{:.17g}", shift_x + side / 2, shift_y + side / 2), "-o", dir + "/p.sl1"}));
  ASSERT_EQ(r.exit_code, 0) << r.output;

  // The part's box on the screen: columns [kShiftCols, kShiftCols + kSide), rows [r0, r0 + kSide).
  const int c0 = kShiftCols, r0 = kRows - kShiftRows - kSide;
  const int width = kSide + 2 * kMargin;  // the page shows the box and a margin around it
  for (const int layer : {3, 12}) {
    const std::string svg = fmt::format("{}/layers/layer_{:05d}.svg", dir, layer);
    // In the <img>'s box the SVG puts part (x, y) at u = x / p, v = (side - y) / p (its y points down).
    // On the screen that point is at column (y + shift_y) / p, row rows - (x + shift_x) / p; less the
    // page's origin (c0 - margin, r0 - margin): column = e - v, row = f - u, a reflection CSS writes as
    // matrix(0, -1, -1, 0, e, f).
    const int e = kSide + kShiftCols - (c0 - kMargin), f = kRows - kShiftRows - (r0 - kMargin);
    const std::string page = fmt::format(
        "<!DOCTYPE html>\n<html><head><style>html, body {{ margin: 0; padding: 0; background: #fff; overflow: hidden; "
        "}}</style></head>\n<body><img src=\"file://{}\" style=\"position: absolute; left: 0; top: 0; width: {}px; "
        "height: {}px; transform-origin: 0 0; transform: matrix(0, -1, -1, 0, {}, {});\"></body></html>\n",
        svg, kSide, kSide, e, f);
    const std::string html = fmt::format("{}/layer{}.html", dir, layer),
                      shot = fmt::format("{}/shot{}.png", dir, layer);
    test_support::write_file(html, page);
    const auto c = test_support::run_command(
        {chromium, "--headless=new", "--no-sandbox", "--disable-gpu", "--hide-scrollbars", "--no-first-run",
         "--force-device-scale-factor=1", fmt::format("--window-size={},{}", width, width),
         "--user-data-dir=" + dir + "/profile", "--screenshot=" + shot, "file://" + html});
    ASSERT_EQ(c.exit_code, 0) << c.output;
    const test::GreyImage rendered = test::read_grey_png(shot);
    ASSERT_EQ(rendered.width, width);
    ASSERT_EQ(rendered.height, width);

    const std::string png = fmt::format("p{:05d}.png", layer);
    test::extract_zip_member(dir + "/p.sl1", png, dir + "/" + png);
    const test::GreyImage screen = test::read_grey_png(dir + "/" + png);
    ASSERT_EQ(screen.width, 1440);
    ASSERT_EQ(screen.height, kRows);

    size_t agree = 0, lit = 0;
    for (int row = 0; row < kSide; ++row)
      for (int col = 0; col < kSide; ++col) {
        const bool ours = screen.at(c0 + col, r0 + row) >= 128;
        const bool chromiums = rendered.at(kMargin + col, kMargin + row) < 128;  // black fill on white
        agree += ours == chromiums;
        lit += ours;
      }
    const double share = double(agree) / (kSide * kSide);
    EXPECT_GE(share, 0.995) << "layer " << layer << ": " << agree << " of " << kSide * kSide << " pixels agree";
    // Not a trivial match: the layer is neither empty nor full.
    EXPECT_GT(lit, size_t(kSide * kSide / 10)) << "layer " << layer;
    EXPECT_LT(lit, size_t(kSide * kSide * 9 / 10)) << "layer " << layer;
    // The margin around the box is white: the mapping does not spill.
    size_t dark = 0;
    for (int row = 0; row < width; ++row)
      for (int col = 0; col < width; ++col)
        if ((row < kMargin - 1 || row > kMargin + kSide || col < kMargin - 1 || col > kMargin + kSide) &&
            rendered.at(col, row) < 128)
          ++dark;
    EXPECT_EQ(dark, 0u) << "layer " << layer;
    RecordProperty(fmt::format("layer{}_agree", layer), fmt::format("{:.5f}", share));
    std::printf("layer %d: %.3f%% of the part's box agree\n", layer, 100 * share);
  }
}

}  // namespace
}  // namespace offsetgen::slice
