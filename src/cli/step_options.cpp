#include "cli/step_options.h"

#include "cli/step_body_options.h"

#include <fmt/format.h>

namespace offsetgen {

void add_step_command(CLI::App& app, StepOptions& o) {
  auto* cmd = app.add_subcommand(
      "step",
      "Write a block of cells of a wall solid as a STEP file (AP214, mm): closed solids of bicubic B-spline\n"
      "faces and planar caps, for CAD. Its deviation from the exact walls is measured on the file before it is\n"
      "written (docs/step.md). Covers the catalog surfaces, uniform or graded walls, so far");
  // The list of step/symmetry_patch.cpp's layouts (this executable does not link them; a test compares).
  add_generation_options(cmd, o,
                         "Catalog surface: by symmetry patches (schwarzp, diamond, neovius, iwp, frd), by box patches "
                         "(gyroid, fischerkoch, splitp, lidinoid)",
                         "Your own F(x, y, z), periodic with period 1 (by box patches)");
  cmd->add_option(
      "-t,--thickness", o.thickness,
      "Total wall thickness in cell units: a number, or an expression of x, y, z (a graded wall). With a "
      "box cell (--cell-size X,Y,Z) in millimetres, along the physical normal (an expression's x, y, z in mm too)");
  cmd->add_option("--density", o.density, "Instead of --thickness: the relative density R of the wall");
  cmd->add_option("-c,--cells", o.cells, "Cells of the block: NX[xNY[xNZ]]")->capture_default_str();
  cmd->add_option("--cell-size", o.cell_size,
                  "Cell edge length in millimetres: MM (a cube cell), or X,Y,Z (a box cell, \"distorted cells\": the "
                  "lattice u = x/X, v = y/Y, w = z/Z; --thickness is then in mm along the physical normal, the wall "
                  "is cut into box patches, --density is refused)")
      ->capture_default_str();
  cmd->add_option("--tolerance", o.tolerance,
                  "Largest distance (mm) of the exact walls from the faces; measured, and no file is written "
                  "beyond it")
      ->capture_default_str();
  cmd->add_option("--max-control-points", o.max_control_points, "Largest number of control points per side of a patch")
      ->capture_default_str();
  cmd->add_option("--patches", o.patches,
                  "How the sheets are cut into faces: symmetry (mirror-plane patches, faces that share their edges "
                  "exactly), box (quarter-cell boxes, any catalog surface), or auto (symmetry where the surface has "
                  "mirror planes, except diamond, which box patches write faster; else box)")
      ->capture_default_str();
  add_step_body_options(cmd, o.body);
  cmd->add_option("-o,--output", o.output, "Output file: .step or .stp");
  cmd->add_flag("-q,--quiet", o.quiet, "Print nothing on success");
  cmd->footer(
      "Exit status: 0 success, 1 a check failed (deviation beyond --tolerance, volume, or the solid is not\n"
      "valid; no file is written), 2 usage or input error, 3 internal error (or offsetgen built without\n"
      "OpenCASCADE), 130/143 interrupted by SIGINT/SIGTERM (nothing written, an existing -o unchanged).\n"
      "`offsetgen check part.step` reads a written file back and measures it again.\n"
      "Examples:\n"
      "  offsetgen step --surface schwarzp --thickness 0.1 --cells 2 --cell-size 10 --tolerance 0.01 -o p.step\n"
      "  offsetgen step --surface gyroid --thickness 0.1 --cells 2 --cell-size 10 --tolerance 0.01 -o g.step\n"
      "  offsetgen step --surface diamond --thickness \"0.05 + 0.05*x\" --cells 2x1x1 -o graded_d.step\n"
      "  offsetgen step --surface gyroid --thickness 1 --cells 2 --cell-size 10,10,15 --tolerance 0.01 -o g_box.step\n"
      "  offsetgen step --surface gyroid --thickness 0.1 --cell-size 10 --body sphere.step -o g_sphere.step\n"
      "  offsetgen step --surface diamond --thickness 0.1 --cell-size 10 --body part.step --skin 1.5 -o d_part.step");
}

}  // namespace offsetgen
