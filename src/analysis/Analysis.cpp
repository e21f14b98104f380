// -analysis_* options, the metrics of a set of spheres, and their CSV files (Analysis.hpp).
#include "vofdem/analysis/Analysis.hpp"

#include "vofdem/base/Options.hpp"
#include "vofdem/base/Runtime.hpp"
#include "vofdem/io/TextFile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

namespace vofdem {

using namespace analysis;

namespace {
const std::vector<std::string> kMetrics = {"all", "packing", "rings", "coordination", "pores", "surface", "segregation", "repose"};

std::string Num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}

std::string HistogramCsv(const Histogram &h, const char *unit) {
  long total = 0;
  for (long c : h.count) total += c;
  std::string t = std::string("bin_lo_") + unit + ",bin_hi_" + unit + ",count,fraction\n";
  for (size_t b = 0; b < h.count.size(); ++b)
    t += Num(h.lo[b]) + "," + Num(h.hi[b]) + "," + std::to_string(h.count[b]) + "," + Num(total ? (double)h.count[b] / total : 0) + "\n";
  return t;
}

double Mean(const std::vector<double> &v) {
  double s = 0;
  for (double x : v) s += x;
  return v.empty() ? 0 : s / v.size();
}
}  // namespace

PetscErrorCode PowderAnalysis::SetFromOptions(MPI_Comm comm, const std::vector<std::string> &defaultMetrics, const std::string &defaultDir) {
  PetscBool lowerSet = PETSC_FALSE, upperSet = PETSC_FALSE, dirSet = PETSC_FALSE, ringRadiusSet = PETSC_FALSE;
  std::vector<std::string> names = defaultMetrics;

  PetscFunctionBeginUser;
  comm_ = comm;
  PetscOptionsBegin(comm, "analysis_", "Powder-bed analysis at the end of the run (src/analysis)", "Analysis");
  {
    OptionReader opt(PetscOptionsObject);
    PetscCall(opt.NameList("-metrics", "Metrics to compute at the end: packing,rings,coordination,pores,surface,segregation,repose; all: every one but repose, which needs a pile (default: none)", kMetrics, &names));
    PetscCall(opt.String("-dir", "Folder for the analysis CSV files (default: <-output_dir>/analysis)", &dir_, &dirSet));
    PetscCall(opt.RealVector("-lower", "Lower corner of the analysed window (default: the box)", "m", lower_, 3, RealRange::Any(), &lowerSet));
    PetscCall(opt.RealVector("-upper", "Upper corner of the analysed window (default: the box)", "m", upper_, 3, RealRange::Any(), &upperSet));
    PetscCall(opt.Real("-contact_gap", "Spheres closer than r_i + r_j + this count as in contact (0: overlap > 0)", "m", &gap_, RealRange::NonNegative()));
    PetscCall(opt.Int("-rings", "Number of cutting rings (vertical cylinders) along x through the window's middle", &rings_, 1, 100000));
    PetscCall(opt.Real("-ring_radius", "Radius of the cutting rings (default: half the ring pitch or of the window's y extent, the smaller)", "m", &ringRadius_, RealRange::Positive(), &ringRadiusSet));
    PetscCall(opt.Real("-ray_spacing", "Spacing of the ray grid cast down onto the layer (seed 001: 2 um)", "m", &spacing_, RealRange::Positive()));
    PetscCall(opt.Int("-line_rays", "Rays along x on the window's centre line, for Ra (seed 002: 500)", &lineRays_, 2, 100000000));
    PetscCall(opt.Real("-substrate", "Height a ray reads when it meets no sphere (default: the window's lower z)", "m", &substrate_, RealRange::Any(), &substrateSet_));
    PetscCall(opt.Bool("-allow_empty", "A window holding no particle centre at the end is a result (particles_in_window 0 and, if asked for, the packing density in summary.csv; no other metric), not an error: for sweeps whose fast blades may leave the layer bare",
                       &allowEmpty_));
    PetscCall(opt.Bool("-surface_grid", "Write every ray height (surface_grid.csv) as well as the centre line", &surfaceGrid_));
    PetscCall(opt.IntVector("-segregation_cells", "Cells of the window in x,y,z for the segregation index (seed 001: 10,1,1)", cells_, 3, 1, 100000));
    PetscCall(opt.Real("-reference_radius", "Reference mean radius of the segregation index (default: the mean of all particles analysed)", "m", &referenceRadius_, RealRange::Positive()));
    PetscCall(opt.RealVector("-repose_axis", "x,y of the pile's axis (default: the centroid of the heights above the substrate)", "m", reposeAxis_, 2, RealRange::Any(), &reposeAxisSet_));
    PetscCall(opt.RealVector("-repose_fit", "Fractions of the pile height between which the slope is fitted", "", reposeFit_, 2, RealRange::Closed(0, 1)));
    PetscCall(opt.Real("-repose_base", "Diameter D of the pile's base for seed 001's angle atan(2 H/D), H the pile's height (default: the window's smaller horizontal extent)", "m",
                       &reposeBase_, RealRange::Positive()));
    PetscCall(opt.Int("-bins", "Bins of the pore histograms", &bins_, 1, 100000));
    PetscCall(opt.Int("-clump_resolution", "Quadrature columns per largest member diameter for the overlaps of clump members cut by the window or a ring (64: ~4e-4 of the volume where two members overlap)",
                      &clumpResolution_, 4, 4096));
  }
  PetscOptionsEnd();
  windowSet_ = (lowerSet || upperSet) ? PETSC_TRUE : PETSC_FALSE;
  if (lowerSet != upperSet) VofdemInputError(comm, "option %s: give both -analysis_lower and -analysis_upper", lowerSet ? "-analysis_lower" : "-analysis_upper");
  for (int d = 0; d < 3 && windowSet_; ++d)
    if (!(upper_[d] > lower_[d]))
      VofdemInputError(comm, "option -analysis_upper: the analysis window is empty: upper must exceed lower in %c (%g <= %g)", "xyz"[d], (double)upper_[d], (double)lower_[d]);
  if (!(reposeFit_[1] > reposeFit_[0])) VofdemInputError(comm, "option -analysis_repose_fit: the upper fraction must exceed the lower (%g <= %g)", (double)reposeFit_[1], (double)reposeFit_[0]);
  if (ringRadiusSet) ringRadius_ = -ringRadius_;  // negative: given (the default depends on the window)
  metrics_.clear();
  for (const auto &n : names)
    if (n == "all") metrics_.assign(kMetrics.begin() + 1, kMetrics.end() - 1);  // all but repose
  for (const auto &n : names)
    if (n != "all" && !Wants(n.c_str())) metrics_.push_back(n);
  if (!Enabled()) PetscFunctionReturn(0);
  if (!dirSet) dir_ = defaultDir;
  if (dir_.empty()) VofdemInputError(comm, "option -analysis_metrics: give -analysis_dir or -output_dir (the folder for the analysis files)");
  PetscFunctionReturn(0);
}

