// Density on the command line: `offsetgen density`, generate --density / --density-field /
// --density-functions, and the refusals (exit 2, nothing written).
#include "test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

namespace offsetgen {
namespace {
namespace fs = std::filesystem;
using testing::run_offsetgen;

TEST(DensityCli, PrintsTheThicknessAndTheConstants) {
  auto r = run_offsetgen("density --surface gyroid --density 0.2");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* needle : {"thickness t = 0.0650", "A = 3.0916", "chi = -8", "t_max = 0.3675"})
    EXPECT_NE(r.output.find(needle), std::string::npos) << needle << "\n" << r.output;
  auto network = run_offsetgen("density --surface gyroid --density 0.5 --network --json");
  ASSERT_EQ(network.exit_code, 0) << network.output;
  const auto j = nlohmann::json::parse(network.output);
  EXPECT_EQ(j["solid"], "network");
  EXPECT_NEAR(j["offset"].get<double>(), 0.0, 1e-8);  // V_0 = 1/2
  EXPECT_EQ(j["chi"], -8);
  EXPECT_LE(j["chi_residual"].get<double>(), 1e-6);
  // The sheet's rho(t) = A t + (pi chi / 6) t^3 at the printed thickness gives back rho.
  auto sheet = nlohmann::json::parse(run_offsetgen("density --surface schwarzp --density 0.3 --json").output);
  const double t = sheet["thickness"], a = sheet["area"];
  const int chi = sheet["chi"];
  EXPECT_NEAR(a * t + 3.141592653589793 * chi / 6 * t * t * t, 0.3, 1e-14);
}

TEST(DensityCli, BadDensitiesAreRefused) {
  struct Case {
    const char* args;
    const char* message;
  };
  for (const Case& c :
       {Case{"--surface gyroid --density 0", "must be > 0"}, Case{"--surface gyroid --density -0.2", "must be > 0"},
        Case{"--surface gyroid --density 0.95", "above rho_max = 0.928"},
        Case{"--surface neovius --density 0.2 --network", "outside [0.318"},
        Case{"--surface gyroid --density much", "'much' is not a number"},
        Case{"--expr \"cos(2*Pi*x) + cos(2*Pi*y) + z\" --density 0.1", "not provably periodic in z"}}) {
    auto r = run_offsetgen(std::string("density ") + c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << "\n" << r.output;
  }
}

TEST(DensityCli, GenerateRefusesBadDensityInputAndWritesNothing) {
  struct Case {
    const char* args;
    const char* message;
  };
  const std::string dir = testing::scratch_dir("density_refusals");
  for (const Case& c :
       {Case{"--surface gyroid --density 0", "must be a number > 0"},
        Case{"--surface gyroid --density -0.1", "must be a number > 0"},
        Case{"--surface schwarzp --density 0.7", "above rho_max = 0.6812"},
        Case{"--surface gyroid --density 0.2 --thickness 0.1",
             "give one of --thickness, --density and --density-field"},
        Case{"--surface gyroid --density 0.2 --density-field 0.2", "give one of"},
        Case{"--expr \"sin(2*Pi*x)*cos(y) + cos(2*Pi*z)\" --name q --density 0.1", "not provably periodic in y"},
        Case{"--expr \"cos(2*Pi*x) + cos(2*Pi*y)\" --name q --density-functions", "need a 3D surface"},
        Case{"--surface gyroid --density-field \"0.3 - x\"", "a relative density must lie in (0, rho_max"}}) {
    auto r = run_offsetgen(std::string("generate ") + c.args + " --lang all --out-dir " + dir);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_TRUE(fs::is_empty(dir)) << c.args << " left a file behind";
  }
}

TEST(DensityCli, GenerateAddsWallGradedAndTheRelations) {
  const std::string dir = testing::scratch_dir("density_generate");
  auto r =
      run_offsetgen("generate --surface gyroid --order 2 --density 0.2 --lang all --precision both --out-dir " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string h = testing::read_file(dir + "/gyroid_o2.h");
  for (const char* needle :
       {"static inline double gyroid_o2_wall(double x, double y, double z)",
        "static inline float gyroid_o2_wallf(float x, float y, float z)",
        "static inline double gyroid_o2_density(double t)",
        "static inline double gyroid_o2_thickness_for_density(double rho)",
        "static inline double gyroid_o2_network_density(double h)",
        "static inline float gyroid_o2_offset_for_densityf(float rho)", "Euler characteristic chi = -8",
        "with t = 0.0650636", "nan(\"\")", "nanf(\"\")", "\"wall_density\":0.2"})
    EXPECT_NE(h.find(needle), std::string::npos) << needle;
  const std::string g = testing::read_file(dir + "/gyroid_o2.glsl");
  for (const char* needle :
       {"float gyroid_o2_wall(highp vec3 p)", "float gyroid_o2_thickness_for_density(highp float rho)",
        "intBitsToFloat(0x7fc00000)", "GLSL ES 3.00 leaves that value unspecified"})
    EXPECT_NE(g.find(needle), std::string::npos) << needle;

  auto graded =
      run_offsetgen("generate --surface gyroid --order 2 --density-field \"0.3 - 0.2*x\" -o " + dir + "/gg.h");
  ASSERT_EQ(graded.exit_code, 0) << graded.output;
  const std::string gg = testing::read_file(dir + "/gg.h");
  EXPECT_NE(gg.find("static inline double gyroid_o2_graded(double x, double y, double z)"), std::string::npos);
  EXPECT_NE(gg.find("\"density_field\":\"0.3 - 0.2*x\""), std::string::npos);
  EXPECT_NE(gg.find("--density-field: gyroid_o2_graded(p) is the sheet with t(p) ="), std::string::npos);
  EXPECT_EQ(gg.find("_wall("), std::string::npos);

  // Without density options the files keep their bytes: no density text at all.
  auto plain = run_offsetgen("generate --surface gyroid --order 2 -o " + dir + "/plain.h");
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_EQ(testing::read_file(dir + "/plain.h").find("density"), std::string::npos);
}

}  // namespace
}  // namespace offsetgen
