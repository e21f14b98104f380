// Surface heights by rays cast down onto the spheres, roughness, and the angle of repose
// (PowderMetrics.hpp).
#include "vofdem/analysis/PowderMetrics.hpp"

#include <algorithm>
#include <cmath>

namespace vofdem::analysis {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The spheres a downward ray over the window may meet (centre z in the window's range; periodic
// images in x and y), binned by their x-y extent so that a ray tests only its bin.
struct RayTargets {
  std::vector<double>       c;  // x, y, z, r per target
  std::vector<std::size_t>  start, items;
  double                    lo[2] = {0, 0}, h = 1;
  int                       n[2] = {1, 1};

  RayTargets(const Spheres &s, const Window &w) {
    const double rmax = s.MaxRadius();
    for (std::size_t i = 0; i < s.Size(); ++i) {
      const double *p = &s.x[3 * i];
      if (p[2] < w.lo[2] || p[2] > w.hi[2]) continue;
      const int    nx = s.periodic[0] ? 1 : 0, ny = s.periodic[1] ? 1 : 0;
      const double Lx = s.upper[0] - s.lower[0], Ly = s.upper[1] - s.lower[1];
      for (int a = -nx; a <= nx; ++a)
        for (int b = -ny; b <= ny; ++b) {
          const double q[2] = {p[0] + a * Lx, p[1] + b * Ly};
          if (q[0] + s.r[i] < w.lo[0] || q[0] - s.r[i] > w.hi[0] || q[1] + s.r[i] < w.lo[1] || q[1] - s.r[i] > w.hi[1]) continue;
          c.push_back(q[0]), c.push_back(q[1]), c.push_back(p[2]), c.push_back(s.r[i]);
        }
    }
    h = rmax > 0 ? 2 * rmax : 1;
    for (int d = 0; d < 2; ++d) lo[d] = w.lo[d], n[d] = std::max(1, (int)std::ceil((w.hi[d] - w.lo[d]) / h));
    const std::size_t nb = (std::size_t)n[0] * n[1];
    std::vector<std::vector<std::size_t>> bins(nb);
    for (std::size_t t = 0; t < c.size() / 4; ++t) {
      const double *q = &c[4 * t];
      const int     i0 = Bin(q[0] - q[3], 0), i1 = Bin(q[0] + q[3], 0), j0 = Bin(q[1] - q[3], 1), j1 = Bin(q[1] + q[3], 1);
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) bins[(std::size_t)j * n[0] + i].push_back(t);
    }
    start.assign(nb + 1, 0);
    for (std::size_t b = 0; b < nb; ++b) start[b + 1] = start[b] + bins[b].size(), items.insert(items.end(), bins[b].begin(), bins[b].end());
  }
  int Bin(double v, int d) const { return std::clamp((int)std::floor((v - lo[d]) / h), 0, n[d] - 1); }
  // Height where the ray at (x, y) first meets a sphere, or `floor`; *hit says whether one was met.
  double Height(double x, double y, double floor, bool *hit) const {
    const std::size_t b    = (std::size_t)Bin(y, 1) * n[0] + Bin(x, 0);
    double            best = -HUGE_VAL;
    for (std::size_t k = start[b]; k < start[b + 1]; ++k) {
      const double *q  = &c[4 * items[k]];
      const double  d2 = (x - q[0]) * (x - q[0]) + (y - q[1]) * (y - q[1]);
      if (d2 <= q[3] * q[3]) best = std::max(best, q[2] + std::sqrt(q[3] * q[3] - d2));
    }
    *hit = best > -HUGE_VAL && best > floor;
    return *hit ? best : floor;
  }
};

}  // namespace

