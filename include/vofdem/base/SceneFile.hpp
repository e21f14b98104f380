// Checks a scene file before PETSc reads it, so that a bad file gives one line naming the file
// and, for YAML, the line and column of the problem.
#pragma once

#include <string>

namespace vofdem {

enum class SceneFormat { Yaml, Plain };

// Returns true when `path` can be read and (for YAML) parses into a mapping of options; otherwise
// false with `message` set to "<path>[:line:col]: <what is wrong>".
bool CheckSceneFile(const std::string &path, SceneFormat format, std::string *message);

}  // namespace vofdem
