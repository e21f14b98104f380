// The DEM's laws a scene chooses by name: one table row per normal law (-dem_contact), cohesion model
// (-dem_cohesion) and rolling model (-dem_rolling). The options' names and help, the banner's names and the
// compile-time binding of the contact loops (Dem::ComputeForces) are all built from these rows, so a law is
// named in one place (docs/architecture.md, "add a contact law").
#pragma once

#include "vofdem/base/NamedTable.hpp"
#include "vofdem/dem/ContactLaw.hpp"

namespace vofdem::contact {

// linear: the template argument LIN of the loops (NormalLawAt: Hertz (P3) or the linear spring (P4)).
struct NormalRow {
  const char *name, *summary;
  bool        linear;
};
inline constexpr NormalRow kNormalLaws[] = {
    {"hertz", "Hertz-Mindlin, P3", false},
    {"linear", "spring-dashpot, P4", true},
};

// model: the template argument COH of the loops; hertzOnly: refused with a law whose linear flag is set.
struct CohesionRow {
  const char *name, *summary;
  int         model;
  bool        hertzOnly;
};
inline constexpr CohesionRow kCohesionLaws[] = {
    {"none", "no adhesion", kNoCohesion, false},
    {"jkr", "JKR with hysteresis, P6", kJkr, true},
    {"sjkr", "LIGGGHTS' simplified JKR, F = k A", kSjkr, false},
    {"bond", "bonded particles, parallel or contact bonds that break (-dem_bond_*), P13", kBond, false},
};

// model: the template argument of hertz::RollingTorque; shown: the banner's name.
struct RollingRow {
  const char    *name, *summary, *shown;
  hertz::Rolling model;
};
inline constexpr RollingRow kRollingLaws[] = {
    {"none", "no rolling resistance", "none", hertz::Rolling::None},
    {"cdt", "constant torque", "constant torque", hertz::Rolling::ConstantTorque},
    {"epsd", "elastic-plastic spring-dashpot, Ai et al.", "EPSD", hertz::Rolling::Epsd},
    {"epsd2", "LIGGGHTS' undamped epsd2", "EPSD2 (LIGGGHTS)", hertz::Rolling::Epsd2},
};

using table::AtRow;
using table::Choices;
using table::Find;
using table::Help;
using table::Names;

}  // namespace vofdem::contact
