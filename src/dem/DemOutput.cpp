// Particle and contact-network output (XDMF + HDF5) and the Love-Weber stress of a region.
//
// Files: <output_dir>/particles_<step>.h5 and contacts_<step>.h5, one per output, indexed by
// particles.xmf and contacts.xmf (temporal collections, rewritten atomically at each output).
// Particles are written in id order when the ids are 0..N-1 (always so until particles can be
// removed), else in rank order; contacts in rank order. Values do not depend on the rank count.
#include "vofdem/dem/Dem.hpp"

#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/io/TextFile.hpp"

#include <petscviewerhdf5.h>

#include <cmath>
#include <cstdio>

namespace vofdem {

namespace {

// The particle type for output: the index into -dem_types.
inline PetscReal ParticleTypeOf(const ParticleArrays &a, PetscInt p) { return (PetscReal)a.type[p]; }

// Writes `values` (bs per item, local items in `index` order or contiguous by rank when index is
// null) as dataset `name` of `viewer`, a Vec of `total` items.
PetscErrorCode WriteItems(PetscViewer viewer, MPI_Comm comm, const char *name, PetscInt bs, PetscInt total, const std::vector<PetscReal> &values,
                          const std::vector<PetscInt> *index) {
  Vec v;

  PetscFunctionBeginUser;
  if (index) {
    PetscCall(VecCreate(comm, &v));
    PetscCall(VecSetSizes(v, PETSC_DECIDE, total * bs));
    PetscCall(VecSetBlockSize(v, bs));
    PetscCall(VecSetType(v, VECMPI));
    PetscCall(VecSetValuesBlocked(v, (PetscInt)index->size(), index->data(), values.data(), INSERT_VALUES));
    PetscCall(VecAssemblyBegin(v));
    PetscCall(VecAssemblyEnd(v));
  } else {
    PetscCall(VecCreateMPIWithArray(comm, bs, (PetscInt)values.size(), total * bs, values.data(), &v));
  }
  PetscCall(PetscObjectSetName((PetscObject)v, name));
  PetscCall(VecView(v, viewer));
  PetscCall(VecDestroy(&v));
  PetscFunctionReturn(0);
}

std::string StepFile(const char *kind, PetscInt step) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%s_%06d.h5", kind, (int)step);
  return buf;
}

}  // namespace

// The index entries of one output: particles (N points) or contacts (M segments, 2M points).
XdmfEntry DemOutputSettings::ParticleEntry(PetscInt step, PetscReal time, PetscInt N) {
  XdmfEntry e;
  e.time = time, e.step = step, e.file = StepFile("particles", step), e.nodes = N;
  e.attributes = {{"radius", "/radius"},     {"velocity", "/velocity", 3}, {"angular_velocity", "/angular_velocity", 3}, {"id", "/id"},
                  {"type", "/type"},         {"clump", "/clump"},          {"contacts", "/contacts"},    {"contact_force", "/contact_force"}};
  return e;
}

XdmfEntry DemOutputSettings::ContactEntry(PetscInt step, PetscReal time, PetscInt M) {
  XdmfEntry e;
  e.time = time, e.step = step, e.file = StepFile("contacts", step), e.nodes = 2 * M, e.segments = M;
  e.attributes = {{"ids", "/ids", 2, true}, {"normal_force", "/normal_force", 3, true}, {"tangential_force", "/tangential_force", 3, true},
                  {"force_magnitude", "/force_magnitude", 1, true}};
  return e;
}

namespace {

}  // namespace

