// The two phases of the VOF module (Vof.hpp): the initial fraction from -vof_boxes/-vof_spheres, and
// the mixture properties the flow reads (docs/physics.md F: rho = alpha rho_1 + (1 - alpha) rho_0, likewise mu).
#include "vofdem/vof/Vof.hpp"

#include "vofdem/flow/Flow.hpp"

#include <cmath>

namespace vofdem {

namespace {

struct Shapes {
  const std::vector<PetscReal> *boxes, *spheres;
};

// Negative inside any box or sphere of the heavy phase.
PetscReal InsideShapes(void *ctx, const PetscReal x[3]) {
  const Shapes *s = static_cast<const Shapes *>(ctx);
  for (size_t b = 0; b + 6 <= s->boxes->size(); b += 6) {
    const PetscReal *q = s->boxes->data() + b;
    if (x[0] > q[0] && x[0] < q[3] && x[1] > q[1] && x[1] < q[4] && x[2] > q[2] && x[2] < q[5]) return -1;
  }
  for (size_t b = 0; b + 4 <= s->spheres->size(); b += 4) {
    const PetscReal *q = s->spheres->data() + b;
    if (std::hypot(x[0] - q[0], std::hypot(x[1] - q[1], x[2] - q[2])) < q[3]) return -1;
  }
  return 1;
}

// InsideShapes' answer for a whole cell where it is certain (Vof::CellClass): outside every shape's
// bounding box (the samples lie strictly inside the cell): 0; all 8 corners strictly inside one box or
// sphere (convex: so is every point between them): 1. Otherwise -1 (sampled). Most cells of a scene
// are one or the other; sampling them all was a tenth of the dam break's start-up.
int ShapesCellClass(void *ctx, const PetscReal lo[3], const PetscReal hi[3]) {
  const Shapes *s    = static_cast<const Shapes *>(ctx);
  bool          near = false;
  for (size_t b = 0; b + 6 <= s->boxes->size(); b += 6) {
    const PetscReal *q = s->boxes->data() + b;
    bool             apart = false, in = true;
    for (int d = 0; d < 3; ++d) {
      apart = apart || hi[d] <= q[d] || lo[d] >= q[d + 3];
      in    = in && lo[d] > q[d] && hi[d] < q[d + 3];
    }
    if (in) return 1;
    near = near || !apart;
  }
  for (size_t b = 0; b + 4 <= s->spheres->size(); b += 4) {
    const PetscReal *q = s->spheres->data() + b;
    bool             apart = false, in = true;
    for (int d = 0; d < 3; ++d) apart = apart || hi[d] <= q[d] - q[3] || lo[d] >= q[d] + q[3];
    for (int c = 0; c < 8 && in; ++c) {
      const PetscReal x[3] = {c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]};
      in                   = std::hypot(x[0] - q[0], std::hypot(x[1] - q[1], x[2] - q[2])) < q[3];
    }
    if (in) return 1;
    near = near || !apart;
  }
  return near ? -1 : 0;
}

}  // namespace

PetscErrorCode Vof::SetInitialShapes() {
  PetscFunctionBeginUser;
  Shapes         s       = {&boxes_, &spheres_};
  const PetscInt n[3]    = {samples_, samples_, samples_};
  PetscCall(SetFraction(InsideShapes, &s, n, ShapesCellClass));
  PetscFunctionReturn(0);
}

PetscErrorCode Vof::UpdateProperties(Flow &flow) const {
  const PetscScalar *a;
  PetscScalar       *rho, *mu;
  PetscInt           n;

  PetscFunctionBeginUser;
  const PetscReal rho0 = flow.ReferenceDensity(), mu0 = flow.ReferenceViscosity();
  PetscCall(VecGetLocalSize(alpha_, &n));
  PetscCall(VecGetArrayRead(alpha_, &a));
  PetscCall(VecGetArray(flow.Density(), &rho));
  PetscCall(VecGetArray(flow.Viscosity(), &mu));
  for (PetscInt i = 0; i < n; ++i) {
    // Round-off outside [0, 1] (Vof.hpp: no clipping of alpha) must not make a property negative.
    const PetscReal f = std::fmin(std::fmax(PetscRealPart(a[i]), (PetscReal)0), (PetscReal)1);
    rho[i]            = f * density_ + (1 - f) * rho0;
    mu[i]             = f * viscosity_ + (1 - f) * mu0;
  }
  PetscCall(VecRestoreArray(flow.Viscosity(), &mu));
  PetscCall(VecRestoreArray(flow.Density(), &rho));
  PetscCall(VecRestoreArrayRead(alpha_, &a));
  bool inflow = false;  // the flow's ghost cells beyond inflow faces take the entering phase (VofOpenFaces.cpp)
  for (int t : openType_) inflow = inflow || t == 1;
  if (inflow) flow.SetPropertyGhosts(InflowPropertyGhosts, this);
  PetscCall(flow.PropertiesChanged());
  PetscFunctionReturn(0);
}

}  // namespace vofdem
