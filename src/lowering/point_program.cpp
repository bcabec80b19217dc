#include "lowering/point_program.h"

#include "lowering/lower.h"
#include "surfaces/surface.h"

#include <string>

namespace offsetgen {

Program point_program(int dims, const std::vector<GiNaC::ex>& outputs, const AtomTable& atoms,
                      const std::vector<GiNaC::ex>& coordinates, double scale) {
  Program program(dims == 3 ? std::vector<std::string>{"x", "y", "z"} : std::vector<std::string>{"x", "y"});
  Lowerer lowerer(program, atoms);
  Environment env;
  env.id = env.shared_id = 1;
  const Symbols& sym = Symbols::get();
  for (int i = 0; i < dims; ++i) {
    const GiNaC::ex symbol = coordinates.empty() ? GiNaC::ex(sym.natural(i)) : coordinates[static_cast<size_t>(i)];
    const NodeId input = program.input(i);
    env.bindings.emplace_back(symbol, scale == 1 ? input : program.mul(program.constant(scale), input));
  }
  for (size_t k = 0; k < outputs.size(); ++k)
    program.add_output("o" + std::to_string(k), lowerer.lower(outputs[k], env));
  return program;
}

}  // namespace offsetgen
