// The drag laws by name (DragLaws.hpp): one row per law. A new law is a function in a file of its own
// (its formula and its reference, declared here) and one row below; -coupling_drag and its help follow.
#include "vofdem/coupling/DragLaws.hpp"

#include <algorithm>

namespace vofdem {
namespace drag {

const std::vector<Entry> &Table() {
  static const std::vector<Entry> table = {
    {"gidaspow", "Wen-Yu above eps = -coupling_drag_switch, Ergun below", [](const Input &i) { return Gidaspow(i.d, i.eps, i.slip, i.rho, i.mu, i.eSwitch); }},
    {"difelice", "Di Felice 1994, eps times the total force", [](const Input &i) { return DiFelice(i.d, i.eps, i.slip, i.rho, i.mu); }},
    {"wenyu", "Wen and Yu 1966", [](const Input &i) { return WenYu(i.d, i.eps, i.slip, i.rho, i.mu); }},
    {"ergun", "Ergun 1952, dense beds", [](const Input &i) { return Ergun(i.d, i.eps, i.slip, i.rho, i.mu); }},
    {"schillernaumann", "the single sphere, no eps", [](const Input &i) { return SchillerNaumann(i.d, i.slip, i.rho, i.mu); }},
    {"kochhill", "Koch and Hill 2001, eps times the total force", [](const Input &i) { return KochHill(i.d, i.eps, i.slip, i.rho, i.mu); }},
    {"beetstra", "Beetstra, van der Hoef and Kuipers 2007, monodisperse", [](const Input &i) { return Beetstra(i.d, i.eps, i.slip, i.rho, i.mu); }},
  };
  return table;
}

const std::vector<std::string> &Names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const Entry &e : Table()) n.push_back(e.name);
    return n;
  }();
  return names;
}

Law Find(const std::string &name) {
  for (const Entry &e : Table())
    if (name == e.name) return &e;
  return nullptr;
}

bool Parse(const std::string &name, Law *law) {
  const Law found = Find(name);
  if (found) *law = found;
  return found != nullptr;
}

const char *Name(Law law) { return law->name; }

std::string Help() {
  std::string s;
  for (const Entry &e : Table()) s += (s.empty() ? "" : ", ") + std::string(e.name) + " (" + e.summary + ")";
  return s;
}

}  // namespace drag
}  // namespace vofdem