bool PowderAnalysis::Wants(const char *metric) const { return std::find(metrics_.begin(), metrics_.end(), metric) != metrics_.end(); }

PetscErrorCode PowderAnalysis::SetUp(const Window *box) {
  PetscMPIInt rank;

  PetscFunctionBeginUser;
  if (!Enabled()) PetscFunctionReturn(0);
  for (int d = 0; d < 3 && box && windowSet_; ++d)
    if (!(upper_[d] > box->lo[d] && lower_[d] < box->hi[d]))
      VofdemInputError(comm_, "options -analysis_lower/-analysis_upper: the window [%g, %g] m in %c lies outside the box [%g, %g] m", (double)lower_[d], (double)upper_[d], "xyz"[d],
                       box->lo[d], box->hi[d]);
  PetscCallMPI(MPI_Comm_rank(comm_, &rank));
  if (rank == 0) {
    std::error_code ec;
    std::filesystem::create_directories(dir_, ec);
  }
  PetscCall(CheckWritable(comm_, dir_ + "/summary.csv", "option -analysis_dir"));
  PetscFunctionReturn(0);
}

PetscErrorCode PowderAnalysis::Write(const std::string &name, const std::string &text) const {
  PetscFunctionBeginUser;
  PetscCall(WriteTextFile(comm_, dir_ + "/" + name, text, "option -analysis_dir"));
  PetscFunctionReturn(0);
}

