// A triangle mesh read from STL (ASCII or binary), scaled and shifted, with its vertices welded (bit-
// equal coordinates are one vertex) and its edges numbered, so that contacts on an edge or vertex
// shared by several triangles can be recognised as one (WallSet's "counted once" rule).
#pragma once

#include <petscsys.h>

#include <string>
#include <vector>

namespace vofdem {

struct StlMesh {
  std::vector<PetscReal> vertex;        // 3 per welded vertex, m
  std::vector<PetscInt>  triVertex;     // 3 per triangle: vertex indices (a, b, c)
  std::vector<PetscInt>  triEdge;       // 3 per triangle: edge indices of ab, bc, ca
  std::vector<PetscReal> corner;        // 9 per triangle: a, b, c copied, so the contact loop reads one block
  PetscInt               edges = 0;     // number of distinct edges

  PetscInt Triangles() const { return (PetscInt)triVertex.size() / 3; }
  // Builds the welded mesh from 9 coordinates per triangle (already scaled and shifted); drops
  // triangles of zero area (they have no normal). Returns the number dropped.
  PetscInt Build(const std::vector<PetscReal> &corners);
};

// Parses an STL file's bytes: binary when the size is exactly 84 + 50 n bytes for the n the
// header gives, otherwise ASCII ("solid ... facet normal ... outer loop vertex x y z ..."). Each
// coordinate becomes scale * x + offset. On failure returns false and a one-line reason in *error
// (naming the line of ASCII files, or the byte counts of a truncated binary one).
bool ParseStl(const std::string &bytes, PetscReal scale, const PetscReal offset[3], std::vector<PetscReal> *corners, std::string *error);

// Collective: rank 0 reads the file, every rank parses the same bytes (so all fail alike), builds
// the mesh. Raises a one-line input error naming `option` on an unreadable, malformed or empty file.
PetscErrorCode ReadStlMesh(MPI_Comm comm, const std::string &path, PetscReal scale, const PetscReal offset[3], const char *option, StlMesh *mesh);

// Binary STL bytes of the given triangles (9 coordinates each), for examples and tests.
std::string BinaryStl(const std::vector<PetscReal> &corners);

}  // namespace vofdem
