// STL reading (ASCII and binary) and vertex welding for mesh walls.
#include "vofdem/dem/StlMesh.hpp"

#include "vofdem/base/Runtime.hpp"
#include "vofdem/io/InputPath.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>

namespace vofdem {

PetscInt StlMesh::Build(const std::vector<PetscReal> &corners) {
  std::map<std::array<PetscReal, 3>, PetscInt>  vertexOf;
  std::map<std::pair<PetscInt, PetscInt>, PetscInt> edgeOf;
  PetscInt                                      dropped = 0;
  vertex.clear(), triVertex.clear(), triEdge.clear(), corner.clear(), edges = 0;
  for (size_t t = 0; 9 * t + 8 < corners.size(); ++t) {
    const PetscReal *c = &corners[9 * t];
    // Zero area: no normal, no face; its edges are edges of its neighbours anyway.
    const PetscReal e0[3] = {c[3] - c[0], c[4] - c[1], c[5] - c[2]}, e1[3] = {c[6] - c[0], c[7] - c[1], c[8] - c[2]};
    const PetscReal n[3]  = {e0[1] * e1[2] - e0[2] * e1[1], e0[2] * e1[0] - e0[0] * e1[2], e0[0] * e1[1] - e0[1] * e1[0]};
    if (n[0] == 0 && n[1] == 0 && n[2] == 0) {
      ++dropped;
      continue;
    }
    PetscInt v[3];
    for (int k = 0; k < 3; ++k) {
      const std::array<PetscReal, 3> key = {c[3 * k], c[3 * k + 1], c[3 * k + 2]};
      auto                           it  = vertexOf.find(key);
      if (it == vertexOf.end()) {
        it = vertexOf.emplace(key, (PetscInt)(vertex.size() / 3)).first;
        vertex.insert(vertex.end(), key.begin(), key.end());
      }
      v[k] = it->second;
      triVertex.push_back(v[k]);
    }
    for (int k = 0; k < 3; ++k) {
      const PetscInt a = v[k], b = v[(k + 1) % 3];
      auto           it = edgeOf.emplace(std::make_pair(std::min(a, b), std::max(a, b)), edges).first;
      if (it->second == edges) ++edges;
      triEdge.push_back(it->second);
    }
    corner.insert(corner.end(), c, c + 9);
  }
  return dropped;
}

namespace {

bool ParseBinary(const std::string &bytes, PetscReal scale, const PetscReal offset[3], std::vector<PetscReal> *corners, std::string *error) {
  std::uint32_t n;
  std::memcpy(&n, bytes.data() + 80, 4);
  corners->assign(9 * (size_t)n, 0);
  for (std::uint32_t t = 0; t < n; ++t)
    for (int k = 0; k < 9; ++k) {
      float x;  // little-endian IEEE floats, as every machine here
      std::memcpy(&x, bytes.data() + 84 + 50 * (size_t)t + 12 + 4 * k, 4);
      if (!std::isfinite(x)) {
        *error = "binary STL: triangle " + std::to_string(t + 1) + " has a coordinate that is not a finite number";
        return false;
      }
      (*corners)[9 * (size_t)t + k] = scale * x + offset[k % 3];
    }
  return true;
}

bool ParseAscii(const std::string &bytes, PetscReal scale, const PetscReal offset[3], std::vector<PetscReal> *corners, std::string *error) {
  std::istringstream in(bytes);
  std::string        line;
  int                lineNo = 0, vertices = 0;  // vertices read in the current loop
  bool               started = false, inFacet = false, inLoop = false, ended = false;
  corners->clear();
  auto fail = [&](const std::string &what) {
    *error = "ASCII STL line " + std::to_string(lineNo) + ": " + what;
    return false;
  };
  while (std::getline(in, line)) {
    ++lineNo;
    std::istringstream words(line);
    std::string        key;
    if (!(words >> key)) continue;
    if (ended) return fail("text after 'endsolid'");
    if (!started || key == "solid") {
      if (key != "solid" || started) return fail("expected 'solid' on the first line only");
      started = true;
    } else if (key == "facet") {
      if (inFacet) return fail("'facet' inside a facet");
      std::string normal;
      PetscReal   nx, ny, nz;
      if (!(words >> normal >> nx >> ny >> nz) || normal != "normal") return fail("expected 'facet normal nx ny nz'");
      inFacet = true;
    } else if (key == "outer") {
      std::string loop;
      if (!inFacet || inLoop || !(words >> loop) || loop != "loop") return fail("'outer loop' outside a facet");
      inLoop = true, vertices = 0;
    } else if (key == "vertex") {
      PetscReal x[3];
      if (!inLoop) return fail("'vertex' outside 'outer loop'");
      if (!(words >> x[0] >> x[1] >> x[2])) return fail("expected 'vertex x y z' with three numbers");
      if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2])) return fail("a vertex coordinate is not a finite number");
      if (++vertices > 3) return fail("more than three vertices in a facet");
      for (int d = 0; d < 3; ++d) corners->push_back(scale * x[d] + offset[d]);
    } else if (key == "endloop") {
      if (!inLoop || vertices != 3) return fail("'endloop' after " + std::to_string(vertices) + " vertices, expected 3");
      inLoop = false;
    } else if (key == "endfacet") {
      if (!inFacet || inLoop) return fail("'endfacet' without a closed 'outer loop'");
      inFacet = false;
    } else if (key == "endsolid") {
      if (inFacet) return fail("'endsolid' inside a facet");
      ended = true;
    } else {
      return fail("unexpected '" + key + "'");
    }
    std::string extra;
    if (key != "solid" && key != "endsolid" && words >> extra) return fail("unexpected '" + extra + "' after '" + key + "'");
  }
  if (!ended) return fail("the file ends before 'endsolid'");
  return true;
}

}  // namespace

