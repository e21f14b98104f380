// Drag and heat-transfer laws of the coupling (DragLaws.hpp; docs/physics.md F6, F9, F10) against values
// computed separately from the published formulas (a few lines of Python written from the papers'
// equations, not from this code: d = 1 mm, water rho 1000 kg/m^3, mu 1e-3 Pa s, slip 0.05 m/s), their
// limits (Stokes drag as the slip vanishes, the single sphere as eps -> 1), and the kernels
// (Kernel.hpp): shape, cut-off and the self-disturbance coefficient of K1b.
#include "vofdem/coupling/DragLaws.hpp"
#include "vofdem/coupling/Kernel.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace vofdem;

namespace {
const double d = 1e-3, rho = 1000, mu = 1e-3, slip = 0.05;
const double stokes = 3 * M_PI * mu * d;  // K of Stokes drag, kg/s
}  // namespace

TEST(DragLaws, AgainstHandComputedValues) {
  // Hand calculations (d = 1 mm, rho 1000, mu 1e-3, slip 0.05 m/s; Re = eps rho d slip/mu), written out
  // from the papers' formulas; K = force/slip on one particle.
  // Wen & Yu (Gidaspow 1994), eps 0.9: Re = 45, Cd = 24/45 (1 + 0.15 45^0.687) = 1.62690433,
  // beta = 3/4 Cd eps (1-eps) rho slip/d eps^-2.65; K = beta V/(1-eps) = 3.80094657e-5.
  EXPECT_NEAR(drag::WenYu(d, 0.9, slip, rho, mu), 3.8009465703890566e-05, 1e-12 * 3.8e-5);
  // Ergun (Gidaspow's form), eps 0.5: beta = 150 (1-eps)^2 mu/(eps d^2) + 1.75 (1-eps) rho slip/d
  // = 75000 + 43750 = 118750; K = beta V/(1-eps) = 118750 x 5.23598776e-10/0.5 = 1.24354709e-4.
  EXPECT_NEAR(drag::Ergun(d, 0.5, slip, rho, mu), 0.00012435470920459598, 1e-12 * 1.2e-4);
  EXPECT_NEAR(drag::SchillerNaumann(d, slip, rho, mu), 3.020043557511725e-05, 1e-12 * 3e-5);
  // Di Felice (1994), eps 0.7: Re = 35, Cd = (0.63 + 4.8/sqrt 35)^2 = 2.07748430, chi = 3.7 - 0.65
  // exp(-(1.5 - log10 35)^2/2) = 3.05063084; total force 0.5 Cd rho (pi d^2/4) (eps slip)^2 eps^-chi
  // = 2.96676004e-6 N; drag = eps x total; K = 0.7 x 2.96676004e-6/0.05 = 4.15346406e-5.
  EXPECT_NEAR(drag::DiFelice(d, 0.7, slip, rho, mu), 4.1534640629025366e-05, 1e-12 * 4.2e-5);
  // Koch & Hill (Hill, Koch & Ladd 2001; F = F0 + F3 Re/2 with Re on the diameter, as CFDEM's KochHillDrag),
  // eps 0.7 (phi 0.3 < 0.4): F0 = (1 + 3 sqrt(0.15) + 135/64 0.3 ln 0.3 + 16.14 x 0.3)/(1 + 0.681 x 0.3
  // - 8.48 x 0.09 + 8.16 x 0.027) = 9.43728034, F3 = 0.0673 + 0.212 x 0.3 + 0.0232/0.7^5 = 0.268937722,
  // F = 9.43728034 + 0.5 x 0.268937722 x 35 = 14.1436905; K = 3 pi mu d eps^2 F = 6.53175598e-5.
  EXPECT_NEAR(drag::KochHill(d, 0.7, slip, rho, mu), 6.531755975212285e-05, 1e-12 * 6.5e-5);
  // eps 0.5 (phi >= 0.4): F0 = 10 x 0.5/0.125 = 40, F3 = 0.0673 + 0.106 + 0.0232 x 32 = 0.9157, Re = 25,
  // F = 40 + 0.5 x 0.9157 x 25 = 51.44625; K = 3 pi mu d 0.25 F = 1.21217371e-4.
  EXPECT_NEAR(drag::KochHill(d, 0.5, slip, rho, mu), 0.00012121737079105792, 1e-12 * 1.2e-4);
  // Beetstra, van der Hoef & Kuipers (2007), eps 0.7: F = 10 phi/eps^2 + eps^2 (1 + 1.5 sqrt phi)
  // + 0.413 Re/(24 eps^2) (1/eps + 3 eps phi + 8.4 Re^-0.343)/(1 + 10^(3 phi) Re^-(1 + 4 phi)/2)
  // = 7.01502506 + 4.81443079 = 11.8294559; drag 3 pi mu d eps slip F: K = 7.80429964e-5.
  EXPECT_NEAR(drag::Beetstra(d, 0.7, slip, rho, mu), 7.804299635788622e-05, 1e-12 * 7.8e-5);
  // eps 0.45, Re 22.5: F = 27.5882609 + 8.56385159; K = 1.53326535e-4.
  EXPECT_NEAR(drag::Beetstra(d, 0.45, slip, rho, mu), 0.00015332653468440888, 1e-12 * 1.5e-4);
  // Gidaspow is Wen-Yu above its switch and Ergun below.
  EXPECT_EQ(drag::Gidaspow(d, 0.9, slip, rho, mu, 0.8), drag::WenYu(d, 0.9, slip, rho, mu));
  EXPECT_EQ(drag::Gidaspow(d, 0.5, slip, rho, mu, 0.8), drag::Ergun(d, 0.5, slip, rho, mu));
  EXPECT_EQ(drag::Gidaspow(d, 0.76, slip, rho, mu, 0.74), drag::WenYu(d, 0.76, slip, rho, mu));
}

