// The part from the lattice wall w and the signed distance d to what bounds it (a block's box or a
// body; negative inside), in any one length unit (docs/parts.md):
//   no skin:  part = max(w, d)                          (the lattice cut by the domain)
//   skin s:   core c = d + s,  skin k = max(d, -c),  part = smin(k, max(w, c), r)
// where smin is the quadratic smooth minimum of radius r (the fillet; r = 0 gives min). mesh samples it
// on voxels, slice on a layer's pixels and at the contour's points.
#pragma once

namespace offsetgen::wall {

// The part's value at one point from d and the wall w (see above).
double part_value(double d, double w, double skin, double fillet);
// The same where w is known to exceed every value that matters (far from the walls, or not needed):
// the skin's value where it is below `band`, else `background`.
double part_value_without_wall(double d, double skin, double band, double background);
// True when part_value at d depends on w within `band` of the surface.
bool wall_matters(double d, double skin, double fillet, double margin);

}  // namespace offsetgen::wall
