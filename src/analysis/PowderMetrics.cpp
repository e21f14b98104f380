// Packing density, coordination numbers, sample rings, segregation cells and histograms
// (PowderMetrics.hpp).
#include "vofdem/analysis/PowderMetrics.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace vofdem::analysis {

double Spheres::MaxRadius() const { return r.empty() ? 0 : *std::max_element(r.begin(), r.end()); }

double Spheres::MeanRadius() const {
  double sum = 0;
  for (double v : r) sum += v;
  return r.empty() ? 0 : sum / r.size();
}

std::vector<std::size_t> CentresIn(const Spheres &s, const Window &w) {
  std::vector<std::size_t> in;
  for (std::size_t i = 0; i < s.Size(); ++i)
    if (w.Contains(&s.x[3 * i])) in.push_back(i);
  return in;
}

double PackingDensity(const Spheres &s, const Window &w, int resolution) { return ClumpUnions(s, resolution).Inside(s, w) / w.Volume(); }

std::vector<int> CoordinationNumbers(const Spheres &s, double gap) {
  const std::size_t n = s.Size();
  std::vector<int>  z(n, 0);
  if (n < 2) return z;
  // A particle's key: its clump id (>= 0), or -1 - its index for a loose sphere.
  auto Body = [&](std::size_t i) { return s.Clump(i) >= 0 ? s.Clump(i) : -1 - (std::int64_t)i; };
  std::vector<std::pair<std::int64_t, std::int64_t>> touching;  // clumps: (particle, particle it touches)
  const double h = 2 * s.MaxRadius() + gap;
  double       lo[3], len[3];
  int          cells[3];
  for (int d = 0; d < 3; ++d) {
    if (s.periodic[d]) {
      lo[d] = s.lower[d], len[d] = s.upper[d] - s.lower[d];
      cells[d] = std::max(1, (int)std::floor(len[d] / h));
    } else {
      double a = s.x[d], b = s.x[d];
      for (std::size_t i = 0; i < n; ++i) a = std::min(a, s.x[3 * i + d]), b = std::max(b, s.x[3 * i + d]);
      lo[d] = a, cells[d] = std::max(1, (int)std::floor((b - a) / h) + 1), len[d] = cells[d] * h;
    }
  }
  auto cellOf = [&](const double *p, int d) {
    int c = (int)std::floor((p[d] - lo[d]) / len[d] * cells[d]);
    if (s.periodic[d]) c = ((c % cells[d]) + cells[d]) % cells[d];
    return std::clamp(c, 0, cells[d] - 1);
  };
  const std::size_t ncell = (std::size_t)cells[0] * cells[1] * cells[2];
  std::vector<std::size_t> start(ncell + 1, 0), order(n);
  std::vector<std::size_t> cellIndex(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double *p = &s.x[3 * i];
    cellIndex[i]    = ((std::size_t)cellOf(p, 2) * cells[1] + cellOf(p, 1)) * cells[0] + cellOf(p, 0);
    ++start[cellIndex[i] + 1];
  }
  for (std::size_t c = 0; c < ncell; ++c) start[c + 1] += start[c];
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < n; ++i) order[fill[cellIndex[i]]++] = i;
  std::vector<std::size_t> visit;
  for (std::size_t i = 0; i < n; ++i) {
    const double *p = &s.x[3 * i];
    const int     c[3] = {cellOf(p, 0), cellOf(p, 1), cellOf(p, 2)};
    visit.clear();
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          int  q[3] = {c[0] + dx, c[1] + dy, c[2] + dz};
          bool ok   = true;
          for (int d = 0; d < 3; ++d) {
            if (s.periodic[d]) q[d] = (q[d] + cells[d]) % cells[d];
            else if (q[d] < 0 || q[d] >= cells[d]) ok = false;
          }
          if (ok) visit.push_back(((std::size_t)q[2] * cells[1] + q[1]) * cells[0] + q[0]);
        }
    // Fewer than three cells in a periodic direction would visit a cell twice.
    std::sort(visit.begin(), visit.end());
    visit.erase(std::unique(visit.begin(), visit.end()), visit.end());
    for (std::size_t cell : visit)
      for (std::size_t k = start[cell]; k < start[cell + 1]; ++k) {
        const std::size_t j = order[k];
        if (j == i || (s.Clump(i) >= 0 && s.Clump(i) == s.Clump(j))) continue;  // members of one clump are one particle
        double d2 = 0;
        for (int d = 0; d < 3; ++d) {
          double e = s.x[3 * j + d] - p[d];
          if (s.periodic[d]) {
            const double L = s.upper[d] - s.lower[d];
            e -= L * std::round(e / L);
          }
          d2 += e * e;
        }
        const double reach = s.r[i] + s.r[j] + gap;
        if (d2 < reach * reach) {
          ++z[i];
          if (!s.clump.empty()) touching.emplace_back(Body(i), Body(j));
        }
      }
  }
  if (s.clump.empty()) return z;
  // Clumps: a particle's contacts are the other particles any of its members touch, each once;
  // the value sits on its largest sphere (the base sphere of an inserted clump, near its centroid;
  // the rank count does not change which), the other members get -1 (not particles).
  std::sort(touching.begin(), touching.end());
  touching.erase(std::unique(touching.begin(), touching.end()), touching.end());
  std::map<std::int64_t, int> count;
  for (const auto &t : touching) ++count[t.first];
  std::map<std::int64_t, std::size_t> first;
  for (std::size_t i = 0; i < n; ++i) {
    const auto it = first.find(Body(i));
    if (it == first.end()) first.emplace(Body(i), i);
    else if (s.r[i] > s.r[it->second]) it->second = i;
  }
  for (std::size_t i = 0; i < n; ++i) z[i] = first[Body(i)] == i ? count[Body(i)] : -1;
  return z;
}

