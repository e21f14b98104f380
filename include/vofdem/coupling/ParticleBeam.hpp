// The laser's share that particles take before the melt sees it (docs/physics.md P11, F8): the beam is traced down
// -z as rays, each the exact integral of I over a square of a regular sub-grid of the cells' footprints (Laser::
// FootprintPower), so the rays of a column sum to its power to round-off. A ray goes to the highest particle whose
// projected disc reaches it, which takes the share of the ray's square inside its disc (a rim ray in part; the part
// outside passes to the column, not to particles below): it absorbs -coupling_heat_absorptivity of that and the rest is
// reflected and leaves the box; either way it is gone from its column, and what the columns keep reaches the
// energy's interface (Energy::SetBeamTaken). A particle in flight therefore shadows the particles and the melt below
// it, and the power the particles take plus what the columns keep is the beam's, to round-off.
// Rays are traced only within 3 beam radii of the centre (outside, exp(-18) of P) and are the same on every rank
// count (the sub-grid is the box's, the highest hit across ranks an MPI_MAXLOC per ray).
#pragma once

#include "vofdem/energy/Laser.hpp"
#include "vofdem/grid/Grid.hpp"

#include <vector>

namespace vofdem {

class ParticleBeam {
public:
  // raysPerCell: rays per cell edge (0: enough that a ray is at most a sixteenth of the smallest radius, and of R_l).
  void SetUp(const Grid &grid, const Laser &laser, PetscReal absorptivity, PetscInt raysPerCell) { grid_ = &grid, laser_ = &laser, eta_ = absorptivity, raysPerCell_ = raysPerCell; }
  // The beam at time t over the n local particles (centres x[3p..], radii r[p]): power[p] the W each absorbs;
  // taken: per owned column of the cell DM (x fastest, this rank's x-y corners) the W the particles removed from it.
  // Collective.
  PetscErrorCode Trace(PetscReal t, PetscInt n, const PetscReal *x, const PetscReal *r, PetscReal *power, std::vector<PetscReal> *taken);
  PetscReal      Intercepted() const { return intercepted_; }  // W the particles removed from the beam (all ranks; last Trace)
  PetscReal      Absorbed() const { return absorbed_; }        // W they absorbed
  PetscInt       Rays() const { return rays_; }                // rays traced in the last Trace
  PetscReal      Absorptivity() const { return eta_; }

private:
  const Grid  *grid_  = nullptr;
  const Laser *laser_ = nullptr;
  PetscReal    eta_ = 0, intercepted_ = 0, absorbed_ = 0;
  PetscInt     raysPerCell_ = 0, rays_ = 0;
  struct Hit {
    double z;  // the top of the disc's particle above the ray (the highest wins)
    int    rank;
  };
  std::vector<Hit>       hit_, best_;  // per ray: this rank's highest, the highest over all ranks
  std::vector<PetscInt>  owner_;       // per ray: the local particle of hit_ (-1: none)
  std::vector<PetscReal> cover_;      // per ray: the share of its square inside the winner's disc
};

}  // namespace vofdem
