// What an error about an input file says of where a relative path was looked for: scene files name
// their STL meshes and particle files relative to the working directory (config/scenes/... from the
// repository's top), and a run started elsewhere should say so, not only "cannot read".
#pragma once

#include <string>

namespace vofdem {

// "" for an absolute path; otherwise " (a relative path starts at the working directory '<cwd>')".
std::string RelativePathNote(const std::string &path);

}  // namespace vofdem
