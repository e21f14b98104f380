// The fluid's properties at a cell face, from the two cells it separates (docs/physics.md, F2):
// the fluid fraction eps_f is their mean; b = eps/rho is averaged harmonically, so that a face between
// two phases carries the balanced-force density (eps rho)_f = eps_f^2 / b_f. Flow (predictor, viscous
// matrix, projection, pressure operator, step limits) and coupling (added mass, deposits, the drag's face share) all
// form a face from this one definition, so that they see the same face mass to the last bit.
#pragma once

#include <petscsys.h>

namespace vofdem {

struct FaceProperties {
  PetscReal eps;   // eps_f, the face's fluid fraction
  PetscReal beta;  // b_f = (eps/rho)_f
  // (eps rho)_f: the fluid mass per face volume the momentum equation divides by
  PetscReal EpsRho() const { return eps * eps / beta; }
};

// b_f from the eps/rho of the two cells (the pressure operator's face coefficient too).
inline PetscReal FaceBeta(PetscReal bL, PetscReal bR) { return 2 * bL * bR / (bL + bR); }

// eL, eR: the fluid fractions of the cells on either side; bL, bR: their eps/rho.
inline FaceProperties FaceAverage(PetscReal eL, PetscReal eR, PetscReal bL, PetscReal bR) { return {0.5 * (eL + eR), FaceBeta(bL, bR)}; }

// The conductivity of a face between cells of conductivities kL and kR (docs/physics.md F7): the same
// harmonic mean, which keeps the heat flux continuous across a jump of k; 0 if either side conducts nothing.
inline PetscReal FaceConductivity(PetscReal kL, PetscReal kR) { return kL > 0 && kR > 0 ? FaceBeta(kL, kR) : 0; }

}  // namespace vofdem
