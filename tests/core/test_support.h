// Shared helpers for the core tests: build a surface's model and programs, run the CLI.
#pragma once

#include "lowering/surface_programs.h"
#include "offset/method.h"
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

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

// Runs `offsetgen <args>` (the built executable) through the shell.
CommandResult run_offsetgen(const std::string& args);

// A fresh empty directory under the test's temporary area.
std::string fresh_directory(const std::string& name);

std::string read_file(const std::string& path);

}  // namespace offsetgen::testing
