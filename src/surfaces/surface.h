// A smooth implicit surface F = 0, ready for the offset construction.
#pragma once

#include "surfaces/input_error.h"

#include <ginac/ginac.h>

#include <array>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace offsetgen {

// The coordinate symbols. GiNaC tells symbols apart by serial, not by name, so every stage
// must share these objects rather than create its own "x".
struct Symbols {
  GiNaC::symbol x{"x"}, y{"y"}, z{"z"};  // cell coordinates (cell length 1)
  GiNaC::symbol X{"X"}, Y{"Y"}, Z{"Z"};  // natural coordinates X = k*x
  GiNaC::symbol h{"h"};                  // offset distance (natural units inside the model)
  GiNaC::symbol s{"s"};                  // step of one first-order move, h/j in chain j

  const GiNaC::symbol& cell(int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  const GiNaC::symbol& natural(int i) const { return i == 0 ? X : (i == 1 ? Y : Z); }
  static const Symbols& get();
};

struct Surface {
  std::string name;                           // CLI name or --name; the default emitted prefix is <name>_o<order>
  std::string title;                          // human name, e.g. "Schoen gyroid"
  std::string formula;                        // the formula as a person reads it, in cell coordinates
  std::string citation;                       // where the formula comes from
  std::string source_expr;                    // the expression text as given (catalog or --expr)
  std::map<std::string, std::string> params;  // name -> value text, as given
  int dims = 3;                               // 2 (x, y) or 3 (x, y, z)
  // F in natural coordinates X = k*x. Catalog TPMS use k = 2*pi, so derivatives carry no 2*pi
  // factors; F_cell(x) = field(k*x), and by the scaling identity phi_cell(x,h) = phi(kx, kh).
  GiNaC::ex field;
  GiNaC::ex scale;  // k, exact (2*Pi or 1)
  bool from_catalog = false;

  // A mapped lattice (--map, surfaces/lattice_map.h): field is F composed with the lattice
  // coordinates of a physical point, scale is 1 and x, y, z are physical. It is not periodic, so
  // every sweep (bounds, definedness, thickness) runs over `domain` instead of one cell, skipping the
  // points within `singular_clearance` of the map's singular set (sample_region.h).
  struct Box {
    std::array<double, 3> lo{}, hi{};  // natural (= physical) coordinates; z unused in 2D
    int dims = 3;
  };
  std::string map;                           // the --map text; empty when not mapped
  std::string map_formula;                   // u; v; w as a person reads them
  std::optional<Box> domain;                 // required with a map
  std::vector<GiNaC::ex> singular_measures;  // >= 0, and 0 exactly where the map is singular
  double singular_clearance = 0;             // points with a measure below this are not sampled
  bool mapped() const { return !map.empty(); }
};

}  // namespace offsetgen
