#include "offset/surface_programs.h"

#include "lowering/field_lowering.h"

#include <string>
#include <vector>

namespace offsetgen {
namespace {

std::vector<std::string> inputs(int dims, const std::string& extra = "") {
  std::vector<std::string> names = {"x", "y"};
  if (dims == 3) names.push_back("z");
  if (!extra.empty()) names.push_back(extra);
  return names;
}

// One emitted function: a program over the cell coordinates (plus one extra input) and the
// construction's view of it.
class FunctionLowering {
 public:
  FunctionLowering(Program& program, const Surface& surface, const OffsetConstruction& c)
      : program_(program), construction_(c), at_(program, surface, c.atoms(), c.field()) {}

  NodeId extra_input() { return program_.input(at_.dims()); }
  NodeId field() { return at_.field(at_.base()); }
  NodeId offset(NodeId h_cell) { return construction_.lower_offset(at_, at_.natural(h_cell)); }
  NodeId shell(NodeId t_cell) {
    NodeId half = program_.mul(program_.constant(0.5), t_cell);
    return program_.mul(offset(half), offset(program_.neg(half)));
  }
  std::vector<NodeId> normal(NodeId h_cell) { return construction_.lower_normal(at_, at_.natural(h_cell)); }
  NodeId thickness(const GiNaC::ex& t) { return at_.cell_expression(t, at_.point()); }

  // One wall of thickness t(.): h(q) = factor t(q), natural units, read where the method asks.
  NodeId graded_wall(const GiNaC::ex& thickness, NodeId factor) {
    return construction_.lower_graded_offset(at_, [this, &thickness, factor](const std::vector<NodeId>& q) {
      return at_.natural(program_.mul(factor, at_.cell_expression(thickness, q)));
    });
  }
  // The shell of total thickness t(.): walls at +-t/2.
  NodeId graded_shell(const GiNaC::ex& thickness) {
    return program_.mul(graded_wall(thickness, program_.constant(0.5)),
                        graded_wall(thickness, program_.constant(-0.5)));
  }

 private:
  Program& program_;
  const OffsetConstruction& construction_;
  FieldLowering at_;
};

}  // namespace

SurfacePrograms lower_surface(const Surface& surface, const OffsetConstruction& construction,
                              const LoweringOptions& options) {
  const int dims = surface.dims;
  SurfacePrograms out;
  out.field = Program(inputs(dims));
  out.field.add_output("F", FunctionLowering(out.field, surface, construction).field());

  out.offset = Program(inputs(dims, "h"));
  {
    FunctionLowering f(out.offset, surface, construction);
    out.offset.add_output("phi", f.offset(f.extra_input()));
  }
  out.shell = Program(inputs(dims, "t"));
  {
    FunctionLowering f(out.shell, surface, construction);
    out.shell.add_output("Phi", f.shell(f.extra_input()));
  }
  out.normal = Program(inputs(dims, "h"));
  {
    FunctionLowering f(out.normal, surface, construction);
    const auto n = f.normal(f.extra_input());
    for (size_t i = 0; i < n.size(); ++i) out.normal.add_output("n" + std::to_string(i), n[i]);
  }
  if (options.thickness) {
    out.graded = Program(inputs(dims));
    FunctionLowering f(*out.graded, surface, construction);
    out.graded->add_output("Phi", f.graded_shell(*options.thickness));
  }
  if (options.wall_thickness) {
    out.wall = Program(inputs(dims));
    FunctionLowering f(*out.wall, surface, construction);
    out.wall->add_output("Phi", f.shell(out.wall->constant(*options.wall_thickness)));
  }
  return out;
}

Program lower_graded_wall(const Surface& surface, const OffsetConstruction& construction, const GiNaC::ex& thickness) {
  Program program(inputs(surface.dims, "s"));
  FunctionLowering f(program, surface, construction);
  program.add_output("phi", f.graded_wall(thickness, program.mul(program.constant(0.5), f.extra_input())));
  return program;
}

Program lower_thickness(const Surface& surface, const OffsetConstruction& construction, const GiNaC::ex& thickness) {
  Program program(inputs(surface.dims));
  program.add_output("t", FunctionLowering(program, surface, construction).thickness(thickness));
  return program;
}

}  // namespace offsetgen
