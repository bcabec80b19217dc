// --thickness, --density and --density-field each set a wall's thickness, so a request gives at most
// one of them, and exactly one where it describes a solid (mesh, step, slice). Checked here only: the
// commands pass what they were given and the library refuses it.
#pragma once

namespace offsetgen {

enum class WallNeed { Optional, Required };

// Throws InputError naming the options when more than one is given, or none where a wall is required.
void check_wall_choice(bool thickness, bool density, bool density_field, WallNeed need);

}  // namespace offsetgen
