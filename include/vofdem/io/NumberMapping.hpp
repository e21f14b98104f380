// A YAML file that maps names to numbers or to tables of numbers (a material file of the energy module,
// docs/modules/energy.md):
//   density: 8380              a number
//   conductivity: [[300, 11.4], [1600, 29.6]]   a table: rows of equal length
// Anything else (nesting deeper, a string, a key given twice) is refused with one line naming the file,
// the line and what is wrong.
#pragma once

#include <petscsys.h>

#include <map>
#include <string>
#include <vector>

namespace vofdem {

struct NumberEntry {
  std::vector<std::vector<PetscReal>> rows;  // a number is one row of one value
  int                                 line = 0;  // 1-based, for messages
  bool IsNumber() const { return rows.size() == 1 && rows[0].size() == 1 && !table; }
  bool table = false;  // written as a list
};

using NumberMapping = std::map<std::string, NumberEntry>;

// Reads path into *out; false with *message ("path:line: what is wrong") on failure.
bool ReadNumberMapping(const std::string &path, NumberMapping *out, std::string *message);

}  // namespace vofdem
