// The metadata block: read back from real generated files, refused (with a message saying why)
// when absent or damaged.
#include "check/reference.h"
#include "check_test_support.h"
#include "run/metadata.h"
#include "surfaces/surface.h"

#include <gtest/gtest.h>

#include <regex>

namespace offsetgen::check {
namespace {

std::string generated_header() {
  static const std::string text = [] {
    const std::string dir = testing::scratch_dir("metadata");
    return testing::read_text(testing::write_header(dir, "gyroid", 3, "0.02+0.01*x"));
  }();
  return text;
}

std::string refusal(const std::string& text) {
  try {
    run::parse_metadata(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
  auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(Metadata, ReadsEverythingFromAGeneratedHeader) {
  run::FileMetadata m = run::parse_metadata(generated_header());
  EXPECT_EQ(m.format, 1);
  EXPECT_EQ(m.prefix, "gyroid_o3");
  ASSERT_TRUE(m.surface);
  EXPECT_EQ(*m.surface, "gyroid");
  EXPECT_FALSE(m.expression);
  EXPECT_EQ(m.order, 3);
  EXPECT_EQ(m.dims, 3);
  ASSERT_TRUE(m.thickness);
  EXPECT_EQ(*m.thickness, "0.02+0.01*x");
  EXPECT_TRUE(m.has_double);
  EXPECT_FALSE(m.has_float);
  EXPECT_NEAR(m.scale, 6.283185307179586, 1e-15);
  EXPECT_GT(m.gradient_bound, 1.7);
  EXPECT_GT(m.ops.at("offset"), 0);
}

TEST(Metadata, TheModelRebuildsFromTheMetadataAlone) {
  run::FileMetadata m = run::parse_metadata(generated_header());
  auto ref = rebuild_reference(m);
  EXPECT_EQ(ref->generation.prefix, "gyroid_o3");
  EXPECT_EQ(ref->generation.order(), 3);
  EXPECT_DOUBLE_EQ(ref->generation.construction->bounds().gradient, m.gradient_bound);
  EXPECT_TRUE(ref->warnings.empty()) << ref->warnings.front();
}

TEST(Metadata, AFileWithoutTheBlockIsNotAnOffsetgenFile) {
  EXPECT_NE(refusal("#include <math.h>\nstatic double f(double x) { return x; }\n").find("not produced by offsetgen"),
            std::string::npos);
  EXPECT_NE(refusal("").find("not produced by offsetgen"), std::string::npos);
}

TEST(Metadata, DamagedBlocksAreRefusedWithTheReason) {
  const std::string good = generated_header();
  struct Case {
    std::string text;
    std::string says;
  };
  const std::vector<Case> cases = {
      {replace(good, "\"order\":3", "\"order\":3,,"), "does not parse"},
      {replace(good, "\"order\":3", "\"order\":\"3\""), "\"order\" must be an integer"},
      {replace(good, "\"order\":3,", ""), "\"order\" is missing"},
      {replace(good, "\"order\":3", "\"order\":0"), "outside"},
      {replace(good, "\"dims\":3", "\"dims\":4"), "outside"},
      {replace(good, "\"surface\":\"gyroid\"", "\"surface\":null"), "exactly one of"},
      {replace(good, "\"precisions\":[\"double\"]", "\"precisions\":[\"half\"]"), "precisions"},
      {replace(good, "\"gradient_bound\":", "\"gradient_bound\":-"), "positive"},
      {replace(good, "\"prefix\":\"gyroid_o3\"", "\"prefix\":\"gyroid o3\""), "not a C identifier"},
      {replace(good, "\"prefix\":\"gyroid_o3\"", "\"prefix\":\"other_o3\""), "does not define other_o3_offset"},
      {replace(good, "} */", "}"), "does not end"},
      {good + "\n/* offsetgen-metadata {} */\n", "more than one"},
      {replace(good, "\"generator\":\"offsetgen", "\"generator\":\"sympy"), "generator"},
  };
  for (const auto& c : cases) {
    const std::string message = refusal(c.text);
    EXPECT_NE(message.find("damaged"), std::string::npos) << message;
    EXPECT_NE(message.find(c.says), std::string::npos) << "expected '" << c.says << "' in: " << message;
  }
}

TEST(Metadata, AnUnknownFormatIsRefused) {
  const std::string message = refusal(replace(generated_header(), "\"format\":1", "\"format\":2"));
  EXPECT_NE(message.find("format 2"), std::string::npos) << message;
}

TEST(Metadata, AMetadataSurfaceThisOffsetgenDoesNotKnowIsAnInputError) {
  run::FileMetadata m =
      run::parse_metadata(replace(generated_header(), "\"surface\":\"gyroid\"", "\"surface\":\"nosuch\""));
  try {
    rebuild_reference(m);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot be rebuilt"), std::string::npos) << e.what();
  }
}

TEST(Metadata, KindFollowsTheMetadataNotTheFileName) {
  const std::string dir = testing::scratch_dir("metadata-kind");
  const std::string header = testing::write_header(dir, "gyroid", 1);
  const std::string snippet = testing::write_header(dir, "gyroid", 1, "", true);
  // Swapped names: a header called .glsl and a snippet called .h.
  testing::write_text(dir + "/header.glsl", testing::read_text(header));
  testing::write_text(dir + "/snippet.h", testing::read_text(snippet));
  EXPECT_EQ(run::read_metadata(dir + "/header.glsl").language, "c");
  EXPECT_EQ(run::read_metadata(dir + "/snippet.h").language, "glsl");
  EXPECT_NE(testing::read_text(snippet).find("\"language\":\"glsl\""), std::string::npos);
  // Files written before the field existed are told apart by their code.
  EXPECT_EQ(run::parse_metadata(replace(testing::read_text(header), "\"language\":\"c\",", "")).language, "c");
  EXPECT_EQ(run::parse_metadata(replace(testing::read_text(snippet), "\"language\":\"glsl\",", "")).language, "glsl");
  EXPECT_NE(
      refusal(replace(testing::read_text(header), "\"language\":\"c\"", "\"language\":\"fortran\"")).find("language"),
      std::string::npos);
}

TEST(Metadata, ADirectoryOrDeviceIsRefusedWithAClearMessage) {
  const std::string dir = testing::scratch_dir("metadata-dir");
  try {
    run::read_metadata(dir);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
  }
  try {
    run::read_metadata("/dev/null");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a regular file"), std::string::npos) << e.what();
  }
}

TEST(Metadata, BinaryAndMissingFilesAreInputErrors) {
  const std::string dir = testing::scratch_dir("metadata-binary");
  testing::write_text(dir + "/bin.h", std::string("\x7f"
                                                  "ELF\0\0\0",
                                                  7));
  EXPECT_THROW(run::read_metadata(dir + "/bin.h"), InputError);
  EXPECT_THROW(run::read_metadata(dir + "/missing.h"), InputError);
}

TEST(Metadata, ThicknessSyntaxErrorsSayWhere) {
  run::FileMetadata m = run::parse_metadata(generated_header());
  try {
    parse_thickness("0.1*x+*2", m, {});
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("column 7"), std::string::npos) << e.what();
  }
  try {
    parse_thickness("0.1*(x+2", m, {});
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("column 5"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_thickness("0.1*q", m, {}), InputError);  // unknown parameter (the core's message)
  EXPECT_NO_THROW(parse_thickness("q*x", m, {{"q", "0.1"}}));
}

}  // namespace
}  // namespace offsetgen::check