bool ParseStl(const std::string &bytes, PetscReal scale, const PetscReal offset[3], std::vector<PetscReal> *corners, std::string *error) {
  if (bytes.size() >= 84) {
    std::uint32_t n;
    std::memcpy(&n, bytes.data() + 80, 4);
    if (bytes.size() == 84 + 50 * (size_t)n) return ParseBinary(bytes, scale, offset, corners, error);
  }
  const size_t first = bytes.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && bytes.compare(first, 5, "solid") == 0 && bytes.find('\0') == std::string::npos)
    return ParseAscii(bytes, scale, offset, corners, error);
  if (bytes.size() >= 84) {
    std::uint32_t n;
    std::memcpy(&n, bytes.data() + 80, 4);
    *error = "binary STL: the header announces " + std::to_string(n) + " triangles (" + std::to_string(84 + 50 * (size_t)n) + " bytes), the file has " +
             std::to_string(bytes.size()) + " bytes (truncated?)";
  } else {
    *error = "not an STL file (neither ASCII starting with 'solid' nor binary with an 84-byte header)";
  }
  return false;
}

PetscErrorCode ReadStlMesh(MPI_Comm comm, const std::string &path, PetscReal scale, const PetscReal offset[3], const char *option, StlMesh *mesh) {
  PetscMPIInt            rank;
  long long              size = -1;
  std::string            bytes, error;
  std::vector<PetscReal> corners;

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank == 0) {
    std::ifstream f(path, std::ios::binary);
    if (f) {
      std::ostringstream s;
      s << f.rdbuf();
      if (f || f.eof()) bytes = s.str(), size = (long long)bytes.size();
    }
  }
  PetscCallMPI(MPI_Bcast(&size, 1, MPI_LONG_LONG, 0, comm));
  if (size < 0) VofdemInputError(comm, "option %s: cannot read '%s'%s", option, path.c_str(), RelativePathNote(path).c_str());
  bytes.resize((size_t)size);
  PetscCallMPI(MPI_Bcast(bytes.data(), (int)size, MPI_CHAR, 0, comm));
  if (!ParseStl(bytes, scale, offset, &corners, &error)) VofdemInputError(comm, "option %s: '%s': %s", option, path.c_str(), error.c_str());
  mesh->Build(corners);
  if (mesh->Triangles() == 0) VofdemInputError(comm, "option %s: '%s' holds no triangle of non-zero area", option, path.c_str());
  PetscFunctionReturn(0);
}

std::string BinaryStl(const std::vector<PetscReal> &corners) {
  const std::uint32_t n = (std::uint32_t)(corners.size() / 9);
  std::string         out(84 + 50 * (size_t)n, '\0');
  std::memcpy(&out[0], "vofdem binary STL", 17);
  std::memcpy(&out[80], &n, 4);
  for (std::uint32_t t = 0; t < n; ++t)
    for (int k = 0; k < 9; ++k) {
      const float x = (float)corners[9 * (size_t)t + k];
      std::memcpy(&out[84 + 50 * (size_t)t + 12 + 4 * k], &x, 4);
    }
  return out;
}

}  // namespace vofdem