PetscErrorCode DemOutputSettings::SetFromOptions(MPI_Comm comm) {
  PetscBool lowerSet = PETSC_FALSE, upperSet = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, "dem_", "Particle output and analysis (DEM)", "Dem");
  {
    OptionReader opt(PetscOptionsObject);
    PetscCall(opt.Int("-output_every", "Write particles (XDMF + HDF5, particles.xmf in -output_dir) every this many steps (0: never)", &particlesEvery, 0));
    PetscCall(opt.Int("-contacts_every", "Write the contact network (XDMF + HDF5, contacts.xmf in -output_dir) every this many steps (0: never)", &contactsEvery, 0));
    PetscCall(opt.RealVector("-stress_lower", "Lower corner of the region whose Love-Weber stress is monitored", "m", stressLower, 3, RealRange::Any(), &lowerSet));
    PetscCall(opt.RealVector("-stress_upper", "Upper corner of the region whose Love-Weber stress is monitored", "m", stressUpper, 3, RealRange::Any(), &upperSet));
    PetscCall(opt.Bool("-stress_kinetic", "Add the kinetic part sum m v (x) v / V of the particles whose centre is in the region to the stress", &stressKinetic));
  }
  PetscOptionsEnd();
  if (lowerSet != upperSet) VofdemInputError(comm, "option %s: give both -dem_stress_lower and -dem_stress_upper", lowerSet ? "-dem_stress_lower" : "-dem_stress_upper");
  for (int d = 0; d < 3 && lowerSet; ++d)
    if (!(stressUpper[d] > stressLower[d]))
      VofdemInputError(comm, "option -dem_stress_upper: must exceed -dem_stress_lower in %c (%g <= %g)", "xyz"[d], (double)stressUpper[d], (double)stressLower[d]);
  stress = lowerSet;
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::SetOutputDir(const std::string &dir) {
  PetscFunctionBeginUser;
  if (dir.empty() && out_.particlesEvery > 0) VofdemInputError(comm_, "option -dem_output_every needs -output_dir (the folder for the files)");
  if (dir.empty() && out_.contactsEvery > 0) VofdemInputError(comm_, "option -dem_contacts_every needs -output_dir (the folder for the files)");
  out_.dir = dir;
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::WriteOutput(PetscReal time) {
  PetscFunctionBeginUser;
  if (out_.dir.empty()) PetscFunctionReturn(0);
  if (out_.particlesEvery > 0 && steps_ % out_.particlesEvery == 0) PetscCall(WriteParticles(time));
  if (out_.contactsEvery > 0 && steps_ % out_.contactsEvery == 0) PetscCall(WriteContacts(time));
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::WriteParticles(PetscReal time) {
  ParticleArrays a;
  PetscInt       N;
  PetscViewer    viewer;

  PetscFunctionBeginUser;
  PetscCheck(record_.on, comm_, PETSC_ERR_PLIB, "particle output at step %" PetscInt_FMT " without recorded contact forces", steps_);
  PetscCall(swarm_.GlobalCount(&N));
  if (N == 0) PetscFunctionReturn(0);
  PetscCall(swarm_.GetArrays(&a));
  const PetscInt n = a.n;
  // Contacts of each local particle (particles and walls) and the sum of their |F| (record_).
  std::vector<PetscReal> contacts(n, 0), forceSum(n, 0);
  for (size_t k = 0; k < list_.Size(); ++k) {
    if (!list_.touching[k]) continue;
    const PetscReal *F = &record_.pair[ContactRecord::kWidth * k], mag = std::sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]);
    for (PetscInt i : {list_.first[k], list_.second[k]})
      if (i < n) contacts[i] += 1, forceSum[i] += mag;
  }
  for (size_t k = 0; k < walls_.Size(); ++k) {
    if (!walls_.touching[k]) continue;
    const PetscReal *F = &record_.wall[ContactRecord::kWidth * k];
    contacts[walls_.particle[k]] += 1, forceSum[walls_.particle[k]] += std::sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]);
  }
  // Id order when the ids are exactly 0..N-1 (unique, so the largest decides); else rank order.
  PetscInt64 maxId = -1, globalMax;
  for (PetscInt p = 0; p < n; ++p) maxId = std::max(maxId, a.id[p]);
  PetscCallMPI(MPI_Allreduce(&maxId, &globalMax, 1, MPIU_INT64, MPI_MAX, comm_));
  std::vector<PetscInt> index(n);
  if (globalMax == N - 1) {
    for (PetscInt p = 0; p < n; ++p) index[p] = (PetscInt)a.id[p];
  } else {
    PetscInt offset = 0;
    PetscCallMPI(MPI_Exscan(&a.n, &offset, 1, MPIU_INT, MPI_SUM, comm_));
    for (PetscInt p = 0; p < n; ++p) index[p] = offset + p;
  }
  const std::string file = StepFile("particles", steps_);
  PetscCall(PetscViewerHDF5Open(comm_, (out_.dir + "/" + file).c_str(), FILE_MODE_WRITE, &viewer));
  std::vector<PetscReal> buf;
  auto column = [&](const char *name, PetscInt bs, auto value) -> PetscErrorCode {
    PetscFunctionBeginUser;
    buf.resize((size_t)n * bs);
    for (PetscInt p = 0; p < n; ++p)
      for (PetscInt c = 0; c < bs; ++c) buf[(size_t)p * bs + c] = value(p, c);
    PetscCall(WriteItems(viewer, comm_, name, bs, N, buf, &index));
    PetscFunctionReturn(0);
  };
  PetscCall(column("position", 3, [&](PetscInt p, PetscInt c) { return a.x[3 * p + c]; }));
  PetscCall(column("radius", 1, [&](PetscInt p, PetscInt) { return a.radius[p]; }));
  PetscCall(column("velocity", 3, [&](PetscInt p, PetscInt c) { return a.v[3 * p + c]; }));
  PetscCall(column("angular_velocity", 3, [&](PetscInt p, PetscInt c) { return a.omega[3 * p + c]; }));
  PetscCall(column("id", 1, [&](PetscInt p, PetscInt) { return (PetscReal)a.id[p]; }));
  PetscCall(column("type", 1, [&](PetscInt p, PetscInt) { return ParticleTypeOf(a, p); }));
  PetscCall(column("clump", 1, [&](PetscInt p, PetscInt) { return (PetscReal)a.clump[p]; }));  // -1: a loose sphere (vofdem-analyze groups the members)
  PetscCall(column("contacts", 1, [&](PetscInt p, PetscInt) { return contacts[p]; }));
  PetscCall(column("contact_force", 1, [&](PetscInt p, PetscInt) { return forceSum[p]; }));
  if (swarm_.HasHeatFields()) PetscCall(column("temperature", 1, [&](PetscInt p, PetscInt) { return a.temperature[p]; }));  // K (P11)
  PetscCall(PetscViewerDestroy(&viewer));
  PetscCall(swarm_.RestoreArrays(&a));

  out_.particleEntries.push_back(DemOutputSettings::ParticleEntry(steps_, time, N));
  if (swarm_.HasHeatFields()) out_.particleEntries.back().attributes.push_back({"temperature", "/temperature"});
  PetscCall(WriteTextFile(comm_, out_.dir + "/particles.xmf", XdmfIndexText("particles", out_.particleEntries), "option -dem_output_every"));
  PetscFunctionReturn(0);
}

