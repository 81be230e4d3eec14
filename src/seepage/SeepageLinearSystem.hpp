#pragma once
// The implicit seepage path's sparse system: a Tpetra CrsMatrix on the active nodes (rows in
// contiguous blocks per rank, graph from the elements holding liquid points), Belos solvers
// and Ifpack2 preconditioners chosen by a LinearSolverSpec. Private to the seepage room.

#include <memory>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include "argine/core/Types.hpp"
#include "argine/input/Deck.hpp"

namespace argine {

class SeepageLinearSystem {
 public:
  /// `element_dofs`: the unknowns of each element that holds liquid points (the graph couples
  /// all unknowns of an element).
  SeepageLinearSystem(Teuchos::RCP<const Teuchos::Comm<int>> comm, int num_dofs,
                      const std::vector<std::vector<int>>& element_dofs);
  ~SeepageLinearSystem();

  int firstOwned() const { return first_; }
  int endOwned() const { return end_; }
  bool owns(int dof) const { return dof >= first_ && dof < end_; }
  int rank() const;

  void setSolver(const LinearSolverSpec& spec);

  /// Zeroes the matrix for a new assembly.
  void beginAssembly();
  /// Adds vals[j] to A(row, cols[j]) (row owned by this rank).
  void add(int row, const int* cols, const Real* vals, int count);
  void endAssembly();

  /// Assembly by value array (the fast path, Picard's matrix): A's owned entries in a flat
  /// array laid out row by row; entry(row, col) is the index of A(row, col), -1 when the
  /// graph has no such entry or the row is not owned. setValues replaces every owned entry
  /// and completes the matrix (no global-index lookups per point).
  int entry(int row, int col) const;
  int entryCount() const { return static_cast<int>(entry_col_.size()); }
  void setValues(const std::vector<Real>& values);

  /// Solves A x = b; b holds every unknown, only owned rows are read. x (every unknown) is
  /// returned on every rank. Returns the Krylov iterations (1 for the direct solver); throws
  /// RunError when Belos does not converge.
  /// `refactor` false: reuse the last factorisation / preconditioner (the matrix has not
  /// changed since).
  int solve(const std::vector<Real>& b, std::vector<Real>& x, bool refactor = true);

  /// Sums v over the ranks (each rank filled its own rows).
  void sumOverRanks(std::vector<Real>& v) const;

 private:
  struct Tpetra;
  int solveIteratively(bool refactor);  ///< Belos on t_->b, t_->x
  void factoriseGathered();             ///< direct on several ranks: every row on every rank
  std::unique_ptr<Tpetra> t_;
  int first_ = 0, end_ = 0, num_dofs_ = 0;
  std::vector<int> row_start_;        // per owned row: its first entry (entryCount() at the end)
  std::vector<int> entry_col_;        // per entry: column (unknown)
  std::vector<int> entry_local_col_;  // per entry: Tpetra local column index
  LinearSolverSpec spec_;
  bool preconditioner_initialised_ = false;
  bool factorised_ = false;       ///< a factorisation / preconditioner of the current solver exists
  bool gathered_direct_ = false;  ///< direct on several ranks (factoriseGathered)
};

}  // namespace argine
