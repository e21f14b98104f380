#include "vofdem/io/InputPath.hpp"

#include <filesystem>
#include <system_error>

namespace vofdem {

std::string RelativePathNote(const std::string &path) {
  if (path.empty() || path[0] == '/') return "";
  std::error_code ec;
  const std::string cwd = std::filesystem::current_path(ec).string();
  return ec ? std::string(" (a relative path starts at the working directory)") : " (a relative path starts at the working directory '" + cwd + "')";
}

}  // namespace vofdem
