// Rigid multi-sphere clumps (Clumps.hpp, docs/physics.md P10).
#include "vofdem/dem/Clumps.hpp"

#include "vofdem/base/Runtime.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace vofdem {

namespace rigid {

void QuatRotate(const PetscReal q[4], const PetscReal v[3], PetscReal out[3]) {
  // v + 2 w (u x v) + 2 u x (u x v), u = (x, y, z)
  const PetscReal *u = q + 1, t[3] = {2 * (u[1] * v[2] - u[2] * v[1]), 2 * (u[2] * v[0] - u[0] * v[2]), 2 * (u[0] * v[1] - u[1] * v[0])};
  out[0] = v[0] + q[0] * t[0] + (u[1] * t[2] - u[2] * t[1]);
  out[1] = v[1] + q[0] * t[1] + (u[2] * t[0] - u[0] * t[2]);
  out[2] = v[2] + q[0] * t[2] + (u[0] * t[1] - u[1] * t[0]);
}

void QuatRotateInverse(const PetscReal q[4], const PetscReal v[3], PetscReal out[3]) {
  const PetscReal c[4] = {q[0], -q[1], -q[2], -q[3]};
  QuatRotate(c, v, out);
}

void QuatFromMatrix(const PetscReal R[9], PetscReal q[4]) {
  const PetscReal tr = R[0] + R[4] + R[8];
  if (tr > 0) {
    const PetscReal s = 2 * std::sqrt(1 + tr);
    q[0] = 0.25 * s, q[1] = (R[7] - R[5]) / s, q[2] = (R[2] - R[6]) / s, q[3] = (R[3] - R[1]) / s;
  } else if (R[0] > R[4] && R[0] > R[8]) {
    const PetscReal s = 2 * std::sqrt(1 + R[0] - R[4] - R[8]);
    q[0] = (R[7] - R[5]) / s, q[1] = 0.25 * s, q[2] = (R[1] + R[3]) / s, q[3] = (R[2] + R[6]) / s;
  } else if (R[4] > R[8]) {
    const PetscReal s = 2 * std::sqrt(1 + R[4] - R[0] - R[8]);
    q[0] = (R[2] - R[6]) / s, q[1] = (R[1] + R[3]) / s, q[2] = 0.25 * s, q[3] = (R[5] + R[7]) / s;
  } else {
    const PetscReal s = 2 * std::sqrt(1 + R[8] - R[0] - R[4]);
    q[0] = (R[3] - R[1]) / s, q[1] = (R[2] + R[6]) / s, q[2] = (R[5] + R[7]) / s, q[3] = 0.25 * s;
  }
  const PetscReal n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (int k = 0; k < 4; ++k) q[k] /= n;
}

void QuatMultiply(const PetscReal a[4], const PetscReal b[4], PetscReal r[4]) {
  r[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
  r[1] = a[0] * b[1] + b[0] * a[1] + a[2] * b[3] - a[3] * b[2];
  r[2] = a[0] * b[2] + b[0] * a[2] + a[3] * b[1] - a[1] * b[3];
  r[3] = a[0] * b[3] + b[0] * a[3] + a[1] * b[2] - a[2] * b[1];
}

void BestRotation(int n, const PetscReal *P, const PetscReal *Q, PetscReal q[4]) {
  // Horn (1987): with S = sum (p - pbar)(q - qbar)^T, the unit quaternion of the rotation taking the
  // p to the q is the eigenvector of the largest eigenvalue of this symmetric 4 x 4 matrix.
  PetscReal pb[3] = {0, 0, 0}, qb[3] = {0, 0, 0}, S[3][3] = {{0}};
  for (int k = 0; k < n; ++k)
    for (int d = 0; d < 3; ++d) pb[d] += P[3 * k + d] / n, qb[d] += Q[3 * k + d] / n;
  for (int k = 0; k < n; ++k)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) S[a][b] += (P[3 * k + a] - pb[a]) * (Q[3 * k + b] - qb[b]);
  const PetscReal N[16] = {S[0][0] + S[1][1] + S[2][2], S[1][2] - S[2][1], S[2][0] - S[0][2], S[0][1] - S[1][0],
                           S[1][2] - S[2][1], S[0][0] - S[1][1] - S[2][2], S[0][1] + S[1][0], S[2][0] + S[0][2],
                           S[2][0] - S[0][2], S[0][1] + S[1][0], -S[0][0] + S[1][1] - S[2][2], S[1][2] + S[2][1],
                           S[0][1] - S[1][0], S[2][0] + S[0][2], S[1][2] + S[2][1], -S[0][0] - S[1][1] + S[2][2]};
  PetscReal values[4], vectors[16];
  SymmetricEigen(4, N, values, vectors);
  for (int k = 0; k < 4; ++k) q[k] = vectors[4 * k + 3];
  const PetscReal len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (int k = 0; k < 4; ++k) q[k] /= len;
}

}  // namespace rigid

