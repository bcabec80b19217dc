// An offset construction is a plug-in: each method lives in one file behind this interface, and
// the pipeline, the 40-digit reference, the file banners, the metadata and `check` ask the method
// instead of switching on its name. Adding a method is one file plus one line in method_registry.cpp.
#pragma once

#include "field/atom_table.h"
#include "field/field_atoms.h"
#include "lowering/cell_bounds.h"
#include "lowering/program.h"
#include "surfaces/surface.h"

#include <ginac/ginac.h>
#include <nlohmann/json.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace offsetgen {

class FieldLowering;   // lowering/field_lowering.h
class FieldReference;  // offset/field_reference.h

// What files and metadata say about one construction. Text fields are plain paragraphs (lines of
// at most ~92 characters, no comment markers); the emitters indent them.
struct MethodFacts {
  std::string method;       // registry name, e.g. "projection"
  int requested_order = 0;  // --order as given
  int order = 0;            // the order of the offset actually built
  // Convergence orders of graded walls (--thickness), as `check` measures them from points p0 on F = 0:
  int graded_order = 0;        // the total thickness between both walls, against t(p0)
  int graded_wall_order = 0;   // each wall's distance from p0, against t(p0)/2
  int graded_paper_order = 0;  // the paper's Figure 8: from a wall point q back to F = 0, against t(q)/2
  std::string summary;         // one line: how phi is built
  std::string citation;        // where the method comes from
  std::string accuracy;        // what the zero set's accuracy is
  std::string variable_thickness;
  std::string safety;     // what keeps the functions finite and free of phantom walls
  std::string normal;     // what _normal returns
  std::string lipschitz;  // a bound on |grad phi| where a sphere tracer or mesher needs one ("" if none)
  // The same as numbers, for `check` to measure: |grad phi| <= bound (cell units) at every point p with
  // |F(p)| <= M |h| (natural units) for |h| <= h (cell units); bound 0 where the method gives none.
  struct LipschitzBound {
    double h = 0, bound = 0;
  };
  std::vector<LipschitzBound> lipschitz_bounds;
  nlohmann::ordered_json metadata = nlohmann::ordered_json::object();  // method-specific fields
};

// The half thickness h(q) of a graded wall at a point q (natural coordinates and units), signed:
// +t(q)/2 for the outer wall, -t(q)/2 for the inner one.
using LoweredHalfThickness = std::function<NodeId(const std::vector<NodeId>& natural_point)>;
using ReferenceHalfThickness = std::function<GiNaC::numeric(const std::vector<GiNaC::numeric>& natural_point)>;

// One method built for one surface and order. Everything is in natural coordinates X = k x, with
// h in natural units; the point p is the lowering's (or the reference's) base point.
class OffsetConstruction {
 public:
  virtual ~OffsetConstruction() = default;

  virtual const MethodFacts& facts() const = 0;
  virtual const AtomTable& atoms() const = 0;
  virtual const FieldAtoms& field() const = 0;
  virtual const CellBounds& bounds() const = 0;

  // phi(p, h), the unit normal of its zero set, and the graded wall phi(p, h(.)).
  virtual NodeId lower_offset(FieldLowering& at, NodeId h) const = 0;
  virtual std::vector<NodeId> lower_normal(FieldLowering& at, NodeId h) const = 0;
  virtual NodeId lower_graded_offset(FieldLowering& at, const LoweredHalfThickness& h) const = 0;

  // The same functions at high precision (CLN), without any lowering: the reference of `check`.
  virtual GiNaC::numeric offset(FieldReference& at, const GiNaC::numeric& h) const = 0;
  virtual std::vector<GiNaC::numeric> normal(FieldReference& at, const GiNaC::numeric& h) const = 0;
  virtual GiNaC::numeric graded_offset(FieldReference& at, const ReferenceHalfThickness& h) const = 0;
};

class OffsetMethod {
 public:
  virtual ~OffsetMethod() = default;
  virtual std::string name() const = 0;         // the --method / METHOD value
  virtual std::string description() const = 0;  // one line, for --help and `offsetgen list`
  virtual int max_order() const = 0;
  // True where the construction's size grows geometrically with the order, so that request checks
  // extrapolate its cost from low orders before building (validate/cost_guard.h).
  virtual bool cost_grows_geometrically() const { return false; }
  // The order a request for `requested` builds (projection rounds odd orders up).
  virtual int effective_order(int requested) const = 0;
  // Builds the construction (symbolic model and cell bounds) for one surface.
  virtual std::unique_ptr<OffsetConstruction> build(const Surface& surface, int order) const = 0;
};

// The registry (method_registry.cpp).
const std::vector<const OffsetMethod*>& offset_methods();
// Throws InputError naming the known methods.
const OffsetMethod& offset_method(const std::string& name);
inline constexpr const char* kDefaultMethod = "richardson";

}  // namespace offsetgen
