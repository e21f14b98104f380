// The four lunar-regolith simulant shapes of seed 002 (docs/physics.md S, P10) as built-in clump templates.
//
// A reading: seed 002 fig. 2 is an image only; its text says each simulant grain is "one base sphere
// plus several satellite spheres", four shapes in equal shares. Here the four shapes are the base
// sphere (radius 1, at the origin) with 1, 2, 3 and 4 satellites of radius 0.5-0.7 whose centres lie
// 0.64-0.76 base radii from the base's centre, in directions that make the grains irregular (none is
// symmetric beyond the two-sphere one). These are plausible shapes, not the seed's measured ones.
#include "vofdem/dem/ClumpLibrary.hpp"

namespace vofdem {

std::vector<PetscReal> RegolithTemplate(const std::string &name) {
  //                    x      y      z      r
  if (name == "regolith1")  // base + 1: an elongated grain
    return {0, 0, 0, 1, 0.7, 0, 0, 0.7};
  if (name == "regolith2")  // base + 2: a bent grain
    return {0, 0, 0, 1, 0.7, 0, 0, 0.6, -0.3, 0.6, 0, 0.7};
  if (name == "regolith3")  // base + 3: a flattened tripod
    return {0, 0, 0, 1, 0.65, 0, 0, 0.7, -0.3, 0.6, 0, 0.6, -0.2, -0.3, 0.6, 0.5};
  if (name == "regolith4")  // base + 4: a knobbly, nearly equant grain
    return {0, 0, 0, 1, 0.6, 0, 0, 0.65, -0.5, 0.4, 0, 0.6, 0, -0.5, 0.45, 0.55, 0, 0.1, -0.75, 0.5};
  return {};
}

}  // namespace vofdem