namespace {

void Cross(const PetscReal a[3], const PetscReal b[3], PetscReal c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1], c[1] = a[2] * b[0] - a[0] * b[2], c[2] = a[0] * b[1] - a[1] * b[0];
}

// q exp(theta): q times the rotation by the body-frame vector theta, normalised.
void QuatStep(const PetscReal q[4], const PetscReal theta[3], PetscReal out[4]) {
  const PetscReal a = std::sqrt(theta[0] * theta[0] + theta[1] * theta[1] + theta[2] * theta[2]);
  const PetscReal c = std::cos(0.5 * a), s = a > 0 ? std::sin(0.5 * a) / a : 0.5;
  const PetscReal d[4] = {c, s * theta[0], s * theta[1], s * theta[2]};
  PetscReal       r[4];
  r[0] = q[0] * d[0] - q[1] * d[1] - q[2] * d[2] - q[3] * d[3];
  r[1] = q[0] * d[1] + d[0] * q[1] + q[2] * d[3] - q[3] * d[2];
  r[2] = q[0] * d[2] + d[0] * q[2] + q[3] * d[1] - q[1] * d[3];
  r[3] = q[0] * d[3] + d[0] * q[3] + q[1] * d[2] - q[2] * d[1];
  const PetscReal n = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
  for (int k = 0; k < 4; ++k) out[k] = r[k] / n;
}

// R(q) of a unit quaternion, row-major: a clump's members are turned by one matrix instead of a
// quaternion product each (the kick is most of a clump step).
void RotationMatrix(const PetscReal q[4], PetscReal R[9]) {
  const PetscReal w = q[0], x = q[1], y = q[2], z = q[3];
  R[0] = 1 - 2 * (y * y + z * z), R[1] = 2 * (x * y - w * z), R[2] = 2 * (x * z + w * y);
  R[3] = 2 * (x * y + w * z), R[4] = 1 - 2 * (x * x + z * z), R[5] = 2 * (y * z - w * x);
  R[6] = 2 * (x * z - w * y), R[7] = 2 * (y * z + w * x), R[8] = 1 - 2 * (x * x + y * y);
}

void Apply(const PetscReal R[9], const PetscReal v[3], PetscReal out[3]) {
  for (int i = 0; i < 3; ++i) out[i] = R[3 * i] * v[0] + R[3 * i + 1] * v[1] + R[3 * i + 2] * v[2];
}

void ApplyTranspose(const PetscReal R[9], const PetscReal v[3], PetscReal out[3]) {
  for (int i = 0; i < 3; ++i) out[i] = R[i] * v[0] + R[3 + i] * v[1] + R[6 + i] * v[2];
}

// Body-frame angular velocity I^-1 R^T L.
void BodyOmega(const PetscReal R[9], const PetscReal I[3], const PetscReal L[3], PetscReal wb[3]) {
  ApplyTranspose(R, L, wb);
  for (int d = 0; d < 3; ++d) wb[d] /= I[d];
}

}  // namespace

void Clumps::Group(const ParticleArrays &a) const {
  if (!stale_ && groupedN_ == a.n) return;
  stale_ = false, groupedN_ = a.n;
  for (auto &kv : members_) kv.second.clear();
  for (PetscInt p = 0; p < a.n; ++p)
    if (a.clump[p] >= 0) members_[a.clump[p]].push_back(p);
  for (auto it = members_.begin(); it != members_.end();) it = it->second.empty() ? members_.erase(it) : std::next(it);
  Flatten();
}

void Clumps::Flatten() const {
  order_.clear(), start_.assign(1, 0);
  size_t widest = 0;
  for (const auto &kv : members_) {
    order_.insert(order_.end(), kv.second.begin(), kv.second.end());
    start_.push_back((PetscInt)order_.size());
    widest = std::max(widest, kv.second.size());
  }
  if (scratch_.size() < 3 * widest) scratch_.resize(3 * widest);
}