PetscErrorCode Dem::WriteContacts(PetscReal time) {
  ParticleArrays a;
  PetscViewer    viewer;

  PetscFunctionBeginUser;
  PetscCheck(record_.on, comm_, PETSC_ERR_PLIB, "contact output at step %" PetscInt_FMT " without recorded contact forces", steps_);
  PetscCall(swarm_.GetArrays(&a));
  const PetscInt n = a.n;
  auto pos = [&](PetscInt j) { return j < n ? &a.x[3 * j] : &halo_.x[3 * (j - n)]; };
  auto idOf = [&](PetscInt j) { return j < n ? a.id[j] : halo_.id[j - n]; };
  // Each touching pair once: by the rank that holds its lower id (the first of the pair).
  std::vector<PetscReal> ids, points, normal, tangential, magnitude;
  for (size_t k = 0; k < list_.Size(); ++k) {
    if (!list_.touching[k] || list_.first[k] >= n) continue;
    const PetscReal *F = &record_.pair[ContactRecord::kWidth * k], *Ft = F + 3;
    ids.push_back((PetscReal)idOf(list_.first[k])), ids.push_back((PetscReal)idOf(list_.second[k]));
    points.insert(points.end(), pos(list_.first[k]), pos(list_.first[k]) + 3);
    points.insert(points.end(), pos(list_.second[k]), pos(list_.second[k]) + 3);
    for (int e = 0; e < 3; ++e) normal.push_back(F[e] - Ft[e]), tangential.push_back(Ft[e]);
    magnitude.push_back(std::sqrt(F[0] * F[0] + F[1] * F[1] + F[2] * F[2]));
  }
  PetscCall(swarm_.RestoreArrays(&a));
  PetscInt m = (PetscInt)magnitude.size(), M = 0, offset = 0;
  PetscCallMPI(MPI_Allreduce(&m, &M, 1, MPIU_INT, MPI_SUM, comm_));
  PetscCallMPI(MPI_Exscan(&m, &offset, 1, MPIU_INT, MPI_SUM, comm_));
  if (M == 0) PetscFunctionReturn(0);  // nothing to draw (an empty dataset is not written)
  std::vector<PetscReal> connectivity(2 * m);
  for (PetscInt k = 0; k < 2 * m; ++k) connectivity[k] = 2 * offset + k;
  const std::string file = StepFile("contacts", steps_);
  PetscCall(PetscViewerHDF5Open(comm_, (out_.dir + "/" + file).c_str(), FILE_MODE_WRITE, &viewer));
  PetscCall(WriteItems(viewer, comm_, "position", 3, 2 * M, points, nullptr));
  PetscCall(WriteItems(viewer, comm_, "connectivity", 2, M, connectivity, nullptr));
  PetscCall(WriteItems(viewer, comm_, "ids", 2, M, ids, nullptr));
  PetscCall(WriteItems(viewer, comm_, "normal_force", 3, M, normal, nullptr));
  PetscCall(WriteItems(viewer, comm_, "tangential_force", 3, M, tangential, nullptr));
  PetscCall(WriteItems(viewer, comm_, "force_magnitude", 1, M, magnitude, nullptr));
  PetscCall(PetscViewerDestroy(&viewer));
  out_.contactEntries.push_back(DemOutputSettings::ContactEntry(steps_, time, M));
  PetscCall(WriteTextFile(comm_, out_.dir + "/contacts.xmf", XdmfIndexText("contacts", out_.contactEntries), "option -dem_contacts_every"));
  PetscFunctionReturn(0);
}

