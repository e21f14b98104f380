// Powder-bed analysis of a run's particles (-analysis_* options): at the end of a vofdem run, or by
// vofdem-analyze on a saved particles_<step>.h5 (DemOutput.cpp). The particles are gathered to
// every rank (a layer is tens of thousands of spheres), every rank computes the metrics of
// PowderMetrics.hpp, so that a refusal (an empty window) stops all ranks alike, and rank 0 writes
// CSV files into -analysis_dir (plots: scripts/plot_powder.py).
#pragma once

#include "vofdem/analysis/PowderMetrics.hpp"

#include <petscsys.h>

#include <string>
#include <utility>
#include <vector>

namespace vofdem {

class Dem;
class Grid;

class PowderAnalysis {
public:
  // Reads -analysis_*. `defaultMetrics`: what runs when -analysis_metrics is not given (empty: no
  // analysis; vofdem-analyze passes its own default). `defaultDir`: the folder when -analysis_dir is
  // not given (empty: then -analysis_dir is required once a metric is asked for).
  PetscErrorCode SetFromOptions(MPI_Comm comm, const std::vector<std::string> &defaultMetrics, const std::string &defaultDir);
  bool           Enabled() const { return !metrics_.empty(); }
  const std::string &Dir() const { return dir_; }
  // Collective: creates the folder and checks it can be written, and that a given window overlaps
  // `box` when there is one (before a long run, not after).
  PetscErrorCode SetUp(const analysis::Window *box = nullptr);
  // Collective: analyses the spheres; `box` is the default window (when -analysis_lower/upper are
  // not given) and `what` names the data in messages.
  PetscErrorCode Run(const analysis::Spheres &s, const analysis::Window &box, const std::string &what);

  // Collective: every particle of the run (position, radius, type) on every rank, with the grid's
  // periodic directions.
  static PetscErrorCode Gather(const Dem &dem, const Grid &grid, analysis::Spheres *s);
  // Collective: the particles of a particles_<step>.h5 file on every rank.
  static PetscErrorCode Read(MPI_Comm comm, const std::string &path, analysis::Spheres *s);

private:
  bool Wants(const char *metric) const;
  PetscErrorCode Write(const std::string &name, const std::string &text) const;
  // summary.csv: one row per metric, value and unit already formatted.
  PetscErrorCode WriteSummary(const std::vector<std::pair<std::string, std::string>> &summary) const;

  MPI_Comm                 comm_ = MPI_COMM_NULL;
  std::vector<std::string> metrics_;
  std::string              dir_;
  PetscReal                lower_[3] = {0, 0, 0}, upper_[3] = {0, 0, 0};
  PetscBool                windowSet_ = PETSC_FALSE;
  PetscReal                gap_ = 0, spacing_ = 2e-6, substrate_ = 0, referenceRadius_ = 0, ringRadius_ = 0;
  PetscBool                substrateSet_ = PETSC_FALSE;
  PetscInt                 rings_ = 9, lineRays_ = 500, bins_ = 30, cells_[3] = {10, 1, 1}, clumpResolution_ = analysis::kClumpResolution;
  PetscReal                reposeAxis_[2] = {0, 0}, reposeFit_[2] = {0.2, 0.8};
  PetscReal                reposeBase_    = 0;  // -analysis_repose_base; 0: the window's smaller horizontal extent
  PetscBool                reposeAxisSet_ = PETSC_FALSE, surfaceGrid_ = PETSC_TRUE, allowEmpty_ = PETSC_FALSE;
};

}  // namespace vofdem
