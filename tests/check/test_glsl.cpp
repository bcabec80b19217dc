// GLSL snippets: compiled with glslangValidator in the four host dialects; errors point at the
// snippet's own line.
#include "check_test_support.h"
#include "run/glsl_compile.h"
#include "run/process.h"

#include <gtest/gtest.h>

namespace offsetgen::check {
namespace {

TEST(Glsl, GeneratedSnippetsCompileForAllFourTargets) {
  if (run::find_on_path("glslangValidator").empty()) GTEST_SKIP() << "glslangValidator not installed (glslang-tools)";
  const std::string dir = testing::scratch_dir("glsl-ok");
  const std::string path = testing::write_header(dir, "neovius", 2, "0.02+0.01*y", true);
  const std::string text = testing::read_text(path);
  run::FileMetadata meta = run::parse_metadata(text);
  auto results = run::compile_glsl(text, meta, path);
  ASSERT_EQ(results.size(), 4u);
  for (const auto& r : results) EXPECT_TRUE(r.ok) << r.name << "\n" << r.output;
  EXPECT_EQ(results[3].target, run::GlslTarget::Vulkan);
  EXPECT_NE(std::find(results[3].command.begin(), results[3].command.end(), "-V"), results[3].command.end());
}

TEST(Glsl, AnErrorNamesTheSnippetLine) {
  if (run::find_on_path("glslangValidator").empty()) GTEST_SKIP() << "glslangValidator not installed (glslang-tools)";
  const std::string dir = testing::scratch_dir("glsl-bad");
  const std::string path = testing::write_header(dir, "gyroid", 1, "", true);
  std::string text = testing::read_text(path);
  const auto fn = text.find("highp float gyroid_o1_offset");
  const auto body = text.find("{\n", fn) + 2;
  text.insert(body, "    highp float oops = 1.0 +;\n");
  int line = 1;
  for (size_t i = 0; i < body; ++i) line += text[i] == '\n';
  run::FileMetadata meta = run::parse_metadata(text);
  auto results = run::compile_glsl(text, meta, "bad.glsl");
  for (const auto& r : results) {
    EXPECT_FALSE(r.ok) << r.name;
    EXPECT_NE(r.output.find("[bad.glsl line " + std::to_string(line) + "]"), std::string::npos) << r.output;
  }
}

TEST(Glsl, HostShaderCallsEveryFunction) {
  run::FileMetadata meta;
  meta.prefix = "s";
  meta.dims = 2;
  meta.thickness = "0.1";
  const std::string host = run::glsl_host_shader("/* snippet */\n", meta, run::GlslTarget::Es300);
  for (const char* call :
       {"s_field(q.xy)", "s_offset(q.xy, q.w)", "s_shell(q.xy, q.w)", "s_normal(q.xy, q.w)", "s_graded(q.xy)"})
    EXPECT_NE(host.find(call), std::string::npos) << call;
  EXPECT_EQ(host.rfind("#version 300 es", 0), 0u);
}

}  // namespace
}  // namespace offsetgen::check
