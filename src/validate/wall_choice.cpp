#include "validate/wall_choice.h"

#include "surfaces/input_error.h"

namespace offsetgen {

void check_wall_choice(bool thickness, bool density, bool density_field, WallNeed need) {
  const int given = int(thickness) + int(density) + int(density_field);
  if (given > 1)
    throw InputError("give one of --thickness, --density and --density-field: each one sets the wall's thickness");
  if (given == 0 && need == WallNeed::Required)
    throw InputError(
        "no wall given: use --thickness T (cell units; a number or an expression of x, y, z), --density R or "
        "--density-field E");
}

}  // namespace offsetgen
