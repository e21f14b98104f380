// Rewrites the values of an assembled AIJ matrix in place, for assemblies that set the same entries of the
// same rows in the same order every time (a stencil whose coefficients change, its shape not).
// Why: a coupled run reassembles the implicit viscous matrices every step (eps changes), and
// MatSetValuesStencil spends most of that time mapping and searching indices, the same ones each step:
// at cell/d 0.5 in the bubbling bed the assembly was a quarter of the flow step.
// Use: the first assembly goes through MatSetValuesStencil as usual and calls Note() for every row
// (MatStencil layout of the matrix's DMDA, 3-D, as MatSetValuesStencil reads it), then Finish() after
// MatAssemblyEnd, which finds where each entry lives in the CSR arrays. Later assemblies call Begin(),
// Put() per row in the same order, End(). Put() checks that each row has the shape it had (count and
// columns); if not it returns false, and the caller assembles the usual way again (after Reset()). The
// values land where MatSetValues(INSERT_VALUES) would put them: the matrix is the same to the bit.
// SEQAIJ and MPIAIJ only (Ready() stays false otherwise).
#pragma once

#include <petscdmda.h>

#include <cstdint>
#include <vector>

namespace vofdem {

class AijRowWriter {
public:
  // Forget the recorded rows: the next assembly must record again.
  void Reset();
  // During a recording assembly: the row's entries, as passed to MatSetValuesStencil(A, 1, row, nc, col, ...).
  PetscErrorCode Note(Mat A, DM da, const MatStencil &row, PetscInt nc, const MatStencil col[]);
  // After that assembly's MatAssemblyEnd: the positions of the noted entries. Collective.
  PetscErrorCode Finish(Mat A);
  bool           Ready() const { return ready_; }

  PetscErrorCode Begin(Mat A);
  // The next row's values; false (nothing written) if its count or columns differ from the recorded ones.
  bool Put(PetscInt nc, const MatStencil col[], const PetscScalar val[]) {
    if (row_ + 1 >= start_.size() || (PetscInt)(start_[row_ + 1] - start_[row_]) != nc || shape_[row_] != Shape(nc, col)) return false;
    const int64_t *p = &pos_[start_[row_++]];
    for (PetscInt c = 0; c < nc; ++c) {
      if (p[c] >= 0) diag_[p[c]] = val[c];
      else if (p[c] != kIgnored) off_[-p[c] - 2] = val[c];
    }
    return true;
  }
  // Restores the arrays and marks the matrix changed; `complete`: every recorded row was Put.
  PetscErrorCode End(Mat A, bool *complete);

private:
  static constexpr int64_t kIgnored = -1;  // a column MatSetValuesStencil drops (outside the ghosted box)
  static uint64_t          Shape(PetscInt nc, const MatStencil col[]) {
    uint64_t h = (uint64_t)nc;
    for (PetscInt c = 0; c < nc; ++c) h = h * 1000003u + ((uint64_t)(uint32_t)col[c].i * 73856093u ^ (uint64_t)(uint32_t)col[c].j * 19349663u ^ (uint64_t)(uint32_t)col[c].k * 83492791u);
    return h;
  }
  PetscErrorCode Local(DM da, const MatStencil &s, PetscInt *local) const;

  bool                  ready_ = false;
  bool                  unsupported_ = false;  // not SEQAIJ/MPIAIJ (found by Finish): Note records nothing
  std::vector<size_t>   start_;   // row r's entries: [start_[r], start_[r + 1])
  std::vector<uint64_t> shape_;   // per row
  std::vector<PetscInt> rows_;    // global row of each noted row (recording only)
  std::vector<PetscInt> cols_;    // global column of each noted entry, -1 dropped (recording only)
  std::vector<int64_t>  pos_;     // >= 0: the diagonal block's value index; <= -2: -(off-diagonal index) - 2
  size_t                row_  = 0;
  PetscScalar          *diag_ = nullptr, *off_ = nullptr;
  Mat                   Ad_ = nullptr, Ao_ = nullptr;  // the blocks whose arrays are held (Ao_ null for SEQAIJ)
};

}  // namespace vofdem