Surface CastRays(const Spheres &s, const Window &w, double spacing, double substrate) {
  Surface out;
  const RayTargets t(s, w);
  out.spacing = spacing, out.x0 = w.lo[0], out.y0 = w.lo[1];
  out.nx      = std::max(1, (int)std::lround((w.hi[0] - w.lo[0]) / spacing));
  out.ny      = std::max(1, (int)std::lround((w.hi[1] - w.lo[1]) / spacing));
  out.z.resize((std::size_t)out.nx * out.ny);
  double sum = 0;
  for (int j = 0; j < out.ny; ++j)
    for (int i = 0; i < out.nx; ++i) {
      bool         hit;
      const double z = t.Height(out.x0 + (i + 0.5) * spacing, out.y0 + (j + 0.5) * spacing, substrate, &hit);
      out.z[(std::size_t)j * out.nx + i] = z, sum += z, out.hits += hit;
    }
  out.mean = sum / out.z.size();
  double var = 0, dev = 0;
  for (double z : out.z) var += (z - out.mean) * (z - out.mean), dev += std::fabs(z - out.mean);
  out.saStd = std::sqrt(var / out.z.size()), out.saMeanAbs = dev / out.z.size();
  return out;
}

LineProfile CastLine(const Spheres &s, const Window &w, int n, double substrate) {
  LineProfile      out;
  const RayTargets t(s, w);
  const double     y = 0.5 * (w.lo[1] + w.hi[1]), dx = (w.hi[0] - w.lo[0]) / n;
  double           sum = 0;
  for (int i = 0; i < n; ++i) {
    bool hit;
    out.x.push_back(w.lo[0] + (i + 0.5) * dx);
    out.z.push_back(t.Height(out.x.back(), y, substrate, &hit));
    sum += out.z.back();
  }
  out.mean = sum / n;
  double dev = 0, var = 0;
  for (double z : out.z) dev += std::fabs(z - out.mean), var += (z - out.mean) * (z - out.mean);
  out.ra = dev / n, out.rq = std::sqrt(var / n);
  return out;
}

ReposeFit FitRepose(const Surface &surface, double substrate, const double *axis, double fitLo, double fitHi) {
  ReposeFit fit;
  double    top = substrate, wsum = 0, cx = 0, cy = 0;
  auto      pos = [&](std::size_t k, double *x, double *y) {
    *x = surface.x0 + (k % surface.nx + 0.5) * surface.spacing, *y = surface.y0 + (k / surface.nx + 0.5) * surface.spacing;
  };
  for (std::size_t k = 0; k < surface.z.size(); ++k) {
    double x, y;
    pos(k, &x, &y);
    const double h = surface.z[k] - substrate;
    top = std::max(top, surface.z[k]);
    if (h > 0) wsum += h, cx += h * x, cy += h * y;
  }
  fit.height = top - substrate;
  if (axis) fit.axis[0] = axis[0], fit.axis[1] = axis[1];
  else if (wsum > 0) fit.axis[0] = cx / wsum, fit.axis[1] = cy / wsum;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < surface.z.size(); ++k) {
    const double h = surface.z[k] - substrate;
    if (h < fitLo * fit.height || h > fitHi * fit.height || !(h > 0)) continue;
    double x, y;
    pos(k, &x, &y);
    const double d = std::hypot(x - fit.axis[0], y - fit.axis[1]);
    fit.distance.push_back(d), fit.z.push_back(surface.z[k]);
    sx += d, sy += surface.z[k], sxx += d * d, sxy += d * surface.z[k];
  }
  fit.points = (long)fit.distance.size();
  const double det = fit.points * sxx - sx * sx;
  if (fit.points < 2 || !(det > 0)) return fit;
  fit.slope     = (fit.points * sxy - sx * sy) / det;
  fit.intercept = (sy - fit.slope * sx) / fit.points;
  fit.angleDeg  = std::atan(-fit.slope) * 180 / kPi;
  return fit;
}

double HeightReposeAngleDeg(double height, double base) { return base > 0 ? std::atan(2 * height / base) * 180 / kPi : 0; }

}  // namespace vofdem::analysis
