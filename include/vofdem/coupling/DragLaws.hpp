// Fluid-particle drag laws (docs/physics.md F6, P1; seed 004 table 4) and heat-transfer laws (F9, F10) as
// plain functions, chosen once per scene by name (-coupling_drag) from the table of laws
// (DragLawTable.cpp: one row per law, which also builds the option's help). Every drag law returns the
// coefficient K (kg/s) of the force on one particle, f_drag = K (u - v), with u the kernel-averaged
// fluid velocity at the particle (K1), v the particle's velocity, d its diameter, eps the averaged
// fluid fraction, slip = |u - v|. The pressure-gradient force -V grad p is a separate term (P1,
// CFD-DEM "model A"); where a correlation gives the total fluid-particle force of a homogeneous bed
// (Di Felice, Koch-Hill), the drag part is eps times the total (Zhou et al. 2010, J. Fluid
// Mech. 661: in a homogeneous bed -V grad p = (1 - eps)/eps f_drag, so total = f_drag/eps).
#pragma once

#include <string>
#include <vector>

namespace vofdem {
namespace drag {

// The table of laws (DragLawTable.cpp). A new law: its function in a file of its own, and one row there.
struct Input {
  double d, eps, slip, rho, mu;  // diameter (m), fluid fraction, |u - v| (m/s), fluid density (kg/m^3), viscosity (Pa s)
  double eSwitch;                // Gidaspow's switch (-coupling_drag_switch)
};
struct Entry {
  const char *name;                        // -coupling_drag
  const char *summary;                     // one line for -help
  double (*coefficient)(const Input &in);  // K (kg/s)
};
const std::vector<Entry> &Table();
using Law = const Entry *;  // chosen once per scene: the row of the table

const std::vector<std::string> &Names();  // in the table's order
bool        Parse(const std::string &name, Law *law);
Law         Find(const std::string &name);  // nullptr if no law has that name
const char *Name(Law law);
std::string Help();  // "name (summary), ...", for -coupling_drag

// Particle Reynolds number on the interstitial slip, Re = eps rho d |u - v| / mu (F6).
double Reynolds(double d, double eps, double slip, double rho, double mu);
// Single-sphere drag coefficient of F6: 24/Re (1 + 0.15 Re^0.687) below Re = 1000, 0.44 above.
double SchillerNaumannCd(double Re);

// Gidaspow (F6): Wen-Yu above eps = eSwitch (beta = 3 eps rho |u-v| Cd eps^-2.65 /(4 d), Cd from
// Re = eps rho d |u-v|/mu), Ergun below (beta = 150 (1-eps) mu/(eps d^2) + 1.75 rho |u-v|/d);
// K = beta V.
double Gidaspow(double d, double eps, double slip, double rho, double mu, double eSwitch);
double WenYu(double d, double eps, double slip, double rho, double mu);
double Ergun(double d, double eps, double slip, double rho, double mu);
// Schiller-Naumann, the single sphere: K = (pi/8) Cd rho d^2 |u-v|, Re = rho d |u-v|/mu (no eps).
double SchillerNaumann(double d, double slip, double rho, double mu);
// Di Felice (1994): total force (pi/8) Cd rho d^2 eps^2 |u-v| (u-v) eps^-chi, Cd = (0.63 + 4.8/sqrt(Re))^2,
// chi = 3.7 - 0.65 exp(-(1.5 - log10 Re)^2/2), Re = eps rho d |u-v|/mu; drag = eps x total.
double DiFelice(double d, double eps, double slip, double rho, double mu);
// Koch & Hill (2001; Hill, Koch & Ladd 2001): total force 3 pi mu d eps (u-v) F, F = F0(phi) + F3(phi) Re/2,
// phi = 1 - eps, Re = rho eps |u-v| d/mu (F3 Re_a with Koch & Hill's Re_a on the radius); drag = eps x total.
double KochHill(double d, double eps, double slip, double rho, double mu);
// Beetstra, van der Hoef & Kuipers (2007), monodisperse: drag 3 pi mu d eps (u-v) F(phi, Re), Re = rho eps |u-v| d/mu;
// F is normalised as the drag already (F -> 10 phi/eps^2 = eps x Carman-Kozeny's total force at Re -> 0).
double Beetstra(double d, double eps, double slip, double rho, double mu);

// K of the chosen law (eSwitch: Gidaspow's switch).
inline double Coefficient(Law law, double d, double eps, double slip, double rho, double mu, double eSwitch) {
  return law->coefficient(Input{d, eps, slip, rho, mu, eSwitch});
}

}  // namespace drag

namespace heat {
// Particle Nusselt number (F10, seed 000 eq. 8), Re = eps rho d |u-v|/mu, Pr = cp mu/k.
double Nusselt(double eps, double Re, double Pr);
// Heat the particle gives to the fluid (F9; W): pi d^2 [h (Tp - Tf) + emissivity sigma (Tp^4 - Tf^4)],
// h = Nu k/d. The particle loses exactly this (P11).
double ParticleToFluid(double d, double Nu, double kFluid, double Tp, double Tf, double emissivity);
}  // namespace heat

}  // namespace vofdem
