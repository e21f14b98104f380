// MaterialFile.hpp: the material search path.
#include "vofdem/io/MaterialFile.hpp"

#include <cstdio>
#include <cstdlib>
#include <vector>

namespace vofdem {

std::string FindMaterialFile(const std::string &name) {
  auto readable = [](const std::string &p) {
    FILE *f = std::fopen(p.c_str(), "rb");
    if (f) std::fclose(f);
    return f != nullptr;
  };
  if (name.find('/') != std::string::npos || (name.size() > 5 && name.compare(name.size() - 5, 5, ".yaml") == 0)) return readable(name) ? name : "";
  std::vector<std::string> dirs;
  if (const char *env = std::getenv("VOFDEM_MATERIALS_DIR")) dirs.push_back(env);
#ifdef VOFDEM_MATERIALS_DIR
  dirs.push_back(VOFDEM_MATERIALS_DIR);
#endif
  for (const auto &d : dirs)
    if (readable(d + "/" + name + ".yaml")) return d + "/" + name + ".yaml";
  return "";
}

}  // namespace vofdem
