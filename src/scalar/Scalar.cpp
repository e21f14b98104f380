// Scalar.hpp: a passive scalar on the flow's cells.
#include "vofdem/scalar/Scalar.hpp"

#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/grid/CellStencil.hpp"

#include <petscviewerhdf5.h>

#include <algorithm>
#include <cmath>

namespace vofdem {

PetscErrorCode Scalar::SetFromOptions(const Grid &grid) {
  std::vector<std::string> shape = {shape_};
  PetscBool                lowerSet = PETSC_FALSE, upperSet = PETSC_FALSE;

  PetscFunctionBeginUser;
  comm_ = grid.Comm();
  for (int d = 0; d < 3; ++d) lower_[d] = grid.Lower()[d], upper_[d] = grid.Lower()[d];
  PetscOptionsBegin(comm_, "scalar_", "Scalar: a passive concentration c carried by the flow, dc/dt + div(u c) = D lap(c) (docs/modules/scalar.md)", "Scalar");
  {
    OptionReader opt(PetscOptionsObject);
    PetscCall(opt.Real("-diffusivity", "Diffusivity D of the scalar", "m^2/s", &D_, RealRange::NonNegative()));
    PetscCall(opt.Real("-cfl", "Step limit: dt (sum_d |u_d|/h_d + 2 D sum_d 1/h_d^2) at most this (0.5 keeps the limited scheme bounded)", "", &cfl_, RealRange::LeftOpen(0, 0.5)));
    PetscCall(opt.NameList("-initial", "Initial shape: box (-scalar_value inside -scalar_box_lower/upper, -scalar_background outside, as cell averages) or sine (background + value sin(2 pi n.x/L), cell averages)", {"box", "sine"}, &shape));
    PetscCall(opt.Real("-value", "Value inside the box, or the sine's amplitude", "", &value_));
    PetscCall(opt.Real("-background", "Value outside the box, or the sine's mean", "", &background_));
    PetscCall(opt.RealVector("-box_lower", "Lower corner of the initial box (default: none)", "m", lower_, 3, RealRange::Any(), &lowerSet));
    PetscCall(opt.RealVector("-box_upper", "Upper corner of the initial box (default: none)", "m", upper_, 3, RealRange::Any(), &upperSet));
    PetscCall(opt.IntVector("-sine_periods", "Whole periods of the initial sine across the box in x,y,z", periods_, 3, -1000, 1000));
  }
  PetscOptionsEnd();
  shape_ = shape[0];
  if (lowerSet != upperSet) VofdemInputError(comm_, "option -scalar_box_%s: give both corners of the box", lowerSet ? "upper" : "lower");
  for (int d = 0; d < 3 && lowerSet; ++d)
    if (!(upper_[d] > lower_[d])) VofdemInputError(comm_, "option -scalar_box_upper: must exceed -scalar_box_lower in %c", "xyz"[d]);
  if (shape_ == "sine")
    for (int d = 0; d < 3; ++d)
      if (periods_[d] != 0 && !grid.Periodic(d))
        VofdemInputError(comm_, "option -scalar_sine_periods: a sine along %c needs a periodic box in %c (-grid_periodic)", "xyz"[d], "xyz"[d]);
  PetscFunctionReturn(0);
}

// The cell average of the initial shape over cell [a, b] (exact for both shapes).
static PetscReal BoxOverlap(PetscReal a, PetscReal b, PetscReal lo, PetscReal hi) { return std::max((PetscReal)0, std::min(b, hi) - std::max(a, lo)) / (b - a); }

PetscErrorCode Scalar::SetUp(const StaggeredGrid &sg) {
  const Grid      &grid = sg.Base();
  const PetscReal *h = grid.Spacing(), *lo = grid.Lower(), *up = grid.Upper();
  LocalField       c;
  PetscInt         s[3], m[3];

  PetscFunctionBeginUser;
  sg_ = &sg;
  PetscCall(DMCreateGlobalVector(sg.Cells(), &c_));
  PetscCall(PetscObjectSetName((PetscObject)c_, "scalar_c"));
  PetscCall(VecDuplicate(c_, &stage_));
  PetscCall(VecDuplicate(c_, &rate_));
  PetscCall(DMCreateLocalVector(sg.Cells(), &cLocal_));
  for (int d = 0; d < 3; ++d) PetscCall(DMCreateLocalVector(sg.Face(d), &uLocal_[d]));
  PetscCall(DMDAGetCorners(sg.Cells(), &s[0], &s[1], &s[2], &m[0], &m[1], &m[2]));
  PetscCall(sg.GetGlobal(3, c_, &c));
  for (PetscInt k = s[2]; k < s[2] + m[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + m[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + m[0]; ++i) {
        const PetscInt q[3] = {i, j, k};
        PetscReal      v    = 1;
        if (shape_ == "box") {
          for (int d = 0; d < 3; ++d) v *= BoxOverlap(lo[d] + q[d] * h[d], lo[d] + (q[d] + 1) * h[d], lower_[d], upper_[d]);
          v = background_ + (value_ - background_) * v;
        } else {  // the cell average of sin(k.x): the phase at the centre times prod_d sinc(k_d h_d/2)
          PetscReal phase = 0, factor = 1;
          for (int d = 0; d < 3; ++d) {
            const PetscReal kd = 2 * PETSC_PI * periods_[d] / (up[d] - lo[d]);
            phase += kd * (lo[d] + (q[d] + 0.5) * h[d] - lo[d]);
            if (kd != 0) factor *= std::sin(0.5 * kd * h[d]) / (0.5 * kd * h[d]);
          }
          v = background_ + value_ * factor * std::sin(phase);
        }
        c.at(q) = v;
      }
  PetscCall(sg.RestoreGlobal(3, c_, &c));
  PetscFunctionReturn(0);
}

PetscErrorCode Scalar::FillGhosts(LocalField &c) const { return FillNearestOutside(*sg_, c); }

PetscErrorCode Scalar::Rate(Vec cg, Vec const u[3], Vec rate) {
  const Grid      &grid = sg_->Base();
  const PetscReal *h    = grid.Spacing();
  LocalField       c, r, uf[3];
  PetscInt         s[3], m[3];

  PetscFunctionBeginUser;
  PetscCall(DMGlobalToLocal(sg_->Cells(), cg, INSERT_VALUES, cLocal_));
  for (int d = 0; d < 3; ++d) PetscCall(DMGlobalToLocal(sg_->Face(d), u[d], INSERT_VALUES, uLocal_[d]));
  PetscCall(sg_->GetLocal(3, cLocal_, &c));
  PetscCall(FillGhosts(c));
  for (int d = 0; d < 3; ++d) PetscCall(sg_->GetLocal(d, uLocal_[d], &uf[d]));
  PetscCall(sg_->GetGlobal(3, rate, &r));
  PetscCall(DMDAGetCorners(sg_->Cells(), &s[0], &s[1], &s[2], &m[0], &m[1], &m[2]));
  for (PetscInt k = s[2]; k < s[2] + m[2]; ++k)
    for (PetscInt j = s[1]; j < s[1] + m[1]; ++j)
      for (PetscInt i = s[0]; i < s[0] + m[0]; ++i) {
        const PetscInt q[3] = {i, j, k};
        PetscReal      sum  = 0;
        for (int d = 0; d < 3; ++d) {
          const PetscInt n = grid.Cells()[d];
          PetscReal      F[2];  // fluxes through the low and the high face of the cell, along +d
          for (int side = 0; side < 2; ++side) {
            PetscInt f[3] = {i, j, k}, L[3] = {i, j, k}, LL[3] = {i, j, k}, R[3] = {i, j, k}, RR[3] = {i, j, k};
            f[d] += side;  // face index f sits between cells f-1 and f
            L[d] = f[d] - 1, LL[d] = f[d] - 2, R[d] = f[d], RR[d] = f[d] + 1;
            const bool wall = !grid.Periodic(d) && (f[d] == 0 || f[d] == n);
            const PetscReal uface = uf[d].at(f);
            const PetscReal cf    = uface >= 0 ? VanLeerFaceValue(c.at(LL), c.at(L), c.at(R)) : VanLeerFaceValue(c.at(RR), c.at(R), c.at(L));
            // Diffusion: none through the box's faces (walls and open faces alike: the scalar leaves by advection).
            const PetscReal diffusive = wall ? 0 : -D_ * (c.at(R) - c.at(L)) / h[d];
            F[side]                   = uface * cf + diffusive;
          }
          sum -= (F[1] - F[0]) / h[d];
        }
        r.at(q) = sum;
      }
  PetscCall(sg_->RestoreGlobal(3, rate, &r));
  for (int d = 0; d < 3; ++d) PetscCall(sg_->RestoreLocal(d, uLocal_[d], &uf[d]));
  PetscCall(sg_->RestoreLocal(3, cLocal_, &c));
  PetscFunctionReturn(0);
}

PetscErrorCode Scalar::Step(Vec const u[3], PetscReal dt) {
  PetscFunctionBeginUser;  // Heun: c* = c + dt R(c), c' = (c + c* + dt R(c*))/2, each stage a TVD Euler step
  PetscCall(Rate(c_, u, rate_));
  PetscCall(VecWAXPY(stage_, dt, rate_, c_));
  PetscCall(Rate(stage_, u, rate_));
  PetscCall(VecAXPY(stage_, dt, rate_));
  PetscCall(VecAXPBY(c_, 0.5, 0.5, stage_));
  PetscFunctionReturn(0);
}

PetscErrorCode Scalar::StableTimeStep(Vec const u[3], PetscReal *dt) const {
  const PetscReal *h    = sg_->Base().Spacing();
  PetscReal        rate = 0;

  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d) {
    PetscReal m;
    PetscCall(VecNorm(u[d], NORM_INFINITY, &m));
    rate += m / h[d] + 2 * D_ / (h[d] * h[d]);
  }
  *dt = rate > 0 ? cfl_ / rate : PETSC_MAX_REAL;
  PetscFunctionReturn(0);
}

PetscErrorCode Scalar::Summarize(ScalarSummary *s) const {
  const PetscReal *h = sg_->Base().Spacing();

  PetscFunctionBeginUser;
  PetscCall(VecSum(c_, &s->total));
  s->total *= h[0] * h[1] * h[2];
  PetscCall(VecMin(c_, nullptr, &s->min));
  PetscCall(VecMax(c_, nullptr, &s->max));
  PetscFunctionReturn(0);
}

PetscErrorCode Scalar::View(PetscViewer viewer) const {
  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(viewer, "scalar: dc/dt + div(u c) = D lap(c), D %g m^2/s, van Leer TVD advection, Heun in time, step limit %g; initial %s\n", (double)D_,
                                   (double)cfl_, shape_.c_str()));
  PetscFunctionReturn(0);
}

PetscErrorCode Scalar::Save(PetscViewer viewer) const {
  PetscFunctionBeginUser;
  PetscCall(VecView(c_, viewer));
  PetscFunctionReturn(0);
}

PetscErrorCode Scalar::Load(PetscViewer viewer) {
  PetscFunctionBeginUser;
  PetscCall(VecLoad(c_, viewer));
  PetscFunctionReturn(0);
}

PetscErrorCode Scalar::Destroy() {
  PetscFunctionBeginUser;
  for (Vec *v : {&c_, &stage_, &rate_, &cLocal_, &uLocal_[0], &uLocal_[1], &uLocal_[2]}) PetscCall(VecDestroy(v));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
