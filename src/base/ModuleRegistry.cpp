// ModuleRegistry.hpp: the build's modules and the choice of a scene's.
#include "vofdem/base/ModuleRegistry.hpp"

#include "vofdem/base/Runtime.hpp"

#include <algorithm>

namespace vofdem {

const ModuleRegistry &ModuleRegistry::Built() {
  static const ModuleRegistry registry = [] {
    ModuleRegistry r;
    RegisterBuiltModules(r);
    return r;
  }();
  return registry;
}

void ModuleRegistry::Add(ModuleEntry entry) { entries_.push_back(std::move(entry)); }

std::vector<std::string> ModuleRegistry::PhysicsWords() const {
  std::vector<std::string> words;
  for (const ModuleEntry &e : entries_)
    if (e.impliedBy.empty()) words.push_back(e.name);
  return words;
}

const ModuleEntry *ModuleRegistry::Find(const std::string &name) const {
  for (const ModuleEntry &e : entries_)
    if (e.name == name) return &e;
  return nullptr;
}

static std::string Join(const std::vector<std::string> &v) {
  std::string s;
  for (const std::string &w : v) s += (s.empty() ? "" : ", ") + w;
  return s;
}

PetscErrorCode SelectModules(MPI_Comm comm, const std::vector<std::string> &words, std::vector<std::string> *on) {
  const ModuleRegistry &registry = ModuleRegistry::Built();
  const auto            named    = [&words](const std::string &w) { return std::find(words.begin(), words.end(), w) != words.end(); };

  PetscFunctionBeginUser;
  on->clear();
  if (words.empty()) VofdemInputError(comm, "option -physics: name at least one module (available: %s)", Join(registry.PhysicsWords()).c_str());
  for (const std::string &w : words) {
    const ModuleEntry *e = registry.Find(w);
    if (!e || !e->impliedBy.empty()) VofdemInputError(comm, "option -physics: '%s' is not a module of this build (available: %s)", w.c_str(), Join(registry.PhysicsWords()).c_str());
  }
  for (const ModuleEntry &e : registry.Entries()) {
    const bool wanted = e.impliedBy.empty() ? named(e.name) : std::all_of(e.impliedBy.begin(), e.impliedBy.end(), named);
    if (!wanted) continue;
    for (const std::string &need : e.needs)
      if (!named(need)) VofdemInputError(comm, "option -physics: '%s' needs '%s' (%s)", e.name.c_str(), need.c_str(), e.needsReason.c_str());
    on->push_back(e.name);
  }
  PetscFunctionReturn(0);
}

std::string DescribePhysics(const std::vector<std::string> &on) {
  const ModuleRegistry &registry = ModuleRegistry::Built();
  std::string           s;
  for (const std::string &name : on) {
    const ModuleEntry *e = registry.Find(name);
    if (e && e->impliedBy.empty()) s += (s.empty() ? "" : ",") + name;
  }
  return s.empty() ? "none" : s;
}

}  // namespace vofdem
