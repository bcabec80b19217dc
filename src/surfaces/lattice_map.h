// Conforming lattices (--map): the lattice coordinates of a physical point, (u, v, w) = M^-1(x, y, z),
// composed with a surface. G(x) = F(M^-1(x)) is an ordinary smooth implicit function of physical
// x, y, z, so either offset method puts its walls at the requested distance in millimetres, however
// the map stretches the cells (docs/maps.md).
#pragma once

#include "surfaces/surface.h"

#include <map>
#include <string>
#include <vector>

namespace offsetgen {

struct LatticeMap {
  std::string text;                     // as given
  std::string kind;                     // the preset's name, or "mapped" for expressions
  std::vector<GiNaC::ex> coordinates;   // u, v[, w]: expressions of the cell symbols x, y, z (physical units)
  std::vector<std::string> components;  // their text, after expanding a preset
};

// Parses --map: "U; V; W" (three expressions of x, y, z; two for a 2D surface) or a preset:
//   cylindrical:N,A,C   u = sqrt(x^2+y^2)/A, v = N atan2(y, x)/(2 Pi), w = z/C
//   spherical:N,M,A     u = sqrt(x^2+y^2+z^2)/A, v = N atan2(y, x)/(2 Pi), w = M atan2(sqrt(x^2+y^2), z)/Pi
//   polar:N,A           (2D) u = sqrt(x^2+y^2)/A, v = N atan2(y, x)/(2 Pi)
// N and M count cells around (whole numbers, so the cells close up); A and C are cell sizes.
// Throws InputError naming the problem.
LatticeMap parse_lattice_map(const std::string& text, const std::map<std::string, std::string>& params, int dims);

// "X0,Y0,Z0:X1,Y1,Z1" (or X0,Y0:X1,Y1 in 2D), lo below hi on every axis; throws InputError.
Surface::Box parse_domain(const std::string& text);

// "cylindrical:N,A,C, spherical:N,M,A, polar:N,A", for --help.
std::string map_presets_summary();

// `surface` composed with `map`: field G(X) = F(k u(X), k v(X), k w(X)) with X physical, scale 1,
// the map's singular measures set (from the arguments of its atan2s, roots, logarithms and
// divisions). Whether G is single-valued and regular over the domain is validate/map_checks.h's.
Surface map_surface(const Surface& surface, const LatticeMap& map);

}  // namespace offsetgen
