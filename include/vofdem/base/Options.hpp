// Typed option reading for PetscOptionsBegin/End blocks. Each reader
//  - checks the option's raw text first, so a value that is not a number (or not in range) is
//    reported as one line naming the option (PETSc's own message names neither), and
//  - registers the option with PETSc, so -help lists it with its default and its unit.
// The value passed in is the default; it is overwritten only when the option is given.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace vofdem {

// An interval for a real option; open ends exclude the bound.
struct RealRange {
  PetscReal lo = PETSC_MIN_REAL, hi = PETSC_MAX_REAL;
  bool      loOpen = false, hiOpen = false;
  static RealRange Any() { return {}; }
  static RealRange Positive() { return {0, PETSC_MAX_REAL, true, false}; }
  static RealRange NonNegative() { return {0, PETSC_MAX_REAL, false, false}; }
  static RealRange Closed(PetscReal a, PetscReal b) { return {a, b, false, false}; }
  static RealRange LeftOpen(PetscReal a, PetscReal b) { return {a, b, true, false}; }
  bool Contains(PetscReal v) const { return (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi); }
  std::string Describe() const;
};

class OptionReader {
public:
  // `items` is the PetscOptionsObject of the enclosing PetscOptionsBegin block.
  explicit OptionReader(PetscOptionItems *items) : items_(items) {}

  PetscErrorCode Real(const char *name, const char *text, const char *unit, PetscReal *value,
                      RealRange range = RealRange::Any(), PetscBool *set = nullptr);
  PetscErrorCode Int(const char *name, const char *text, PetscInt *value, PetscInt lo = PETSC_MIN_INT,
                     PetscInt hi = PETSC_MAX_INT, PetscBool *set = nullptr);
  PetscErrorCode Bool(const char *name, const char *text, PetscBool *value, PetscBool *set = nullptr);
  // Exactly `n` comma-separated reals (a YAML list works too).
  PetscErrorCode RealVector(const char *name, const char *text, const char *unit, PetscReal *value, PetscInt n,
                            RealRange range = RealRange::Any(), PetscBool *set = nullptr);
  PetscErrorCode IntVector(const char *name, const char *text, PetscInt *value, PetscInt n, PetscInt lo = PETSC_MIN_INT,
                           PetscInt hi = PETSC_MAX_INT, PetscBool *set = nullptr);
  // A comma-separated list of 1..maxCount reals (a YAML list works too).
  PetscErrorCode RealList(const char *name, const char *text, const char *unit, std::vector<PetscReal> *value, PetscInt maxCount,
                          RealRange range = RealRange::Any(), PetscBool *set = nullptr);
  // A comma-separated list of names, each of which must be one of `allowed`.
  PetscErrorCode NameList(const char *name, const char *text, const std::vector<std::string> &allowed,
                          std::vector<std::string> *value, PetscBool *set = nullptr);
  PetscErrorCode String(const char *name, const char *text, std::string *value, PetscBool *set = nullptr);

  // "-prefix_name" as the user writes it.
  std::string FullName(const char *name) const;

private:
  PetscErrorCode RawValue(const char *name, const char **raw, PetscBool *given) const;
  PetscOptionItems *items_;
};

// Text helpers, exposed for unit tests.
bool ParseReal(const std::string &text, PetscReal *value);
bool ParseInt(const std::string &text, PetscInt *value);
// An integer written out (digits, an optional sign) that does not fit a PetscInt (32 bits in this PETSc).
bool IntegerTooLarge(const std::string &text);
// Every option an OptionReader has looked up ("-dem_restitution"), and the one closest to a misspelt name
// (edit distance at most max(2, length/5); "" when none is), for "did you mean" in CheckUnusedOptions.
void        RecordOptionName(const std::string &fullName);
std::string ClosestOptionName(const std::string &fullName);
std::vector<std::string> SplitList(const std::string &text);

}  // namespace vofdem
