// Shared helpers for the core tests: build a surface's model and programs; running the CLI, scratch
// directories and files come from tests/support.
#pragma once

#include "offset/method.h"
#include "offset/offset_model.h"
#include "offset/surface_programs.h"
#include "offsetgen_test_support.h"
#include "surfaces/catalog.h"

#include <memory>
#include <string>

namespace offsetgen::testing {

struct Built {
  Surface surface;
  std::unique_ptr<OffsetConstruction> construction;
  SurfacePrograms programs;
  const CellBounds& bounds() const { return construction->bounds(); }
};

inline std::unique_ptr<Built> build(const std::string& name, int order, const std::string& method = "richardson") {
  auto b = std::make_unique<Built>();
  b->surface = catalog_surface(name);
  b->construction = offset_method(method).build(b->surface, order);
  b->programs = lower_surface(b->surface, *b->construction, {});
  return b;
}

using test_support::read_file;
using test_support::run_command;
using test_support::run_offsetgen;
using test_support::scratch_dir;

}  // namespace offsetgen::testing
