#include "vofdem/sim/CheckpointFile.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <vector>

namespace vofdem {

namespace {

// Options that may differ between a run and its restart without changing what is computed.
const char *const kFreeExact[] = {"-restart", "-max_steps", "-final_time", "-output_dir", "-help", "-allow_unused_options", "-grid_ranks",
                                  "-dem_save_particles", "-dem_save_contact_history", "-flow_profile_output", "-no_signal_handler", "-on_error_abort", "-info",
                                  "-stop_kinetic_energy", "-stop_kinetic_energy_after", "-dem_output_every", "-dem_contacts_every",
                                  "-flow_output_every"};
// -analysis_*: the powder-bed analysis reads the particles at the end and changes nothing in the run.
const char *const kFreePrefix[] = {"-checkpoint_", "-monitor_", "-log_", "-options_", "-malloc", "-memory_", "-analysis_"};

// Options that may change at a restart, deliberately changing what is computed from then on (docs/modules/checkpoint.md):
// the laser's power, path and timing (a long track continued with another power or path). The beam's place and power
// at time t follow the new values as if they had held from the start.
const char *const kChangeable[] = {"-laser_power", "-laser_path", "-laser_speed", "-laser_start_time", "-laser_stop_time", "-laser_ramp_time"};

bool IsChangeable(const std::string &name) {
  for (const char *e : kChangeable)
    if (name == e) return true;
  return false;
}

bool IsFree(const std::string &name) {
  for (const char *e : kFreeExact)
    if (name == e) return true;
  for (const char *p : kFreePrefix)
    if (name.compare(0, std::strlen(p), p) == 0) return true;
  return false;
}

// A token of PetscOptionsGetAll's text is an option name when it is '-' and a letter: "-1e-3" is a value.
bool IsName(const std::string &t) { return t.size() > 1 && t[0] == '-' && std::isalpha((unsigned char)t[1]); }

constexpr std::uint64_t kFnvOffset = 1469598103934665603ull, kFnvPrime = 1099511628211ull;

void Hash(std::uint64_t *h, const void *bytes, size_t n) {
  const unsigned char *b = (const unsigned char *)bytes;
  for (size_t k = 0; k < n; ++k) *h = (*h ^ b[k]) * kFnvPrime;
}

herr_t CollectDataset(hid_t group, const char *name, const H5L_info_t *, void *names) {
  hid_t obj = H5Oopen(group, name, H5P_DEFAULT);
  if (obj < 0) return -1;
  const bool dataset = H5Iget_type(obj) == H5I_DATASET;
  H5Oclose(obj);
  if (dataset) ((std::vector<std::string> *)names)->push_back(name);
  return 0;
}

herr_t CollectAttribute(hid_t, const char *name, const H5A_info_t *, void *names) {
  if (std::strcmp(name, "checksum")) ((std::vector<std::string> *)names)->push_back(name);
  return 0;
}

// Hashes the name and the whole value of the attribute (attribute) or dataset `name` of `file`:
// strings as stored, numbers in the native layout. False when it cannot be read.
bool HashObject(hid_t file, const std::string &name, bool attribute, std::uint64_t *sum) {
  Hash(sum, name.c_str(), name.size() + 1);
  const hid_t id    = attribute ? H5Aopen(file, name.c_str(), H5P_DEFAULT) : H5Dopen2(file, name.c_str(), H5P_DEFAULT);
  const hid_t ftype = id < 0 ? -1 : attribute ? H5Aget_type(id) : H5Dget_type(id);
  const hid_t space = id < 0 ? -1 : attribute ? H5Aget_space(id) : H5Dget_space(id);
  const bool  str   = ftype >= 0 && H5Tget_class(ftype) == H5T_STRING;
  const hid_t mtype = ftype < 0 || (str && H5Tis_variable_str(ftype)) ? -1 : str ? H5Tcopy(ftype) : H5Tget_native_type(ftype, H5T_DIR_ASCEND);
  const hssize_t n  = space >= 0 ? H5Sget_simple_extent_npoints(space) : -1;
  bool           ok = mtype >= 0 && n >= 0;
  if (ok) {
    std::vector<char> buf((size_t)n * H5Tget_size(mtype) + 1, '\0');
    if (n > 0) ok = (attribute ? H5Aread(id, mtype, buf.data()) : H5Dread(id, mtype, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf.data())) >= 0;
    if (ok) Hash(sum, buf.data(), buf.size() - 1);
  }
  if (space >= 0) H5Sclose(space);
  if (mtype >= 0) H5Tclose(mtype);
  if (ftype >= 0) H5Tclose(ftype);
  if (id >= 0) attribute ? H5Aclose(id) : H5Dclose(id);
  return ok;
}

// FNV-1a over the root attributes but "checksum" (format, options, the clock), then every dataset,
// each in name order (HashObject).
bool Checksum(hid_t file, std::uint64_t *sum, std::string *why) {
  std::vector<std::string> attributes, datasets;
  hsize_t                  at = 0;
  if (H5Aiterate2(file, H5_INDEX_NAME, H5_ITER_INC, &at, CollectAttribute, &attributes) < 0 ||
      H5Lvisit(file, H5_INDEX_NAME, H5_ITER_INC, CollectDataset, &datasets) < 0) {
    *why = "its structure cannot be read (corrupted)";
    return false;
  }
  std::sort(attributes.begin(), attributes.end());
  std::sort(datasets.begin(), datasets.end());
  *sum = kFnvOffset;
  for (const std::string &name : attributes)
    if (!HashObject(file, name, true, sum)) {
      *why = "attribute " + name + " cannot be read (corrupted)";
      return false;
    }
  for (const std::string &name : datasets)
    if (!HashObject(file, name, false, sum)) {
      *why = "dataset " + name + " cannot be read (truncated or corrupted)";
      return false;
    }
  return true;
}

bool ReadString(hid_t file, const char *name, std::string *value) {
  hid_t attr = H5Aopen(file, name, H5P_DEFAULT);
  if (attr < 0) return false;
  hid_t             type = H5Aget_type(attr);
  bool              ok   = type >= 0 && H5Tget_class(type) == H5T_STRING && !H5Tis_variable_str(type);
  std::vector<char> buf(ok ? H5Tget_size(type) + 1 : 1, '\0');
  ok = ok && H5Aread(attr, type, buf.data()) >= 0;
  if (ok) value->assign(buf.data());
  if (type >= 0) H5Tclose(type);
  H5Aclose(attr);
  return ok;
}

template <class T>
bool ReadNumber(hid_t file, const char *name, hid_t memType, T *value) {
  hid_t attr = H5Aopen(file, name, H5P_DEFAULT);
  if (attr < 0) return false;
  const bool ok = H5Aread(attr, memType, value) >= 0;
  H5Aclose(attr);
  return ok;
}

}  // namespace

PetscErrorCode RunDefiningOptions(std::string *text) {
  char *all;

  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetAll(nullptr, &all));
  std::istringstream       in(all);
  std::vector<std::string> lines;
  std::string              token;
  bool                     keep = false;
  while (in >> token) {
    if (IsName(token)) {
      keep = !IsFree(token);
      if (keep) lines.push_back(token);
    } else if (keep && !lines.empty()) {
      lines.back() += " " + token;
    }
  }
  PetscCall(PetscFree(all));
  std::sort(lines.begin(), lines.end());
  text->clear();
  for (const std::string &l : lines) *text += l + "\n";
  PetscFunctionReturn(0);
}