PetscErrorCode PowderAnalysis::Run(const Spheres &s, const Window &box, const std::string &what) {
  Window                                        w = box;
  std::vector<std::pair<std::string, std::string>> summary;  // name, value and unit
  auto add = [&](const std::string &name, double v, const char *unit) { summary.emplace_back(name, Num(v) + "," + unit); };

  PetscFunctionBeginUser;
  if (!Enabled()) PetscFunctionReturn(0);
  if (windowSet_)
    for (int d = 0; d < 3; ++d) w.lo[d] = lower_[d], w.hi[d] = upper_[d];
  if (w.Empty()) VofdemInputError(comm_, "analysis: the window [%g,%g]x[%g,%g]x[%g,%g] m is empty", w.lo[0], w.hi[0], w.lo[1], w.hi[1], w.lo[2], w.hi[2]);
  const std::vector<std::size_t> in = CentresIn(s, w);
  if (in.empty() && !allowEmpty_)
    VofdemInputError(comm_, "analysis of %s: no particle centre in the window [%g,%g]x[%g,%g]x[%g,%g] m (%ld particles in all); move it with -analysis_lower/-analysis_upper (or -analysis_allow_empty)",
                     what.c_str(), w.lo[0], w.hi[0], w.lo[1], w.hi[1], w.lo[2], w.hi[2], (long)s.Size());
  PetscCall(PetscPrintf(comm_, "analysis of %s: %ld of %ld particles in the window [%g,%g]x[%g,%g]x[%g,%g] m; files in %s\n", what.c_str(), (long)in.size(), (long)s.Size(), w.lo[0],
                        w.hi[0], w.lo[1], w.hi[1], w.lo[2], w.hi[2], dir_.c_str()));
  add("particles_total", (double)s.Size(), "1");
  add("particles_in_window", (double)in.size(), "1");
  for (int d = 0; d < 3; ++d) add(std::string("window_lower_") + "xyz"[d], w.lo[d], "m"), add(std::string("window_upper_") + "xyz"[d], w.hi[d], "m");
  if (in.empty()) {
    // -analysis_allow_empty: a spreading sweep's fast blade can leave the window bare. That layer's packing
    // is the solid volume of the spheres reaching into it (often 0); the metrics of particles in it do not exist.
    if (Wants("packing")) {
      const double phi = PackingDensity(s, w, (int)clumpResolution_);
      add("packing_density", phi, "1");
      PetscCall(PetscPrintf(comm_, "  an empty layer (-analysis_allow_empty): packing density %.6f, no other metric\n", phi));
    } else {
      PetscCall(PetscPrintf(comm_, "  an empty layer (-analysis_allow_empty): no metric\n"));
    }
    PetscCall(WriteSummary(summary));
    PetscFunctionReturn(0);
  }
  add("mean_radius_in_window", [&] { double m = 0; for (std::size_t i : in) m += s.r[i]; return m / in.size(); }(), "m");

  if (Wants("packing")) {
    const double phi = PackingDensity(s, w, (int)clumpResolution_);
    add("packing_density", phi, "1");
    PetscCall(PetscPrintf(comm_, "  packing density %.6f (solid volume inside the window / window volume)\n", phi));
  }
  std::vector<int> z;
  if (Wants("coordination") || Wants("rings")) z = CoordinationNumbers(s, gap_);
  if (Wants("coordination")) {
    std::map<int, long> hist;
    double              mean = 0;
    long                particles = 0;  // clump members other than the first are not particles (-1)
    for (std::size_t i : in)
      if (z[i] >= 0) ++hist[z[i]], mean += z[i], ++particles;
    mean /= std::max(1L, particles);
    std::string t = "coordination,count,fraction\n";
    const int   top = hist.empty() ? 0 : hist.rbegin()->first;
    for (int c = 0; c <= top; ++c) t += std::to_string(c) + "," + std::to_string(hist[c]) + "," + Num((double)hist[c] / std::max(1L, particles)) + "\n";
    PetscCall(Write("coordination.csv", t));
    add("mean_coordination", mean, "1");
    PetscCall(PetscPrintf(comm_, "  mean coordination %.4f (contacts with gap < %g m; largest %d)\n", mean, (double)gap_, top));
  }
  if (Wants("rings")) {
    const double pitch  = (w.hi[0] - w.lo[0]) / rings_;
    const double radius = ringRadius_ < 0 ? -ringRadius_ : std::min(0.5 * pitch, 0.5 * (w.hi[1] - w.lo[1]));
    const auto   res    = SampleRings(s, RingsAlongX(w, (int)rings_, radius), z, (int)clumpResolution_);
    std::string  t      = "ring,x_m,y_m,radius_m,z0_m,z1_m,particles,packing_density,mean_coordination\n";
    double       phi = 0, zc = 0;
    for (size_t k = 0; k < res.size(); ++k) {
      const auto &g = res[k].ring;
      t += std::to_string(k) + "," + Num(g.x) + "," + Num(g.y) + "," + Num(g.outer) + "," + Num(g.z0) + "," + Num(g.z1) + "," + std::to_string(res[k].centres) + "," +
           Num(res[k].packing) + "," + Num(res[k].coordination) + "\n";
      phi += res[k].packing / res.size(), zc += res[k].coordination / res.size();
    }
    PetscCall(Write("rings.csv", t));
    add("rings_packing_density", phi, "1"), add("rings_mean_coordination", zc, "1");
    PetscCall(PetscPrintf(comm_, "  cutting rings (%d of radius %g m): packing density %.6f, mean coordination %.4f (means over the rings)\n", (int)rings_, radius, phi, zc));
  }
  if (Wants("pores")) {
    const PoreStats p = DelaunayPores(s, w);
    if (p.volume.empty()) {
      PetscCall(PetscPrintf(comm_, "  pores: no Delaunay tetrahedron (fewer than 4 centres, or all in a plane): skipped\n"));
    } else {
      const double rmax = *std::max_element(p.equivalentRadius.begin(), p.equivalentRadius.end());
      PetscCall(Write("pore_radius.csv", HistogramCsv(MakeHistogram(p.equivalentRadius, 0, rmax, (int)bins_), "m")));
      PetscCall(Write("pore_sphericity.csv", HistogramCsv(MakeHistogram(p.sphericity, 0, 0.7, (int)bins_), "1")));
      add("tetrahedra", (double)p.volume.size(), "1");
      add("tetrahedra_mean_equivalent_radius", Mean(p.equivalentRadius), "m");
      add("tetrahedra_mean_sphericity", Mean(p.sphericity), "1");
      PetscCall(PetscPrintf(comm_, "  Delaunay tetrahedra %ld: mean equivalent radius %g m, mean sphericity %.4f (regular: 0.671)\n", (long)p.volume.size(), Mean(p.equivalentRadius),
                            Mean(p.sphericity)));
    }
  }
  const double floor = substrateSet_ ? substrate_ : w.lo[2];
  if (Wants("surface") || Wants("repose")) {
    const Surface surf = CastRays(s, w, spacing_, floor);
    if (Wants("surface")) {
      const LineProfile line = CastLine(s, w, (int)lineRays_, floor);
      add("surface_rays_x", surf.nx, "1"), add("surface_rays_y", surf.ny, "1"), add("surface_ray_spacing", surf.spacing, "m");
      add("surface_x0", surf.x0, "m"), add("surface_y0", surf.y0, "m"), add("surface_substrate", floor, "m");
      add("surface_hits_fraction", (double)surf.hits / surf.z.size(), "1"), add("surface_mean_height", surf.mean, "m");
      add("Sa_std", surf.saStd, "m"), add("Sa_mean_abs", surf.saMeanAbs, "m"), add("Ra_line", line.ra, "m"), add("Rq_line", line.rq, "m");
      std::string t = "x_m,z_m\n";
      for (size_t i = 0; i < line.x.size(); ++i) t += Num(line.x[i]) + "," + Num(line.z[i]) + "\n";
      PetscCall(Write("surface_line.csv", t));
      if (surfaceGrid_) {
        std::string g;
        g.reserve(surf.z.size() * 14);
        for (int j = 0; j < surf.ny; ++j)
          for (int i = 0; i < surf.nx; ++i) g += Num(surf.z[(size_t)j * surf.nx + i]) + (i + 1 < surf.nx ? "," : "\n");
        PetscCall(Write("surface_grid.csv", g));
      }
      PetscCall(PetscPrintf(comm_, "  surface (%d x %d rays, %g m apart): Sa %g m (std. dev., seed 001), %g m (mean abs.); Ra %g m on the centre line (%d rays)\n", surf.nx,
                            surf.ny, surf.spacing, surf.saStd, surf.saMeanAbs, line.ra, (int)lineRays_));
    }
    if (Wants("repose")) {
      const ReposeFit fit = FitRepose(surf, floor, reposeAxisSet_ ? reposeAxis_ : nullptr, reposeFit_[0], reposeFit_[1]);
      if (fit.points < 2) VofdemInputError(comm_, "analysis of %s: no pile surface between %g and %g of the pile height to fit an angle of repose", what.c_str(), reposeFit_[0], reposeFit_[1]);
      add("repose_angle", fit.angleDeg, "deg"), add("repose_axis_x", fit.axis[0], "m"), add("repose_axis_y", fit.axis[1], "m");
      add("repose_pile_height", fit.height, "m"), add("repose_points", (double)fit.points, "1"), add("repose_intercept", fit.intercept, "m");
      // Seed 001's definition of its measured angle (fig. 6): atan(2 H/D), the pile's height over the cup's radius.
      const double base = reposeBase_ > 0 ? reposeBase_ : std::min(w.hi[0] - w.lo[0], w.hi[1] - w.lo[1]);
      add("repose_base", base, "m"), add("repose_angle_height", HeightReposeAngleDeg(fit.height, base), "deg");
      std::string  t      = "distance_m,z_m\n";
      const size_t stride = std::max<size_t>(1, fit.distance.size() / 5000);
      for (size_t i = 0; i < fit.distance.size(); i += stride) t += Num(fit.distance[i]) + "," + Num(fit.z[i]) + "\n";
      PetscCall(Write("repose.csv", t));
      PetscCall(PetscPrintf(comm_, "  angle of repose %.3f deg (line fitted to %ld surface points between %g and %g of the pile height %g m); atan(2 H/D) %.3f deg (seed 001's, D = %g m)\n",
                            fit.angleDeg, fit.points, reposeFit_[0], reposeFit_[1], fit.height, HeightReposeAngleDeg(fit.height, base), base));
    }
  }
  if (Wants("segregation")) {
    const int    cells[3] = {(int)cells_[0], (int)cells_[1], (int)cells_[2]};
    const double ref      = referenceRadius_ > 0 ? referenceRadius_ : s.MeanRadius();
    const auto   si       = Segregation(s, w, cells, ref);
    std::string  t        = "i,j,k,x_lo_m,x_hi_m,y_lo_m,y_hi_m,z_lo_m,z_hi_m,particles,mean_radius_m,segregation_index\n";
    double       lo = HUGE_VAL, hi = 0;
    for (const auto &c : si) {
      t += std::to_string(c.i) + "," + std::to_string(c.j) + "," + std::to_string(c.k);
      for (int d = 0; d < 3; ++d) t += "," + Num(c.box.lo[d]) + "," + Num(c.box.hi[d]);
      t += "," + std::to_string(c.centres) + "," + Num(c.meanRadius) + "," + Num(c.index) + "\n";
      if (c.centres) lo = std::min(lo, c.index), hi = std::max(hi, c.index);
    }
    PetscCall(Write("segregation.csv", t));
    add("segregation_reference_radius", ref, "m"), add("segregation_index_min", lo, "1"), add("segregation_index_max", hi, "1");
    PetscCall(PetscPrintf(comm_, "  segregation index per cell (%d x %d x %d, reference radius %g m): %.4f to %.4f\n", cells[0], cells[1], cells[2], ref, lo, hi));
  }
  PetscCall(WriteSummary(summary));
  PetscFunctionReturn(0);
}

PetscErrorCode PowderAnalysis::WriteSummary(const std::vector<std::pair<std::string, std::string>> &summary) const {
  std::string t = "metric,value,unit\n";

  PetscFunctionBeginUser;
  for (const auto &[name, value] : summary) t += name + "," + value + "\n";
  PetscCall(Write("summary.csv", t));
  PetscFunctionReturn(0);
}

}  // namespace vofdem
