// The expensive `offsetgen mesh` cases: the "Slow" prefix gives them the label slow as well.
#include "mesh_test_support.h"

#include <gtest/gtest.h>

namespace offsetgen::mesh::testing {
namespace {

class MeshAdmeshSlow : public ::testing::TestWithParam<Case> {};

TEST_P(MeshAdmeshSlow, IsClosedConsistentlyOrientedAndOnePart) { expect_clean_part(GetParam()); }

// The graded gyroid at the automatic resolution: 4 voxels across its thinnest (0.05 cell) wall.
INSTANTIATE_TEST_SUITE_P(SlowParts, MeshAdmeshSlow,
                         ::testing::Values(Case{"gyroid_graded_automatic_resolution",
                                                {"--surface", "gyroid", "--thickness", "0.05 + 0.1*x/3"}}),
                         [](const ::testing::TestParamInfo<Case>& c) { return c.param.name; });

}  // namespace
}  // namespace offsetgen::mesh::testing