PetscErrorCode Clumps::SetUp(const ParticleArrays &a, const std::vector<PetscReal> &typeDensity, const PetscReal gravity[3], PetscInt *count) {
  // Shapes computed so far, keyed by radii and member distances (invariant under rotation), with the
  // member positions relative to the first member they were computed from.
  struct Shape {
    ClumpTemplate          t;
    std::vector<PetscReal> rel;
  };
  std::map<std::vector<long long>, std::vector<Shape>> cache;

  PetscFunctionBeginUser;
  for (int d = 0; d < 3; ++d) gravity_[d] = gravity[d];
  stale_ = true;
  Group(a);
  *count = (PetscInt)members_.size();
  PetscCheck(!*count || a.rigid, PETSC_COMM_SELF, PETSC_ERR_ORDER, "clumps in a particle swarm created without their rigid state (ParticleSwarm::SetRigidFields before Create)");
  for (auto &kv : members_) {
    std::vector<PetscInt> &m = kv.second;
    std::sort(m.begin(), m.end(), [&](PetscInt i, PetscInt j) { return a.id[i] < a.id[j]; });
    const PetscInt   p0 = m[0], n = (PetscInt)m.size();
    const PetscReal *x0 = &a.x[3 * p0], unit = 1e-9 * a.radius[p0];
    std::vector<PetscReal> rel(3 * n);
    for (PetscInt k = 0; k < n; ++k)
      for (int d = 0; d < 3; ++d) rel[3 * k + d] = a.x[3 * m[k] + d] - x0[d];
    std::vector<long long> key;
    for (PetscInt k = 0; k < n; ++k) {
      key.push_back(std::llround(a.radius[m[k]] / unit));
      for (PetscInt j = k + 1; j < n; ++j)
        key.push_back(std::llround(std::hypot(rel[3 * j] - rel[3 * k], rel[3 * j + 1] - rel[3 * k + 1], rel[3 * j + 2] - rel[3 * k + 2]) / unit));
    }
    // An earlier shape that maps onto this clump by a rotation: q = rotation x that shape's orientation.
    const Shape *shape = nullptr;
    PetscReal    q[4];
    for (const Shape &sh : cache[key]) {
      PetscReal r[4], worst = 0;
      rigid::BestRotation((int)n, sh.rel.data(), rel.data(), r);
      for (PetscInt k = 0; k < n; ++k) {
        PetscReal y[3];
        rigid::QuatRotate(r, &sh.rel[3 * k], y);
        for (int d = 0; d < 3; ++d) worst = std::max(worst, std::fabs(y[d] - rel[3 * k + d]));
      }
      if (worst > 1e-6 * a.radius[p0]) continue;
      PetscReal q0[4];
      rigid::QuatFromMatrix(sh.t.axes, q0);
      rigid::QuatMultiply(r, q0, q);
      shape = &sh;
      break;
    }
    if (!shape) {
      Shape sh;
      for (PetscInt k = 0; k < n; ++k) {
        ClumpSphere s;
        for (int d = 0; d < 3; ++d) s.x[d] = rel[3 * k + d];
        s.r = a.radius[m[k]];
        sh.t.spheres.push_back(s);
      }
      sh.t.Compute();
      ++shapes_;
      sh.rel = rel;
      cache[key].push_back(sh);
      shape = &cache[key].back();
      rigid::QuatFromMatrix(shape->t.axes, q);
    }
    const ClumpTemplate &t   = shape->t;
    const PetscReal      rho = typeDensity[a.type[p0]], M = rho * t.volume;
    PetscReal            V[3] = {0, 0, 0}, w[3] = {0, 0, 0};
    for (PetscInt p : m)
      for (int d = 0; d < 3; ++d) V[d] += a.v[3 * p + d] / n, w[d] += a.omega[3 * p + d] / n;
    for (PetscInt k = 0; k < n; ++k) {
      const PetscInt p = m[k];
      PetscReal     *g = &a.rigid[kRigidWidth * p], rb[3], wxr[3];
      for (int c = 0; c < 4; ++c) g[rigid::kQ + c] = q[c];
      for (int d = 0; d < 3; ++d) g[rigid::kBody + d] = t.body[3 * k + d], g[rigid::kInertia + d] = rho * t.principal[d];
      g[rigid::kMass] = M;
      a.mass[p]       = M / n;
      rigid::QuatRotate(q, &g[rigid::kBody], rb);
      Cross(w, rb, wxr);
      for (int d = 0; d < 3; ++d) a.v[3 * p + d] = V[d] + wxr[d], a.omega[3 * p + d] = w[d];
    }
  }
  Flatten();  // the members sorted by id above
  any_ = *count > 0;
  PetscFunctionReturn(0);
}

