// Ghost particles: copies of other ranks' particles that lie within a cut-off of this rank's box,
// kept in our own arrays (not swarm points: docs/petsc-notes.md). Build() chooses what to send to
// whom (at neighbour-list rebuilds, after migration) and sends everything a contact needs;
// Refresh() sends the moving state of the same particles in the same order on the other steps.
// In periodic directions (-grid_periodic) a rank also receives the periodic images of particles
// near the opposite face, from its neighbours and from itself (PeriodicImages.hpp): one exchange
// entry per (rank, image), so a rank may appear several times in Ranks().
#pragma once

#include "vofdem/dem/ParticleSwarm.hpp"
#include "vofdem/dem/PeriodicImages.hpp"

#include <array>
#include <vector>

namespace vofdem {

class Halo {
public:
  // Every rank's box from the grid's ownership ranges.
  PetscErrorCode SetUp(const Grid &grid);
  PetscErrorCode Build(const ParticleArrays &a, const PetscReal *omega, PetscReal cutoff);
  PetscErrorCode Refresh(const ParticleArrays &a, const PetscReal *omega);
  // After a restart on the same rank count: the saved neighbour ranks and send lists, then a full
  // exchange, so the ghosts come back in the order the saved neighbour list refers to.
  PetscErrorCode Restore(const ParticleArrays &a, const PetscReal *omega, const std::vector<PetscMPIInt> &ranks, const std::vector<int> &images,
                         const std::vector<std::vector<PetscInt>> &send);
  const std::vector<int> &ImageCodes() const { return images_; }
  // With -coupling_lubrication and a free surface: every exchange also carries the particles' fluid_viscosity (one
  // more value per ghost), into `viscosity`. Off by default.
  void SetCarryViscosity(bool on) { carryViscosity_ = on; }

  PetscInt Count() const { return (PetscInt)id.size(); }
  // Ranks this rank exchanges ghosts with (one entry per rank and image), and the local indices sent
  // with each entry (same order).
  const std::vector<PetscMPIInt>           &Ranks() const { return ranks_; }
  const std::vector<std::vector<PetscInt>> &SendLists() const { return send_; }
  MPI_Comm                                  Comm() const { return comm_; }

  const PeriodicImages                     &Images() const { return periodic_; }

  // Collective: `width` reals per local particle (values, the swarm's order as at the last Build) to the ghosts, in
  // the ghosts' order (ghost: width per ghost), as they are sent nothing else; between Builds, as Refresh.
  PetscErrorCode SendValues(int width, const PetscReal *values, std::vector<PetscReal> *ghost) const;

  // Ghost state, structure of arrays; vectors hold x,y,z per ghost. x is where the ghost is seen
  // from this rank (its owner's position plus the shift of its image), xOwner the position exactly
  // as its owner holds it, image the code of that shift (PeriodicImages::kNone if none).
  std::vector<PetscReal>  x, xOwner, v, omega, radius, mass, viscosity;
  std::vector<PetscInt64> id, clump;
  std::vector<PetscInt>   type;
  std::vector<unsigned char> image;

private:
  PetscErrorCode Exchange(const ParticleArrays &a, const PetscReal *omega, bool full);

  MPI_Comm                            comm_ = MPI_COMM_NULL;
  PetscMPIInt                         rank_ = 0;
  std::vector<std::array<PetscReal, 6>> boxes_;  // lo x,y,z, hi x,y,z of every rank
  PeriodicImages                      periodic_;
  std::vector<PetscMPIInt>            ranks_;    // neighbours within the cut-off, one entry per image
  std::vector<int>                    images_;   // image code of what this rank sends with each entry
  std::vector<std::vector<PetscInt>>  send_;
  std::vector<PetscInt>               recvCount_;
  std::vector<PetscReal>              sendBuf_, recvBuf_;
  bool                                carryViscosity_ = false;
};

}  // namespace vofdem
