// What many examples repeat, in one place: setting an option from a number at full precision, the
// verdict word of a check, the observed order of convergence between two grids. Examples stay
// complete programs: this header is all they share beyond the library.
#pragma once

#include <petscsys.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace vofdem::example {

// A number as an option value, at full precision (std::to_string prints 5.4e-8 as 0.000000).
inline std::string Num(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// Sets -name value in the global options (for the runs that follow).
inline PetscErrorCode SetOption(const char *name, const std::string &value) {
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsSetValue(nullptr, name, value.c_str()));
  PetscFunctionReturn(0);
}

inline const char *Verdict(bool ok) { return ok ? "ok" : "FAIL"; }

// The observed order of an error that fell from eCoarse on nCoarse cells to eFine on nFine cells.
inline PetscReal ObservedOrder(PetscReal eCoarse, PetscReal eFine, PetscReal nCoarse, PetscReal nFine) { return std::log(eCoarse / eFine) / std::log(nFine / nCoarse); }

}  // namespace vofdem::example
