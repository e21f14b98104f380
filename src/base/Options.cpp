#include "vofdem/base/Options.hpp"

#include "vofdem/base/Runtime.hpp"

#include <cerrno>
#include <cmath>
#include <algorithm>
#include <cstdlib>
#include <set>
#include <sstream>

namespace vofdem {

namespace {

std::string Trim(const std::string &s) {
  const auto b = s.find_first_not_of(" \t[]");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t[]");
  return s.substr(b, e - b + 1);
}

std::string HelpText(const char *text, const char *unit) {
  return unit && unit[0] ? std::string(text) + " [" + unit + "]" : std::string(text);
}

// PETSc's help line shows only the first entry of an array default: give all of them.
template <typename T>
std::string VectorHelp(const char *text, const char *unit, const T *value, PetscInt n) {
  std::ostringstream s;
  s << HelpText(text, unit) << " (default ";
  for (PetscInt i = 0; i < n; ++i) s << (i ? "," : "") << value[i];
  s << ")";
  return s.str();
}

std::string Join(const std::vector<std::string> &v) {
  std::string s;
  for (const auto &x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

}  // namespace

std::string RealRange::Describe() const {
  std::ostringstream s;
  s << (loOpen ? "(" : "[");
  if (lo == PETSC_MIN_REAL) s << "-inf"; else s << lo;
  s << ", ";
  if (hi == PETSC_MAX_REAL) s << "inf"; else s << hi;
  s << (hiOpen ? ")" : "]");
  return s.str();
}

bool ParseReal(const std::string &text, PetscReal *value) {
  const std::string t = Trim(text);
  if (t.empty()) return false;
  char *end = nullptr;
  errno     = 0;
  const double v = std::strtod(t.c_str(), &end);
  if (errno == ERANGE || *end != '\0' || !std::isfinite(v)) return false;
  *value = v;
  return true;
}

bool IntegerTooLarge(const std::string &text) {
  const std::string t = Trim(text);
  if (t.empty()) return false;
  size_t i = t[0] == '-' || t[0] == '+' ? 1 : 0;
  if (i == t.size()) return false;
  for (; i < t.size(); ++i)
    if (t[i] < '0' || t[i] > '9') return false;
  PetscInt v;
  return !ParseInt(t, &v);  // all digits, yet not a PetscInt: out of its range
}

namespace {
std::set<std::string> &ReadNames() {
  static std::set<std::string> names;
  return names;
}

// Optimal string alignment distance (Damerau-Levenshtein with adjacent transpositions).
size_t EditDistance(const std::string &a, const std::string &b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}
}  // namespace

void RecordOptionName(const std::string &fullName) { ReadNames().insert(fullName); }

std::string ClosestOptionName(const std::string &fullName) {
  std::string best;
  size_t      bestD = std::max<size_t>(2, fullName.size() / 5) + 1;
  for (const std::string &n : ReadNames()) {
    const size_t d = EditDistance(fullName, n);
    if (d < bestD) bestD = d, best = n;
  }
  return best;
}

bool ParseInt(const std::string &text, PetscInt *value) {
  const std::string t = Trim(text);
  if (t.empty()) return false;
  char *end = nullptr;
  errno     = 0;
  const long long v = std::strtoll(t.c_str(), &end, 10);
  if (errno == ERANGE || *end != '\0' || v < PETSC_MIN_INT || v > PETSC_MAX_INT) return false;
  *value = static_cast<PetscInt>(v);
  return true;
}

std::vector<std::string> SplitList(const std::string &text) {
  std::vector<std::string> items;
  std::string              item;
  std::istringstream       in(text);
  while (std::getline(in, item, ',')) items.push_back(Trim(item));
  if (!text.empty() && text.back() == ',') items.push_back("");
  return items;
}

std::string OptionReader::FullName(const char *name) const {
  const char *prefix = items_->prefix;
  return std::string("-") + (prefix ? prefix : "") + (name[0] == '-' ? name + 1 : name);
}

PetscErrorCode OptionReader::RawValue(const char *name, const char **raw, PetscBool *given) const {
  PetscFunctionBeginUser;
  RecordOptionName(FullName(name));
  PetscCall(PetscOptionsFindPair(items_->options, items_->prefix, name, raw, given));
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::Real(const char *name, const char *text, const char *unit, PetscReal *value,
                                  RealRange range, PetscBool *set) {
  PetscOptionItems *PetscOptionsObject = items_;
  const char       *raw                = nullptr;
  PetscBool         given              = PETSC_FALSE;
  PetscReal         v                  = *value;

  PetscFunctionBeginUser;
  PetscCall(RawValue(name, &raw, &given));
  if (given && !ParseReal(raw ? raw : "", &v))
    VofdemInputError(PETSC_COMM_WORLD, "option %s: '%s' is not a number", FullName(name).c_str(), raw ? raw : "");
  if (given && !range.Contains(v))
    VofdemInputError(PETSC_COMM_WORLD, "option %s: %g is out of range, must be in %s", FullName(name).c_str(), (double)v,
                     range.Describe().c_str());
  PetscCall(PetscOptionsReal(name, HelpText(text, unit).c_str(), nullptr, *value, value, set));
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::Int(const char *name, const char *text, PetscInt *value, PetscInt lo, PetscInt hi,
                                 PetscBool *set) {
  PetscOptionItems *PetscOptionsObject = items_;
  const char       *raw                = nullptr;
  PetscBool         given              = PETSC_FALSE;
  PetscInt          v                  = *value;

  PetscFunctionBeginUser;
  PetscCall(RawValue(name, &raw, &given));
  if (given && IntegerTooLarge(raw ? raw : ""))
    VofdemInputError(PETSC_COMM_WORLD, "option %s: %s is too large for this build's 32-bit indices (PETSc's PetscInt: at most %d)", FullName(name).c_str(), raw,
                     (int)PETSC_MAX_INT);
  if (given && !ParseInt(raw ? raw : "", &v))
    VofdemInputError(PETSC_COMM_WORLD, "option %s: '%s' is not an integer", FullName(name).c_str(), raw ? raw : "");
  if (given && (v < lo || v > hi))
    VofdemInputError(PETSC_COMM_WORLD, "option %s: %" PetscInt_FMT " is out of range, must be in [%" PetscInt_FMT ", %" PetscInt_FMT "]",
                     FullName(name).c_str(), v, lo, hi);
  PetscCall(PetscOptionsRangeInt(name, text, nullptr, *value, value, set, lo, hi));
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::Bool(const char *name, const char *text, PetscBool *value, PetscBool *set) {
  PetscOptionItems *PetscOptionsObject = items_;
  const char       *raw                = nullptr;
  PetscBool         given = PETSC_FALSE, isBool = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(RawValue(name, &raw, &given));
  if (given && raw && raw[0]) {
    static const char *const words[] = {"1", "0", "true", "false", "yes", "no", "on", "off"};
    for (const char *w : words) {
      PetscBool same;
      PetscCall(PetscStrcasecmp(raw, w, &same));
      isBool = (PetscBool)(isBool || same);
    }
    if (!isBool) VofdemInputError(PETSC_COMM_WORLD, "option %s: '%s' is not true or false", FullName(name).c_str(), raw);
  }
  PetscCall(PetscOptionsBool(name, text, nullptr, *value, value, set));
  PetscFunctionReturn(0);
}

// Checks that `raw` holds exactly n comma-separated values ("numbers"/"a number", or "integers"/
// "an integer"), each parsed by parse() and accepted by inRange(); describe() names the range.
template <typename T, typename Parse, typename InRange, typename Describe>
static PetscErrorCode CheckVector(const std::string &option, const char *raw, PetscInt n, const char *kinds, const char *kind, Parse parse, InRange inRange,
                                  Describe describe) {
  PetscFunctionBeginUser;
  const auto parts = SplitList(raw ? raw : "");
  if ((PetscInt)parts.size() != n)
    VofdemInputError(PETSC_COMM_WORLD, "option %s: needs %" PetscInt_FMT " comma-separated %s, got '%s'", option.c_str(), n, kinds, raw ? raw : "");
  for (const auto &p : parts) {
    T v;
    if (!parse(p, &v)) VofdemInputError(PETSC_COMM_WORLD, "option %s: '%s' is not %s", option.c_str(), p.c_str(), kind);
    if (!inRange(v)) VofdemInputError(PETSC_COMM_WORLD, "option %s: %s is out of range, must be in %s", option.c_str(), p.c_str(), describe().c_str());
  }
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::RealVector(const char *name, const char *text, const char *unit, PetscReal *value, PetscInt n, RealRange range,
                                        PetscBool *set) {
  PetscOptionItems *PetscOptionsObject = items_;
  const char       *raw                = nullptr;
  PetscBool         given              = PETSC_FALSE;
  PetscInt          count              = n;

  PetscFunctionBeginUser;
  PetscCall(RawValue(name, &raw, &given));
  if (given)
    PetscCall(CheckVector<PetscReal>(
      FullName(name), raw, n, "numbers", "a number", ParseReal, [&](PetscReal v) { return range.Contains(v); }, [&] { return range.Describe(); }));
  PetscCall(PetscOptionsRealArray(name, VectorHelp(text, unit, value, n).c_str(), nullptr, value, &count, set));
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::IntVector(const char *name, const char *text, PetscInt *value, PetscInt n, PetscInt lo, PetscInt hi, PetscBool *set) {
  PetscOptionItems *PetscOptionsObject = items_;
  const char       *raw                = nullptr;
  PetscBool         given              = PETSC_FALSE;
  PetscInt          count              = n;

  PetscFunctionBeginUser;
  PetscCall(RawValue(name, &raw, &given));
  if (given)
    PetscCall(CheckVector<PetscInt>(
      FullName(name), raw, n, "integers", "an integer", ParseInt, [&](PetscInt v) { return v >= lo && v <= hi; },
      [&] { return "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]"; }));
  PetscCall(PetscOptionsIntArray(name, VectorHelp(text, "", value, n).c_str(), nullptr, value, &count, set));
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::RealList(const char *name, const char *text, const char *unit, std::vector<PetscReal> *value, PetscInt maxCount,
                                      RealRange range, PetscBool *set) {
  std::string joined;
  PetscBool   given = PETSC_FALSE;

  PetscFunctionBeginUser;
  {
    std::ostringstream s;
    for (size_t i = 0; i < value->size(); ++i) s << (i ? "," : "") << (*value)[i];
    joined = s.str();
  }
  PetscCall(String(name, HelpText(text, unit).c_str(), &joined, &given));
  if (given) {
    const auto parts = SplitList(joined);
    if (parts.empty() || (PetscInt)parts.size() > maxCount)
      VofdemInputError(PETSC_COMM_WORLD, "option %s: needs 1 to %" PetscInt_FMT " comma-separated numbers, got '%s'", FullName(name).c_str(), maxCount,
                       joined.c_str());
    value->clear();
    for (const auto &p : parts) {
      PetscReal v;
      if (!ParseReal(p, &v)) VofdemInputError(PETSC_COMM_WORLD, "option %s: '%s' is not a number", FullName(name).c_str(), p.c_str());
      if (!range.Contains(v))
        VofdemInputError(PETSC_COMM_WORLD, "option %s: %s is out of range, must be in %s", FullName(name).c_str(), p.c_str(), range.Describe().c_str());
      value->push_back(v);
    }
  }
  if (set) *set = given;
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::NameList(const char *name, const char *text, const std::vector<std::string> &allowed,
                                      std::vector<std::string> *value, PetscBool *set) {
  std::string joined;
  PetscBool   given = PETSC_FALSE;

  PetscFunctionBeginUser;
  for (const auto &v : *value) joined += (joined.empty() ? "" : ",") + v;
  PetscCall(String(name, (std::string(text) + " (any of: " + Join(allowed) + ")").c_str(), &joined, &given));
  if (given) {
    value->clear();
    for (const auto &item : SplitList(joined)) {
      bool known = false;
      for (const auto &a : allowed) known = known || a == item;
      if (!known)
        VofdemInputError(PETSC_COMM_WORLD, "option %s: unknown name '%s' (known: %s)", FullName(name).c_str(), item.c_str(),
                         Join(allowed).c_str());
      value->push_back(item);
    }
  }
  if (set) *set = given;
  PetscFunctionReturn(0);
}

PetscErrorCode OptionReader::String(const char *name, const char *text, std::string *value, PetscBool *set) {
  PetscOptionItems *PetscOptionsObject = items_;
  char              buffer[PETSC_MAX_PATH_LEN];
  PetscBool         given = PETSC_FALSE;

  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(buffer, value->c_str(), sizeof(buffer)));
  PetscCall(PetscOptionsString(name, text, nullptr, value->c_str(), buffer, sizeof(buffer), &given));
  if (given) *value = buffer;
  if (set) *set = given;
  PetscFunctionReturn(0);
}

}  // namespace vofdem
