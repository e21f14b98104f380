// The XDMF index ParaView opens: one temporal collection whose entries point at datasets of HDF5
// files written next to it. The index is kept in memory and rewritten whole (temporary file, then
// rename) at each output, so a reader never sees half of it.
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace vofdem {

struct XdmfAttribute {
  std::string name, dataset;  // dataset path in the entry's HDF5 file, e.g. "/velocity"
  int         components = 1; // 1: Scalar, 3: Vector
  bool        cell       = false;  // Center="Cell" (per element) instead of "Node"
};

// One time level: points (Polyvertex), segments (Polyline of 2 nodes with a connectivity dataset),
// or a uniform grid of cells (3DCoRectMesh, `cells` >= 0, with cell-centred attributes whose HDF5
// datasets are shaped z, y, x[, components], as a DMDA vector is written).
struct XdmfEntry {
  PetscReal   time = 0;
  PetscInt    step = 0;
  std::string file;              // HDF5 file name relative to the index
  PetscInt    nodes = 0;         // number of points
  PetscInt    segments = -1;     // >= 0: Polyline with this many 2-node elements
  std::string geometry = "/position", connectivity = "/connectivity";
  PetscInt    cells[3] = {-1, -1, -1};                   // x, y, z cell counts of a uniform grid
  PetscReal   origin[3] = {0, 0, 0}, spacing[3] = {0, 0, 0};  // its lower corner and cell size, x, y, z
  std::vector<XdmfAttribute> attributes;
};

// The whole index text for `entries` (a temporal collection named `name`).
std::string XdmfIndexText(const std::string &name, const std::vector<XdmfEntry> &entries);

}  // namespace vofdem
