// Writing a solid to STEP (AP214, millimetres, a MANIFOLD_SOLID_BREP per solid) with a fixed header,
// so the same solid gives the same bytes, and reading a STEP file back.
#pragma once

#include <TopoDS_Shape.hxx>

#include <string>

namespace offsetgen::step {

// Writes `solid` to `path` (a scratch file: the caller moves it into place). `description` goes into
// the header's FILE_DESCRIPTION. With `pcurves`, each edge also carries its curves in the parameters
// of its faces (SURFACE_CURVE with PCURVEs): twice the bytes, but a reader need not project the edges
// onto trimmed faces itself (box patches: the file reads back and checks faster). Throws
// std::runtime_error on failure.
void write_step(const TopoDS_Shape& solid, const std::string& path, const std::string& description,
                bool pcurves = false);

// The file's shape (all its roots in one compound if there are several). Throws std::runtime_error.
TopoDS_Shape read_step(const std::string& path);

// A file read back with its header's first FILE_DESCRIPTION entry ("" when there is none).
struct StepContents {
  TopoDS_Shape shape;
  std::string description;
};
StepContents read_step_contents(const std::string& path);

// The file's bytes as they are ("" for a file that cannot be read).
std::string read_file_bytes(const std::string& path);

}  // namespace offsetgen::step
