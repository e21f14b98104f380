// Velocity sampled at points (Flow::SampleVelocity) and along the centre lines of the box
// (Flow::WriteProfile, -flow_profile_output): the staggered components are gathered on rank 0 and
// interpolated trilinearly, with the ghost values of the boundary conditions outside the box, so
// that a point on a wall gets the wall's velocity.
#include "vofdem/flow/Flow.hpp"

#include "vofdem/base/Runtime.hpp"

#include <cmath>
#include <cstdio>
#include <algorithm>
#include <vector>

namespace vofdem {

namespace {

// One velocity component in natural ordering on rank 0, with the boundary rules of FlowBoundary.
struct GatheredComponent {
  int                     d = 0;
  PetscInt                n[3] = {0, 0, 0};
  std::vector<PetscReal>  v;
  const Grid             *grid = nullptr;
  const FlowBoundary     *bc = nullptr;

  PetscReal At(PetscInt q[3]) const {
    for (int e = 0; e < 3; ++e) {
      if (q[e] >= 0 && q[e] < n[e]) continue;
      if (grid->Periodic(e)) {
        PetscInt r[3] = {q[0], q[1], q[2]};
        r[e]          = (q[e] % n[e] + n[e]) % n[e];
        return At(r);
      }
      const int       side = q[e] >= n[e];
      PetscInt        r[3] = {q[0], q[1], q[2]};
      const FlowFace &F    = bc->Face(2 * e + side);
      if (e == d) {  // beyond a boundary face along the normal: the face itself (not used inside the box)
        r[e] = side ? n[e] - 1 : 0;
        return At(r);
      }
      r[e] = side ? 2 * n[e] - 1 - q[e] : -q[e] - 1;  // mirror cell
      const PetscReal inner = At(r);
      if (F.type == FlowBoundaryType::Wall || F.type == FlowBoundaryType::Inflow) {
        PetscReal x[3];
        for (int c = 0; c < 3; ++c) x[c] = grid->Lower()[c] + (c == d ? q[c] : q[c] + 0.5) * grid->Spacing()[c];
        x[e] = side ? grid->Upper()[e] : grid->Lower()[e];
        return 2 * bc->Prescribed(2 * e + side, d, x) - inner;
      }
      return inner;
    }
    return v[(q[2] * n[1] + q[1]) * n[0] + q[0]];
  }

  PetscReal Sample(const PetscReal x[3]) const {
    PetscInt  i0[3];
    PetscReal w[3];
    for (int e = 0; e < 3; ++e) {
      const PetscReal xi = (x[e] - grid->Lower()[e]) / grid->Spacing()[e] - (e == d ? 0 : 0.5);
      PetscInt        i  = (PetscInt)std::floor(xi);
      if (e == d && !grid->Periodic(e)) i = std::min(std::max(i, (PetscInt)0), n[e] - 2);
      i0[e] = i;
      w[e]  = xi - i;
    }
    PetscReal sum = 0;
    for (int c = 0; c < 8; ++c) {
      PetscInt  q[3];
      PetscReal wt = 1;
      for (int e = 0; e < 3; ++e) {
        const int b = (c >> e) & 1;
        q[e]        = i0[e] + b;
        wt *= b ? w[e] : 1 - w[e];
      }
      if (wt != 0) sum += wt * At(q);
    }
    return sum;
  }
};

PetscErrorCode Gather(const StaggeredGrid &sg, const FlowBoundary &bc, int d, Vec u, GatheredComponent *g) {
  Vec        natural, seq;
  VecScatter scatter;
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  g->d    = d;
  g->grid = &sg.Base();
  g->bc   = &bc;
  for (int e = 0; e < 3; ++e) g->n[e] = sg.Points(d, e);
  PetscCall(DMDACreateNaturalVector(sg.Face(d), &natural));
  PetscCall(DMDAGlobalToNaturalBegin(sg.Face(d), u, INSERT_VALUES, natural));
  PetscCall(DMDAGlobalToNaturalEnd(sg.Face(d), u, INSERT_VALUES, natural));
  PetscCall(VecScatterCreateToZero(natural, &scatter, &seq));
  PetscCall(VecScatterBegin(scatter, natural, seq, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(scatter, natural, seq, INSERT_VALUES, SCATTER_FORWARD));
  PetscCallMPI(MPI_Comm_rank(sg.Base().Comm(), &rank));
  if (rank == 0) {
    const PetscScalar *a;
    PetscInt           len;
    PetscCall(VecGetLocalSize(seq, &len));
    PetscCall(VecGetArrayRead(seq, &a));
    g->v.resize(len);
    for (PetscInt i = 0; i < len; ++i) g->v[i] = PetscRealPart(a[i]);
    PetscCall(VecRestoreArrayRead(seq, &a));
  }
  PetscCall(VecScatterDestroy(&scatter));
  PetscCall(VecDestroy(&seq));
  PetscCall(VecDestroy(&natural));
  PetscFunctionReturn(0);
}

}  // namespace

PetscErrorCode Flow::SampleVelocity(const PetscReal x[3], PetscReal u[3]) const {
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(grid_->Comm(), &rank));
  for (int d = 0; d < 3; ++d) {
    GatheredComponent g;
    PetscCall(Gather(sg_, bc_, d, u_[d], &g));
    u[d] = rank == 0 ? g.Sample(x) : 0;
  }
  PetscCallMPI(MPI_Bcast(u, 3, MPIU_REAL, 0, grid_->Comm()));
  PetscFunctionReturn(0);
}

PetscErrorCode Flow::WriteProfile(const std::string &path) const {
  GatheredComponent g[3];
  PetscMPIInt       rank;
  int               ok = 1;

  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d) PetscCall(Gather(sg_, bc_, d, u_[d], &g[d]));
  PetscCallMPI(MPI_Comm_rank(grid_->Comm(), &rank));
  if (rank == 0) {
    FILE *fp = std::fopen(path.c_str(), "w");
    ok       = fp != nullptr;
    if (fp) {
      const PetscReal *lo = grid_->Lower(), *hi = grid_->Upper(), *h = grid_->Spacing();
      std::fprintf(fp, "line,s,x,y,z,u,v,w\n");
      for (int a = 0; a < 3; ++a) {
        std::vector<PetscReal> s;
        if (!grid_->Periodic(a)) s.push_back(lo[a]);
        for (PetscInt i = 0; i < grid_->Cells()[a]; ++i) s.push_back(lo[a] + (i + 0.5) * h[a]);
        if (!grid_->Periodic(a)) s.push_back(hi[a]);
        for (PetscReal sv : s) {
          PetscReal x[3];
          for (int e = 0; e < 3; ++e) x[e] = 0.5 * (lo[e] + hi[e]);
          x[a] = sv;
          std::fprintf(fp, "%c,%.10e,%.10e,%.10e,%.10e,%.10e,%.10e,%.10e\n", "xyz"[a], (double)sv, (double)x[0], (double)x[1], (double)x[2], (double)g[0].Sample(x),
                       (double)g[1].Sample(x), (double)g[2].Sample(x));
        }
      }
      std::fclose(fp);
    }
  }
  PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, grid_->Comm()));
  if (!ok) VofdemInputError(grid_->Comm(), "option -flow_profile_output: cannot write '%s'", path.c_str());
  PetscFunctionReturn(0);
}

}  // namespace vofdem