// Love-Weber stress of the region R, compression positive:
//   sigma = (1/V) [ sum over pairs with contact point in R of F (x) (x_a - x_b)
//                 + sum over wall contacts with contact point in R of F (x) (x_p - x_c) ],
// F the force on a (the lower id) or on the particle, x_c the point of the face under the particle.
// Reported: the symmetric part (xx, yy, zz, xy, xz, yz), Pa. Each pair is counted by the rank that
// holds its lower id; the sum is over ranks. With -dem_stress_kinetic the kinetic part
// (1/V) sum m v (x) v over the particles whose centre is in R is added (positive, like a pressure).
PetscErrorCode Dem::Stress(PetscReal sigma[6]) const {
  ParticleArrays a;
  PetscReal      s[9] = {0}, g[9];

  PetscFunctionBeginUser;
  PetscCheck(out_.stress && record_.on, comm_, PETSC_ERR_PLIB, "stress without a region or without recorded contact forces");
  const PetscReal *lo = out_.stressLower, *hi = out_.stressUpper;
  auto inside = [&](const PetscReal x[3]) { return x[0] >= lo[0] && x[0] <= hi[0] && x[1] >= lo[1] && x[1] <= hi[1] && x[2] >= lo[2] && x[2] <= hi[2]; };
  PetscCall(swarm_.GetArrays(&a));
  const PetscInt n = a.n;
  for (size_t k = 0; k < list_.Size(); ++k) {
    if (!list_.touching[k] || list_.first[k] >= n) continue;
    const PetscInt   ia = list_.first[k], ib = list_.second[k];
    const PetscReal *xa = &a.x[3 * ia], *xb = ib < n ? &a.x[3 * ib] : &halo_.x[3 * (ib - n)];
    const PetscReal  rb = ib < n ? a.radius[ib] : halo_.radius[ib - n], ra = a.radius[ia];
    const PetscReal  l[3] = {xa[0] - xb[0], xa[1] - xb[1], xa[2] - xb[2]}, d = std::sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
    // Contact point: the middle of the overlap on the line of centres.
    const PetscReal t = (rb + 0.5 * (d - ra - rb)) / d, xc[3] = {xb[0] + t * l[0], xb[1] + t * l[1], xb[2] + t * l[2]};
    if (!inside(xc)) continue;
    const PetscReal *F = &record_.pair[ContactRecord::kWidth * k];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) s[3 * i + j] += F[i] * l[j];
  }
  for (size_t k = 0; k < walls_.Size(); ++k) {
    if (!walls_.touching[k]) continue;
    const PetscInt   p = walls_.particle[k];
    const int        face = walls_.wall[k], dim = face / 2;
    const PetscReal *x = &a.x[3 * p];
    PetscReal        xc[3] = {x[0], x[1], x[2]};
    xc[dim]                = face % 2 ? grid_->Upper()[dim] : grid_->Lower()[dim];
    if (!inside(xc)) continue;
    const PetscReal *F = &record_.wall[ContactRecord::kWidth * k];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) s[3 * i + j] += F[i] * (x[j] - xc[j]);
  }
  for (PetscInt p = 0; p < n && out_.stressKinetic; ++p) {
    if (!inside(&a.x[3 * p])) continue;
    const PetscReal *v = &a.v[3 * p];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) s[3 * i + j] += a.mass[p] * v[i] * v[j];
  }
  PetscCall(swarm_.RestoreArrays(&a));
  PetscCallMPI(MPI_Allreduce(s, g, 9, MPIU_REAL, MPIU_SUM, comm_));
  const PetscReal V = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
  sigma[0] = g[0] / V, sigma[1] = g[4] / V, sigma[2] = g[8] / V;
  sigma[3] = 0.5 * (g[1] + g[3]) / V, sigma[4] = 0.5 * (g[2] + g[6]) / V, sigma[5] = 0.5 * (g[5] + g[7]) / V;
  PetscFunctionReturn(0);
}

std::string Dem::MonitorHeader() const { return out_.stress ? ",stress_xx_Pa,stress_yy_Pa,stress_zz_Pa,stress_xy_Pa,stress_xz_Pa,stress_yz_Pa" : ""; }

PetscErrorCode Dem::MonitorValues(std::string *csv, std::string *screen) const {
  PetscReal s[6];
  char      buf[256];

  PetscFunctionBeginUser;
  csv->clear(), screen->clear();
  if (!out_.stress) PetscFunctionReturn(0);
  PetscCall(Stress(s));
  std::snprintf(buf, sizeof buf, ",%.10e,%.10e,%.10e,%.10e,%.10e,%.10e", (double)s[0], (double)s[1], (double)s[2], (double)s[3], (double)s[4], (double)s[5]);
  *csv = buf;
  std::snprintf(buf, sizeof buf, "  stress zz %.6e Pa", (double)s[2]);
  *screen = buf;
  PetscFunctionReturn(0);
}

}  // namespace vofdem
