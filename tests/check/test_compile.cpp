// Compiling with the system compiler and loading with dlopen; compiler errors come back verbatim.
#include "check_test_support.h"
#include "lowering/program.h"
#include "pipeline/generate.h"
#include "run/c_library.h"
#include "run/process.h"
#include "surfaces/surface.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace offsetgen::check {
namespace {

// Restores an environment variable at the end of a scope.
class EnvGuard {
 public:
  explicit EnvGuard(const char* name) : name_(name) {
    const char* v = std::getenv(name);
    had_ = v != nullptr;
    if (had_) value_ = v;
  }
  ~EnvGuard() {
    if (had_) {
      ::setenv(name_, value_.c_str(), 1);
    } else {
      ::unsetenv(name_);
    }
  }
  EnvGuard(const EnvGuard&) = delete;
  EnvGuard& operator=(const EnvGuard&) = delete;

 private:
  const char* name_;
  bool had_ = false;
  std::string value_;
};

TEST(Compile, StrictC99AndCxx17ThenDlopenGiveTheProgramsValues) {
  const std::string dir = testing::scratch_dir("compile-ok");
  const std::string path = testing::write_header(dir, "schwarzp", 2, "0.05");
  run::FileMetadata meta = run::read_metadata(path);
  run::CompileResult r = run::compile_and_load(path, meta, run::find_toolchain());
  ASSERT_TRUE(r.ok) << r.steps.front().output << r.steps.back().output;
  ASSERT_GE(r.steps.size(), 3u);
  EXPECT_EQ(r.steps[0].name, "C99 strict + shared object");
  EXPECT_EQ(r.optimization, "-O2");
  const auto& f = r.library->functions();
  ASSERT_TRUE(f.field && f.offset && f.shell && f.normal && f.graded);
  EXPECT_EQ(f.fieldf, nullptr);

  GenerationRequest request;
  request.surface = "schwarzp";
  request.order = 2;
  request.thickness = "0.05";
  Generation g = generate(request);
  Evaluator offset(g.programs.offset), shell(g.programs.shell), graded(*g.programs.graded);
  const double p[3] = {0.1, 0.27, 0.61};
  // The header's inline sin/cos are within 1.5 ulp of the interpreter's libm ones.
  EXPECT_NEAR(f.offset(p, 0.02), offset({p[0], p[1], p[2], 0.02}).at(0), 1e-14);
  EXPECT_NEAR(f.shell(p, 0.04), shell({p[0], p[1], p[2], 0.04}).at(0), 1e-14);
  EXPECT_NEAR(f.graded(p), graded({p[0], p[1], p[2]}).at(0), 1e-14);
  EXPECT_NE(f.offset(p, 0.02), f.offset(p, 0.021));
  EXPECT_NEAR(f.shell(p, 0.05), f.graded(p), 1e-15);  // same value, separately scheduled program
}

TEST(Compile, ABrokenHeaderIsReportedWithTheCompilersOwnWords) {
  const std::string dir = testing::scratch_dir("compile-broken");
  const std::string path = testing::write_header(dir, "gyroid", 1);
  std::string text = testing::read_text(path);
  const auto body = text.find("{", text.find("static inline double gyroid_o1_offset"));
  text.insert(body + 1, "\n    const double oops = ;");
  testing::write_text(path, text);
  run::FileMetadata meta = run::read_metadata(path);
  run::CompileResult r = run::compile_and_load(path, meta, run::find_toolchain());
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(r.library, nullptr);
  ASSERT_FALSE(r.steps.empty());
  EXPECT_FALSE(r.steps[0].ok);
  EXPECT_NE(r.steps[0].output.find("gyroid_o1.h:"), std::string::npos) << r.steps[0].output;
  EXPECT_NE(r.steps[0].output.find("error"), std::string::npos) << r.steps[0].output;
  EXPECT_NE(r.steps[0].output.find("const double oops = ;"), std::string::npos) << r.steps[0].output;
}

TEST(Compile, AWarningIsAnErrorUnderTheStrictFlags) {
  const std::string dir = testing::scratch_dir("compile-warning");
  const std::string path = testing::write_header(dir, "gyroid", 1);
  std::string text = testing::read_text(path);
  const auto body = text.find("{", text.find("static inline double gyroid_o1_field"));
  text.insert(body + 1, "\n    int unused_variable;");
  testing::write_text(path, text);
  run::CompileResult r = run::compile_and_load(path, run::read_metadata(path), run::find_toolchain());
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.steps[0].output.find("unused_variable"), std::string::npos) << r.steps[0].output;
}

TEST(Compile, NoCompilerOnPathIsAnInputErrorSayingSo) {
  EnvGuard path("PATH"), cc("CC");
  ::setenv("PATH", "/nonexistent-offsetgen-test", 1);
  ::unsetenv("CC");
  try {
    run::find_toolchain();
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no C compiler on PATH"), std::string::npos) << e.what();
  }
}

TEST(Compile, CcIsRespected) {
  EnvGuard cc("CC");
  ::setenv("CC", "no-such-compiler-offsetgen", 1);
  try {
    run::find_toolchain();
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("$CC"), std::string::npos) << e.what();
  }
  const std::string gcc = run::find_on_path("gcc");
  if (gcc.empty()) GTEST_SKIP() << "no gcc";
  ::setenv("CC", "gcc -m64", 1);
  run::Toolchain t = run::find_toolchain();
  ASSERT_EQ(t.c.size(), 2u);
  EXPECT_EQ(t.c[0], "gcc");
  EXPECT_EQ(t.c_origin, "$CC");
}

TEST(Compile, TheWrapperIncludesTheHeaderTwice) {
  run::FileMetadata meta;
  meta.prefix = "p";
  meta.dims = 2;
  meta.has_float = true;
  const std::string s = run::wrapper_source("p.h", meta);
  EXPECT_NE(s.find("#include \"p.h\"\n#include \"p.h\""), std::string::npos);
  EXPECT_NE(s.find("p_offsetf(p[0], p[1], h)"), std::string::npos);
  EXPECT_EQ(s.find("graded"), std::string::npos);
}

}  // namespace
}  // namespace offsetgen::check