void Clumps::Kick(const ParticleArrays &a, PetscReal dt, bool drift) const {
  if (!any_) return;
  Group(a);
  PetscReal *rb = scratch_.data();  // R b_k of each member of the clump at hand
  for (size_t cl = 0; cl + 1 < start_.size(); ++cl) {
    const PetscInt  *m = &order_[start_[cl]], n = start_[cl + 1] - start_[cl], p0 = m[0];
    const PetscReal *g = &a.rigid[kRigidWidth * p0], *I = g + rigid::kInertia, M = g[rigid::kMass];
    const PetscReal  q[4] = {g[rigid::kQ], g[rigid::kQ + 1], g[rigid::kQ + 2], g[rigid::kQ + 3]};
    PetscReal        R[9], F[3] = {0, 0, 0}, T[3] = {0, 0, 0}, c[3], V[3], L[3], wb[3], Lb[3];
    RotationMatrix(q, R);
    for (PetscInt k = 0; k < n; ++k) {
      const PetscInt p = m[k];
      // The member's weight m_k g is its share of M g, which acts at the centroid: no torque.
      const PetscReal fc[3] = {a.f[3 * p] - a.mass[p] * gravity_[0], a.f[3 * p + 1] - a.mass[p] * gravity_[1], a.f[3 * p + 2] - a.mass[p] * gravity_[2]};
      Apply(R, &a.rigid[kRigidWidth * p + rigid::kBody], &rb[3 * k]);
      Cross(&rb[3 * k], fc, c);
      for (int d = 0; d < 3; ++d) F[d] += a.f[3 * p + d], T[d] += a.torque[3 * p + d] + c[d];
    }
    // The body's velocity and angular momentum, from its first member.
    Cross(&a.omega[3 * p0], rb, c);
    for (int d = 0; d < 3; ++d) V[d] = a.v[3 * p0 + d] - c[d] + 0.5 * dt * F[d] / M;
    ApplyTranspose(R, &a.omega[3 * p0], wb);
    for (int d = 0; d < 3; ++d) Lb[d] = I[d] * wb[d];
    Apply(R, Lb, L);
    for (int d = 0; d < 3; ++d) L[d] += 0.5 * dt * T[d];
    PetscReal qn[4] = {q[0], q[1], q[2], q[3]}, Rn[9];
    if (drift) {
      PetscReal th[3], qm[4], Rm[9];
      BodyOmega(R, I, L, wb);
      for (int d = 0; d < 3; ++d) th[d] = 0.5 * dt * wb[d];
      QuatStep(q, th, qm);
      RotationMatrix(qm, Rm);
      BodyOmega(Rm, I, L, wb);
      for (int d = 0; d < 3; ++d) th[d] = dt * wb[d];
      QuatStep(q, th, qn);
      RotationMatrix(qn, Rn);
    } else {
      for (int k = 0; k < 9; ++k) Rn[k] = R[k];
    }
    PetscReal w[3];
    BodyOmega(Rn, I, L, wb);
    Apply(Rn, wb, w);
    for (PetscInt k = 0; k < n; ++k) {
      const PetscInt p  = m[k];
      PetscReal     *gp = &a.rigid[kRigidWidth * p], rn[3];
      if (drift) Apply(Rn, gp + rigid::kBody, rn);
      else
        for (int d = 0; d < 3; ++d) rn[d] = rb[3 * k + d];
      Cross(w, rn, c);
      for (int d = 0; d < 3; ++d) {
        if (drift) a.x[3 * p + d] += dt * V[d] + rn[d] - rb[3 * k + d];
        a.v[3 * p + d] = V[d] + c[d], a.omega[3 * p + d] = w[d];
      }
      for (int k4 = 0; k4 < 4; ++k4) gp[rigid::kQ + k4] = qn[k4];
    }
  }
}

void Clumps::Energy(const ParticleArrays &a, PetscReal *translational, PetscReal *rotational) const {
  *translational = *rotational = 0;
  if (!any_) return;
  Group(a);
  for (size_t cl = 0; cl + 1 < start_.size(); ++cl) {
    const PetscInt   p0 = order_[start_[cl]];
    const PetscReal *g = &a.rigid[kRigidWidth * p0], *q = g + rigid::kQ, *I = g + rigid::kInertia;
    PetscReal        rb[3], c[3], wb[3], V2 = 0;
    rigid::QuatRotate(q, g + rigid::kBody, rb);
    Cross(&a.omega[3 * p0], rb, c);
    for (int d = 0; d < 3; ++d) V2 += (a.v[3 * p0 + d] - c[d]) * (a.v[3 * p0 + d] - c[d]);
    rigid::QuatRotateInverse(q, &a.omega[3 * p0], wb);
    *translational += 0.5 * g[rigid::kMass] * V2;
    *rotational += 0.5 * (I[0] * wb[0] * wb[0] + I[1] * wb[1] * wb[1] + I[2] * wb[2] * wb[2]);
  }
}

}  // namespace vofdem