namespace {

// A line "-name value" with every number of the value (separated by spaces or commas) printed in
// one way: 2.5e-4, 0.00025 and 2.50e-04 are the same option value.
std::string Canonical(const std::string &line) {
  std::string out, token;
  auto flush = [&]() {
    char  *end = nullptr;
    double v   = token.empty() ? 0 : std::strtod(token.c_str(), &end);
    if (!token.empty() && end && *end == '\0') {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.17g", v);
      out += buf;
    } else out += token;
    token.clear();
  };
  for (char c : line) {
    if (c == ' ' || c == ',') flush(), out += c;
    else token += c;
  }
  flush();
  return out;
}

}  // namespace

std::string FirstDifference(const std::string &saved, const std::string &current) {
  std::istringstream a(saved), b(current);
  std::string        la, lb;
  // A checkpoint of an older vofdem may list options that are free now (-analysis_* since 2026-11-27).
  auto next = [](std::istringstream &in, std::string *line) {
    while (std::getline(in, *line)) {
      const std::string name = line->substr(0, line->find(' '));
      if (!IsFree(name) && !IsChangeable(name)) return true;
    }
    return false;
  };
  while (true) {
    const bool ha = next(a, &la), hb = next(b, &lb);
    if (!ha && !hb) return "";
    if (ha && hb && Canonical(la) == Canonical(lb)) continue;
    // Sorted lists: the smaller line is the one missing from the other side.
    if (ha && (!hb || la < lb) && la.substr(0, la.find(' ')) != lb.substr(0, lb.find(' ')))
      return "'" + la + "' in the checkpoint, not in this run";
    if (hb && (!ha || lb < la) && la.substr(0, la.find(' ')) != lb.substr(0, lb.find(' ')))
      return "'" + lb + "' in this run, not in the checkpoint";
    return "'" + la + "' in the checkpoint, '" + lb + "' in this run";
  }
}

