// The particle heat laws (HeatExchange.hpp; docs/physics.md P11; F10's Nusselt number is test_coupling_laws.cpp's): the
// inverse of h(T) through the melting range, and the exchange step: the exact exponential of the linear law, the pair's common temperature for
// a long step, no overshoot however short the particle's time constant, the heat it returns is its enthalpy change.
#include "vofdem/coupling/HeatExchange.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace vofdem;

namespace {
ThermalMaterial Inconel() {  // config/materials/in718.yaml's values, constant cp
  ThermalMaterial m;
  m.density = 8380, m.cp = PropertyTable{{}, {650}}, m.k = PropertyTable{{}, {29}};
  m.metal = true, m.solidus = 1533, m.liquidus = 1609, m.latentHeat = 2.1e5, m.emissivity = 0.4, m.referenceTemperature = 300;
  return m;
}
const double d = 96e-6, mass = 8380 * M_PI * d * d * d / 6, area = M_PI * d * d;
}  // namespace

TEST(HeatExchange, TemperatureOfEnthalpy) {
  const ThermalMaterial m = Inconel();
  for (double T : {250.0, 573.0, 1533.0, 1550.0, 1600.0, 1609.0, 2500.0})
    for (double guess : {300.0, 1570.0, 3000.0}) EXPECT_NEAR(heat::TemperatureOf(m, m.Enthalpy(T), guess), T, 1e-9 * T) << T << " from " << guess;
}

TEST(HeatExchange, StepIsTheExponentialOfTheLinearLaw) {
  ThermalMaterial m = Inconel();
  const double    hc = 375, Tb = 1400, T0 = 573, dt = 0.01, C = mass * 650;
  const auto      r = heat::Step(m, mass, area, hc, 0, Tb, 0, m.Enthalpy(T0), T0, dt);
  const double    Q = C * (Tb - T0) * -std::expm1(-area * hc * dt / C);
  EXPECT_NEAR(r.heat, Q, 1e-12 * std::fabs(Q));
  EXPECT_NEAR(mass * (r.h - m.Enthalpy(T0)), r.heat, 1e-12 * std::fabs(Q));  // the heat is the enthalpy change
  EXPECT_NEAR(r.T, T0 + Q / C, 1e-9 * T0);
}

TEST(HeatExchange, LongStepsReachThePairsTemperatureWithoutOvershoot) {
  ThermalMaterial m = Inconel();
  const double    Tb = 1400, T0 = 573, C = mass * 650;
  // A reservoir: the particle reaches Tb, never beyond, for a step 1e6 of its time constant (with radiation too).
  auto r = heat::Step(m, mass, area, 375, 0.4, Tb, 0, m.Enthalpy(T0), T0, 1e6 * C / (area * 375));
  EXPECT_NEAR(r.T, Tb, 1e-9 * Tb);
  EXPECT_LE(r.T, Tb * (1 + 1e-12));
  // Fluid of the particle's capacity: both end at the mean, Q = (C/2)(Tb - T0).
  r = heat::Step(m, mass, area, 375, 0, Tb, C, m.Enthalpy(T0), T0, 1e6 * C / (area * 375));
  EXPECT_NEAR(r.heat, 0.5 * C * (Tb - T0), 1e-9 * C * (Tb - T0));
  // Cooling past the melting range: a hot liquid particle in cold gas ends at the gas temperature, with the latent heat given.
  r = heat::Step(m, mass, area, 375, 0.4, 1000, 0, m.Enthalpy(1700), 1700, 1e7 * C / (area * 375));
  EXPECT_NEAR(r.T, 1000, 1e-6);
  EXPECT_NEAR(r.heat, mass * (m.Enthalpy(1000) - m.Enthalpy(1700)), 1e-9 * mass * m.Enthalpy(1700));
}