std::vector<Ring> RingsAlongX(const Window &w, int n, double radius) {
  std::vector<Ring> rings;
  const double      pitch = (w.hi[0] - w.lo[0]) / n;
  for (int k = 0; k < n; ++k) {
    Ring g;
    g.x = w.lo[0] + (k + 0.5) * pitch, g.y = 0.5 * (w.lo[1] + w.hi[1]);
    g.inner = 0, g.outer = radius, g.z0 = w.lo[2], g.z1 = w.hi[2];
    rings.push_back(g);
  }
  return rings;
}

std::vector<RingResult> SampleRings(const Spheres &s, const std::vector<Ring> &rings, const std::vector<int> &contacts, int resolution) {
  std::vector<RingResult> out;
  const ClumpUnions       unions(s, resolution);
  for (const Ring &g : rings) {
    RingResult res;
    double     zsum = 0;
    res.ring        = g;
    // A clump is counted once, by its largest sphere (CoordinationNumbers: the others hold -1).
    for (std::size_t i = 0; i < s.Size(); ++i)
      if (g.Contains(&s.x[3 * i]) && contacts[i] >= 0) ++res.centres, zsum += contacts[i];
    res.packing      = unions.Inside(s, g) / g.Volume();
    res.coordination = res.centres ? zsum / res.centres : 0;
    out.push_back(res);
  }
  return out;
}

std::vector<SegregationCell> Segregation(const Spheres &s, const Window &w, const int cells[3], double referenceRadius) {
  std::vector<SegregationCell> out((std::size_t)cells[0] * cells[1] * cells[2]);
  std::vector<double>          sum(out.size(), 0);
  auto index = [&](int i, int j, int k) { return ((std::size_t)k * cells[1] + j) * cells[0] + i; };
  for (int k = 0; k < cells[2]; ++k)
    for (int j = 0; j < cells[1]; ++j)
      for (int i = 0; i < cells[0]; ++i) {
        SegregationCell &c = out[index(i, j, k)];
        c.i = i, c.j = j, c.k = k;
        const int ijk[3] = {i, j, k};
        for (int d = 0; d < 3; ++d) {
          const double h = (w.hi[d] - w.lo[d]) / cells[d];
          c.box.lo[d] = w.lo[d] + ijk[d] * h, c.box.hi[d] = ijk[d] + 1 == cells[d] ? w.hi[d] : w.lo[d] + (ijk[d] + 1) * h;
        }
      }
  for (std::size_t p : CentresIn(s, w)) {
    int ijk[3];
    for (int d = 0; d < 3; ++d)
      ijk[d] = std::clamp((int)std::floor((s.x[3 * p + d] - w.lo[d]) / (w.hi[d] - w.lo[d]) * cells[d]), 0, cells[d] - 1);
    const std::size_t c = index(ijk[0], ijk[1], ijk[2]);
    ++out[c].centres, sum[c] += s.r[p];
  }
  for (std::size_t c = 0; c < out.size(); ++c)
    if (out[c].centres) out[c].meanRadius = sum[c] / out[c].centres, out[c].index = out[c].meanRadius / referenceRadius;
  return out;
}

Histogram MakeHistogram(const std::vector<double> &values, double lo, double hi, int bins) {
  Histogram h;
  for (int b = 0; b < bins; ++b) h.lo.push_back(lo + (hi - lo) * b / bins), h.hi.push_back(lo + (hi - lo) * (b + 1) / bins);
  h.count.assign(bins, 0);
  for (double v : values) ++h.count[std::clamp((int)std::floor((v - lo) / (hi - lo) * bins), 0, bins - 1)];
  return h;
}

}  // namespace vofdem::analysis