TEST(DragLaws, DenseStokesLimitIsCarmanKozeny) {
  // In a fixed bed at vanishing Re the dense-bed laws must give the Carman-Kozeny pressure gradient
  // 180 phi^2 mu U/(eps^3 d^2) (Ergun's viscous term has 150): with model A, -grad p = n K u/eps,
  // n = phi/V, u = U/eps, so K = 30 pi mu d phi/eps exactly for Koch-Hill (F0 = 10 phi/eps^3 at phi >= 0.4)
  // and within Beetstra's small eps^2 (1 + 1.5 sqrt phi) term; Ergun's K is 150/180 of it.
  const double tiny = 1e-9;
  for (double eps : {0.4, 0.5, 0.6}) {
    const double phi = 1 - eps, carman = 30 * M_PI * mu * d * phi / eps;
    EXPECT_NEAR(drag::KochHill(d, eps, tiny, rho, mu) / carman, 1, 1e-6) << eps;
    EXPECT_NEAR(drag::Ergun(d, eps, tiny, rho, mu) / carman, 150.0 / 180.0, 1e-6) << eps;
    const double extra = eps * eps * (1 + 1.5 * std::sqrt(phi)) / (10 * phi / (eps * eps));  // Beetstra's second term
    EXPECT_NEAR(drag::Beetstra(d, eps, tiny, rho, mu) / carman, 1 + extra, 1e-3) << eps;
  }
}

TEST(DragLaws, StokesLimit) {
  // Vanishing slip, a single sphere: every single-particle law tends to 3 pi mu d.
  const double tiny = 1e-12;
  EXPECT_NEAR(drag::SchillerNaumann(d, tiny, rho, mu) / stokes, 1, 1e-6);
  EXPECT_NEAR(drag::WenYu(d, 1, tiny, rho, mu) / stokes, 1, 1e-6);
  EXPECT_NEAR(drag::KochHill(d, 1, tiny, rho, mu) / stokes, 1, 1e-6);
  // Beetstra's fit is 1 + O(Re^0.5) at eps = 1, Di Felice's (0.63 + 4.8/sqrt(Re))^2 Re/24 -> 0.96.
  EXPECT_NEAR(drag::Beetstra(d, 1, tiny, rho, mu) / stokes, 1, 1e-3);
  EXPECT_NEAR(drag::DiFelice(d, 1, tiny, rho, mu) / stokes, 4.8 * 4.8 / 24, 1e-4);
  // Every law stays finite and positive as the slip goes to zero.
  for (const std::string &name : drag::Names()) {
    drag::Law law;
    ASSERT_TRUE(drag::Parse(name, &law));
    EXPECT_STREQ(drag::Name(law), name.c_str());
    const double K = drag::Coefficient(law, d, 0.6, 0, rho, mu, 0.8);
    EXPECT_TRUE(std::isfinite(K) && K > 0) << name;
  }
  drag::Law law;
  EXPECT_FALSE(drag::Parse("stokes", &law));
}

TEST(DragLaws, SchillerNaumannCd) {
  EXPECT_NEAR(drag::SchillerNaumannCd(1), 24 * 1.15, 1e-12);
  EXPECT_NEAR(drag::SchillerNaumannCd(100), 0.24 * (1 + 0.15 * std::pow(100.0, 0.687)), 1e-12);
  EXPECT_EQ(drag::SchillerNaumannCd(2000), 0.44);
}

TEST(HeatLaws, NusseltBranchesAndFlux) {
  EXPECT_NEAR(heat::Nusselt(0.8, 50, 0.7), 3.7251116988936595, 1e-12);
  EXPECT_NEAR(heat::Nusselt(0.9, 800, 7), 26.269224849767536, 1e-11);
  EXPECT_NEAR(heat::Nusselt(0.6, 3000, 1), 15.663442975839036, 1e-11);
  EXPECT_EQ(heat::Nusselt(0.7, 0, 0.7), 2);  // conduction into still fluid
  EXPECT_NEAR(heat::ParticleToFluid(d, 5, 0.6, 400, 300, 0.3), 0.9434130314243743, 1e-13);
  // Antisymmetric in the temperatures: what one side gains the other loses (F9 with P11).
  EXPECT_NEAR(heat::ParticleToFluid(d, 5, 0.6, 300, 400, 0.3), -0.9434130314243743, 1e-13);
}

