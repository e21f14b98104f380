// Where a material named in a scene is found (the DEM's -dem_type_<t>_material, the energy's -energy_metal
// and -energy_gas): NAME itself when it is a path (has a '/' or ends in .yaml) and readable, else
// <dir>/NAME.yaml for each dir of the search path ($VOFDEM_MATERIALS_DIR when set, then the source tree's
// config/materials). "" when not found.
#pragma once

#include <string>

namespace vofdem {

std::string FindMaterialFile(const std::string &name);

}  // namespace vofdem