std::string ChangedAtRestart(const std::string &saved, const std::string &current) {
  auto values = [](const std::string &text) {
    std::istringstream                               in(text);
    std::string                                      line;
    std::vector<std::pair<std::string, std::string>> kv;
    while (std::getline(in, line)) {
      const size_t      cut  = line.find(' ');
      const std::string name = line.substr(0, cut);
      if (IsChangeable(name)) kv.push_back({name, cut == std::string::npos ? "" : Canonical(line).substr(cut + 1)});
    }
    return kv;
  };
  const auto  a = values(saved), b = values(current);
  std::string out;
  for (const char *name : kChangeable) {
    std::string va = "(not given)", vb = "(not given)";
    for (const auto &kv : a)
      if (kv.first == name) va = kv.second;
    for (const auto &kv : b)
      if (kv.first == name) vb = kv.second;
    if (va != vb) out += std::string(out.empty() ? "" : "; ") + name + " " + va + " -> " + vb;
  }
  return out;
}

bool SealCheckpoint(const std::string &path, std::string *why) {
  QuietHdf5     quiet;
  std::uint64_t sum  = 0;
  hid_t         file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (file < 0) {
    *why = "cannot reopen it to seal it";
    return false;
  }
  bool ok = Checksum(file, &sum, why);
  if (ok) {
    hid_t space = H5Screate(H5S_SCALAR);
    hid_t attr  = H5Acreate2(file, "checksum", H5T_STD_U64LE, space, H5P_DEFAULT, H5P_DEFAULT);
    ok          = attr >= 0 && H5Awrite(attr, H5T_NATIVE_UINT64, &sum) >= 0;
    if (attr >= 0) H5Aclose(attr);
    H5Sclose(space);
    if (!ok) *why = "cannot write its checksum";
  }
  if (H5Fclose(file) < 0 && ok) {
    *why = "cannot close it after sealing (disk full?)";
    ok   = false;
  }
  return ok;
}

bool ReadCheckpointHeader(const std::string &path, CheckpointHeader *h, std::string *why) {
  QuietHdf5 quiet;
  if (H5Fis_hdf5(path.c_str()) <= 0) {
    *why = "cannot open it as HDF5 (missing, truncated or not a checkpoint)";
    return false;
  }
  hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) {
    *why = "cannot open it as HDF5 (truncated or corrupted)";
    return false;
  }
  bool          ok    = false;
  std::uint64_t saved = 0, sum = 0;
  if (!ReadNumber(file, "vofdem_checkpoint_format", H5T_NATIVE_INT, &h->format)) *why = "it is not a vofdem checkpoint (no format version)";
  else if (h->format != kCheckpointFormat)
    *why = "format version " + std::to_string(h->format) + ", this vofdem reads version " + std::to_string(kCheckpointFormat);
  else if (!ReadNumber(file, "checksum", H5T_NATIVE_UINT64, &saved)) *why = "it has no checksum (its writing did not finish)";
  else if (!ReadString(file, "run_options", &h->options) || !ReadString(file, "physics", &h->physics) ||
           !ReadNumber(file, "ranks", H5T_NATIVE_INT, &h->ranks) || !ReadNumber(file, "simulation_step", H5T_NATIVE_LLONG, &h->step))
    *why = "its header is incomplete (corrupted)";
  else if (Checksum(file, &sum, why)) {
    ok = sum == saved;
    if (!ok) *why = "checksum mismatch (corrupted)";
  }
  H5Fclose(file);
  return ok;
}

}  // namespace vofdem