TEST(Kernels, ShapeAndCutoff) {
  const double H = 2.0;
  const double rcS = kernel::Cutoff(kernel::Shape::Smooth, H, 1.5), rcT = kernel::Cutoff(kernel::Shape::Truncated, H, 1.5);
  EXPECT_NEAR(rcS, std::sqrt(8.0) * H, 1e-14);
  EXPECT_NEAR(rcT, 3.0, 1e-14);
  EXPECT_EQ(kernel::Weight(kernel::Shape::Smooth, 0, H, rcS), 1);
  EXPECT_EQ(kernel::Weight(kernel::Shape::Smooth, rcS * rcS, H, rcS), 0);
  // Smooth: zero with a vanishing slope at the cut-off; the truncated Gaussian jumps there.
  const double eps = 1e-4 * rcS, r = rcS - eps;
  EXPECT_LT(kernel::Weight(kernel::Shape::Smooth, r * r, H, rcS), 1e-14);
  EXPECT_NEAR(kernel::Weight(kernel::Shape::Truncated, (rcT - 1e-9) * (rcT - 1e-9), H, rcT), std::exp(-0.5 * 1.5 * 1.5), 1e-9);
  EXPECT_EQ(kernel::Weight(kernel::Shape::Truncated, rcT * rcT, H, rcT), 0);
  // Close to the Gaussian of K1 near the centre: within 2.5 % of its peak inside r = H ((1 - 1/8)^4 = 0.586 against exp(-1/2) = 0.607 at r = H).
  for (double x = 0; x <= 1.0; x += 0.1)
    EXPECT_NEAR(kernel::Weight(kernel::Shape::Smooth, x * x * H * H, H, rcS), std::exp(-0.5 * x * x), 0.025);
}

TEST(Kernels, SelfDisturbanceCoefficient) {
  // A Gaussian (truncated far out): 1/(6 pi^(3/2) H), i.e. 0.282 d/H of the slip under Stokes drag (K1b).
  const double H = 1.5e-3;
  const double gauss = kernel::SelfDisturbanceCoefficient(kernel::Shape::Truncated, H, 6.0);
  EXPECT_NEAR(gauss * 6 * std::pow(M_PI, 1.5) * H, 1, 1e-6);
  EXPECT_NEAR(gauss * 3 * M_PI * 1e-3, 0.282 * 1e-3 / H, 1e-3 * 0.282 / 1.5);
  // The coefficient scales as 1/H.
  EXPECT_NEAR(kernel::SelfDisturbanceCoefficient(kernel::Shape::Smooth, 2 * H, 0) * 2, kernel::SelfDisturbanceCoefficient(kernel::Shape::Smooth, H, 0),
              1e-9 * gauss);
  // The smooth kernel is a little narrower than the Gaussian: a slightly larger coefficient.
  const double smooth = kernel::SelfDisturbanceCoefficient(kernel::Shape::Smooth, H, 0);
  EXPECT_GT(smooth / gauss, 1.0);
  EXPECT_LT(smooth / gauss, 1.3);
}

TEST(Kernels, OseenSelfDisturbance) {
  // An independent double quadrature of Kernel.hpp's integral for a Gaussian of width 1, whose transform
  // is exp(-k^2/2): C = 1/(8 pi^3) int 2 pi dk int_-1^1 dc exp(-k^2) (1 - c^2)/(1 + (Re/k)^2 c^2).
  const double Re = 3;
  double       brute = 0;
  const int    nk = 3000, nc = 2000;
  for (int i = 0; i < nk; ++i) {
    const double k = (i + 0.5) * 10.0 / nk;
    for (int j = 0; j < nc; ++j) {
      const double c = -1 + (j + 0.5) * 2.0 / nc, a = Re / k;
      brute += std::exp(-k * k) * (1 - c * c) / (1 + a * a * c * c) * (10.0 / nk) * (2.0 / nc);
    }
  }
  brute *= 2 * M_PI / (8 * M_PI * M_PI * M_PI);
  const std::vector<double> t = kernel::SelfDisturbanceTable(kernel::Shape::Truncated, 8.0, {0, 1e-4, Re, 30});
  EXPECT_NEAR(t[2] / brute, 1, 1e-4);
  EXPECT_NEAR(t[1] / t[0], 1, 1e-4);        // the Stokes limit
  EXPECT_LT(t[2], 0.6 * t[0]);              // Re_H = 3 already more than halves it
  EXPECT_LT(t[3], t[2]);                    // and it keeps falling
}
