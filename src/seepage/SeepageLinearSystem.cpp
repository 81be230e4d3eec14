#include "SeepageLinearSystem.hpp"

#include <mpi.h>
#include <Amesos2.hpp>
#include <BelosLinearProblem.hpp>
#include <BelosSolverFactory.hpp>
#include <BelosTpetraAdapter.hpp>
#include <Ifpack2_Factory.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_DefaultSerialComm.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>
#include <algorithm>
#include <set>
#include <sstream>

#include "argine/core/Error.hpp"

namespace argine {

struct SeepageLinearSystem::Tpetra {
  using Map = ::Tpetra::Map<>;
  using LO = Map::local_ordinal_type;
  using GO = Map::global_ordinal_type;
  using Node = Map::node_type;
  using Graph = ::Tpetra::CrsGraph<LO, GO, Node>;
  using Matrix = ::Tpetra::CrsMatrix<Real, LO, GO, Node>;
  using RowMatrix = ::Tpetra::RowMatrix<Real, LO, GO, Node>;
  using Vector = ::Tpetra::Vector<Real, LO, GO, Node>;
  using MV = ::Tpetra::MultiVector<Real, LO, GO, Node>;
  using OP = ::Tpetra::Operator<Real, LO, GO, Node>;
  using Import = ::Tpetra::Import<LO, GO, Node>;
  using Preconditioner = Ifpack2::Preconditioner<Real, LO, GO, Node>;

  Teuchos::RCP<const Teuchos::Comm<int>> comm;
  Teuchos::RCP<const Map> rows, everywhere;
  Teuchos::RCP<const Import> to_everywhere;
  Teuchos::RCP<Graph> graph;
  Teuchos::RCP<Matrix> matrix;
  Teuchos::RCP<Vector> b, x;
  Teuchos::RCP<Vector> x_everywhere;
  Teuchos::RCP<Preconditioner> preconditioner;
  Teuchos::RCP<Belos::SolverManager<Real, MV, OP>> solver;
  Teuchos::RCP<Amesos2::Solver<Matrix, MV>> direct;  // Solver: direct (KLU2)
  // Solver: direct on several ranks: the whole matrix gathered to every rank and factorised
  // there on a one-process communicator (KLU2 given the split rows answered wrongly,
  // doc/parallel.md).
  Teuchos::RCP<Matrix> gathered;
  Teuchos::RCP<Vector> gathered_b, gathered_x, b_everywhere;
};

SeepageLinearSystem::SeepageLinearSystem(Teuchos::RCP<const Teuchos::Comm<int>> comm, int num_dofs,
                                         const std::vector<std::vector<int>>& element_dofs)
    : t_(std::make_unique<Tpetra>()), num_dofs_(num_dofs) {
  using T = Tpetra;
  t_->comm = comm.is_null() ? ::Tpetra::getDefaultComm() : comm;
  const int ranks = t_->comm->getSize(), rank = t_->comm->getRank();
  // Contiguous blocks of rows: the first (num_dofs % ranks) ranks get one more.
  const int base = num_dofs / ranks, extra = num_dofs % ranks;
  first_ = rank * base + std::min(rank, extra);
  end_ = first_ + base + (rank < extra ? 1 : 0);
  t_->rows = Teuchos::rcp(new T::Map(static_cast<::Tpetra::global_size_t>(num_dofs),
                                     static_cast<size_t>(end_ - first_), 0, t_->comm));
  std::vector<T::GO> all(num_dofs);
  for (int i = 0; i < num_dofs; ++i) all[i] = i;
  t_->everywhere =
      Teuchos::rcp(new T::Map(Teuchos::OrdinalTraits<::Tpetra::global_size_t>::invalid(),
                              Teuchos::ArrayView<const T::GO>(all.data(), num_dofs), 0, t_->comm));
  t_->to_everywhere = Teuchos::rcp(new T::Import(t_->rows, t_->everywhere));

  // The graph: each owned row couples to every unknown of the elements holding it.
  std::vector<std::set<T::GO>> columns(end_ - first_);
  for (const auto& dofs : element_dofs)
    for (const int row : dofs)
      if (owns(row))
        for (const int col : dofs) columns[row - first_].insert(col);
  size_t widest = 1;
  for (const auto& row : columns) widest = std::max(widest, row.size());
  t_->graph = Teuchos::rcp(new T::Graph(t_->rows, widest));
  for (int row = first_; row < end_; ++row) {
    auto& set = columns[row - first_];
    set.insert(row);  // a diagonal even for an unknown of no element (never happens)
    const std::vector<T::GO> cols(set.begin(), set.end());
    t_->graph->insertGlobalIndices(row, Teuchos::ArrayView<const T::GO>(cols));
  }
  t_->graph->fillComplete();
  // The value layout of setValues: the graph's owned rows, columns in increasing order.
  const auto column_map = t_->graph->getColMap();
  row_start_.assign(1, 0);
  for (int row = first_; row < end_; ++row) {
    for (const T::GO col : columns[row - first_]) {
      entry_col_.push_back(static_cast<int>(col));
      entry_local_col_.push_back(column_map->getLocalElement(col));
    }
    row_start_.push_back(static_cast<int>(entry_col_.size()));
  }
  t_->matrix = Teuchos::rcp(new T::Matrix(t_->graph));
  t_->matrix->fillComplete();
  t_->b = Teuchos::rcp(new T::Vector(t_->rows));
  t_->x = Teuchos::rcp(new T::Vector(t_->rows));
  t_->x_everywhere = Teuchos::rcp(new T::Vector(t_->everywhere));
  setSolver(spec_);
}

SeepageLinearSystem::~SeepageLinearSystem() = default;

int SeepageLinearSystem::rank() const {
  return t_->comm->getRank();
}

void SeepageLinearSystem::setSolver(const LinearSolverSpec& spec) {
  using T = Tpetra;
  spec_ = spec;
  auto params = Teuchos::rcp(new Teuchos::ParameterList);
  params->set("Convergence Tolerance", spec.tolerance);
  params->set("Maximum Iterations", spec.max_iterations);
  if (spec.solver == "GMRES") {
    params->set("Num Blocks", std::min(spec.max_iterations, 300));
    params->set("Maximum Restarts", std::max(1, spec.max_iterations / 300 + 1));
  }
  t_->direct = Teuchos::null;
  factorised_ = false;
  t_->preconditioner = Teuchos::null;
  preconditioner_initialised_ = false;
  gathered_direct_ = false;
  t_->gathered = Teuchos::null;
  if (spec.solver == "DIRECT" && t_->comm->getSize() > 1) {
    gathered_direct_ = true;  // factoriseGathered at the first solve
    return;
  }
  if (spec.solver == "DIRECT") {
    // KLU2 ships with Amesos2; the sparsity pattern never changes within a stage, so the
    // symbolic factorisation (ordering) is done once and each solve refactors numerically.
    t_->direct = Amesos2::create<T::Matrix, T::MV>("KLU2", t_->matrix, t_->x, t_->b);
    t_->direct->symbolicFactorization();
    return;
  }
  Belos::SolverFactory<Real, T::MV, T::OP> factory;
  t_->solver = factory.create(spec.solver, params);

  if (spec.preconditioner == "NONE") return;
  Teuchos::ParameterList prec;
  if (spec.preconditioner == "RILUK") {
    prec.set("fact: iluk level-of-fill", spec.fill_level);
  } else if (spec.preconditioner == "ILUT") {
    prec.set("fact: ilut level-of-fill", 1.0 + spec.fill_level);
    prec.set("fact: drop tolerance", 0.0);
  } else if (spec.preconditioner == "RELAXATION") {
    prec.set("relaxation: type", spec.relaxation);
    prec.set("relaxation: sweeps", spec.sweeps);
  } else if (spec.preconditioner == "CHEBYSHEV") {
    prec.set("chebyshev: degree", spec.sweeps);
  }
  t_->preconditioner = Ifpack2::Factory::create<T::RowMatrix>(spec.preconditioner, t_->matrix);
  t_->preconditioner->setParameters(prec);
}

void SeepageLinearSystem::beginAssembly() {
  t_->matrix->resumeFill();
  t_->matrix->setAllToScalar(0.0);
}

void SeepageLinearSystem::add(int row, const int* cols, const Real* vals, int count) {
  using GO = Tpetra::GO;
  GO global_cols[16];
  for (int j = 0; j < count; ++j) global_cols[j] = cols[j];
  t_->matrix->sumIntoGlobalValues(static_cast<GO>(row),
                                  Teuchos::ArrayView<const GO>(global_cols, count),
                                  Teuchos::ArrayView<const Real>(vals, count));
}

int SeepageLinearSystem::entry(int row, int col) const {
  if (!owns(row)) return -1;
  for (int e = row_start_[row - first_]; e < row_start_[row - first_ + 1]; ++e)
    if (entry_col_[e] == col) return e;
  return -1;
}

void SeepageLinearSystem::setValues(const std::vector<Real>& values) {
  using LO = Tpetra::LO;
  t_->matrix->resumeFill();
  for (int row = first_; row < end_; ++row) {
    const int start = row_start_[row - first_], count = row_start_[row - first_ + 1] - start;
    t_->matrix->replaceLocalValues(static_cast<LO>(row - first_),
                                   Teuchos::ArrayView<const LO>(&entry_local_col_[start], count),
                                   Teuchos::ArrayView<const Real>(&values[start], count));
  }
  t_->matrix->fillComplete();
}

void SeepageLinearSystem::endAssembly() {
  t_->matrix->fillComplete();
}

int SeepageLinearSystem::solve(const std::vector<Real>& b, std::vector<Real>& x, bool refactor) {
  {
    auto bv = t_->b->getDataNonConst();
    for (int row = first_; row < end_; ++row) bv[row - first_] = b[row];
  }
  t_->x->putScalar(0.0);
  int iterations = 1;
  if (gathered_direct_) {
    if (refactor || !factorised_) factoriseGathered();
    factorised_ = true;
    t_->b_everywhere->doImport(*t_->b, *t_->to_everywhere, ::Tpetra::INSERT);
    {
      const auto from = t_->b_everywhere->getData();
      auto to = t_->gathered_b->getDataNonConst();
      for (int i = 0; i < num_dofs_; ++i) to[i] = from[i];
    }
    t_->direct->solve();
    x.assign(num_dofs_, 0.0);
    const auto xv = t_->gathered_x->getData();
    for (int i = 0; i < num_dofs_; ++i) x[i] = xv[i];
    return iterations;
  }
  if (!t_->direct.is_null()) {
    if (refactor || !factorised_) t_->direct->numericFactorization();
    factorised_ = true;
    t_->direct->solve();
  } else {
    iterations = solveIteratively(refactor);
  }
  t_->x_everywhere->doImport(*t_->x, *t_->to_everywhere, ::Tpetra::INSERT);
  x.assign(num_dofs_, 0.0);
  const auto xv = t_->x_everywhere->getData();
  for (int i = 0; i < num_dofs_; ++i) x[i] = xv[i];
  return iterations;
}

int SeepageLinearSystem::solveIteratively(bool refactor) {
  using T = Tpetra;
  auto problem = Teuchos::rcp(new Belos::LinearProblem<Real, T::MV, T::OP>(
      t_->matrix, Teuchos::rcp_static_cast<T::MV>(t_->x),
      Teuchos::rcp_static_cast<const T::MV>(t_->b)));
  if (!t_->preconditioner.is_null()) {
    if (!preconditioner_initialised_) {
      t_->preconditioner->initialize();  // symbolic: the graph never changes
      preconditioner_initialised_ = true;
    }
    if (refactor || !factorised_) t_->preconditioner->compute();
    factorised_ = true;
    if (spec_.solver == "CG")
      problem->setLeftPrec(t_->preconditioner);
    else
      problem->setRightPrec(t_->preconditioner);
  }
  problem->setProblem();
  t_->solver->setProblem(problem);
  const Belos::ReturnType result = t_->solver->solve();
  // Pseudo-block GMRES reports "unconverged" after a loss-of-accuracy warning although its
  // residual met the tolerance; Picard recomputes the true residual anyway.
  if (result != Belos::Converged && !(t_->solver->achievedTol() <= spec_.tolerance)) {
    std::ostringstream out;
    out << "implicit seepage: " << spec_.solver << " did not reach the relative tolerance "
        << spec_.tolerance << " in " << spec_.max_iterations << " iterations (reached "
        << t_->solver->achievedTol() << ", |b| = " << t_->b->norm2() << ")";
    throw RunError(out.str());
  }
  return t_->solver->getNumIters();
}

void SeepageLinearSystem::factoriseGathered() {
  using T = Tpetra;
  // The owned rows (global columns and values) of every rank, in rank order: the ranks own
  // consecutive blocks of rows, so the concatenation is rows 0..n-1.
  std::vector<int> lengths, columns;
  std::vector<Real> values;
  std::vector<T::GO> cols;
  std::vector<Real> vals;
  for (int row = first_; row < end_; ++row) {
    const size_t count = t_->matrix->getNumEntriesInGlobalRow(row);
    cols.resize(count);
    vals.resize(count);
    size_t got = 0;
    t_->matrix->getGlobalRowCopy(row, Teuchos::ArrayView<T::GO>(cols),
                                 Teuchos::ArrayView<Real>(vals), got);
    lengths.push_back(static_cast<int>(got));
    for (size_t k = 0; k < got; ++k) {
      columns.push_back(static_cast<int>(cols[k]));
      values.push_back(vals[k]);
    }
  }
  const auto mpi = Teuchos::rcp_dynamic_cast<const Teuchos::MpiComm<int>>(t_->comm, true);
  const MPI_Comm comm = *mpi->getRawMpiComm();
  const int ranks = t_->comm->getSize();
  auto allGather = [&](const auto& mine, auto& all, MPI_Datatype type) {
    int count = static_cast<int>(mine.size());
    std::vector<int> counts(ranks), offsets(ranks, 0);
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
    for (int r = 1; r < ranks; ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
    all.resize(offsets[ranks - 1] + counts[ranks - 1]);
    MPI_Allgatherv(mine.data(), count, type, all.data(), counts.data(), offsets.data(), type, comm);
  };
  std::vector<int> all_lengths, all_columns;
  std::vector<Real> all_values;
  allGather(lengths, all_lengths, MPI_INT);
  allGather(columns, all_columns, MPI_INT);
  allGather(values, all_values, MPI_DOUBLE);

  // The graph never changes within a stage: the gathered matrix and its symbolic
  // factorisation are made once, later calls replace the values.
  const bool first = t_->gathered.is_null();
  if (first) {
    const Teuchos::RCP<const Teuchos::Comm<int>> self = Teuchos::rcp(new Teuchos::SerialComm<int>);
    const auto rows =
        Teuchos::rcp(new T::Map(static_cast<::Tpetra::global_size_t>(num_dofs_), 0, self));
    const int widest = *std::max_element(all_lengths.begin(), all_lengths.end());
    t_->gathered = Teuchos::rcp(new T::Matrix(rows, widest));
    t_->gathered_b = Teuchos::rcp(new T::Vector(rows));
    t_->gathered_x = Teuchos::rcp(new T::Vector(rows));
    t_->b_everywhere = Teuchos::rcp(new T::Vector(t_->everywhere));
  } else {
    t_->gathered->resumeFill();
  }
  for (int row = 0, start = 0; row < num_dofs_; start += all_lengths[row], ++row) {
    cols.assign(all_columns.begin() + start, all_columns.begin() + start + all_lengths[row]);
    const Teuchos::ArrayView<const T::GO> row_cols(cols);
    const Teuchos::ArrayView<const Real> row_values(all_values.data() + start, all_lengths[row]);
    if (first)
      t_->gathered->insertGlobalValues(row, row_cols, row_values);
    else
      t_->gathered->replaceGlobalValues(row, row_cols, row_values);
  }
  t_->gathered->fillComplete();
  if (first) {
    t_->direct =
        Amesos2::create<T::Matrix, T::MV>("KLU2", t_->gathered, t_->gathered_x, t_->gathered_b);
    t_->direct->symbolicFactorization();
  }
  t_->direct->numericFactorization();
}

void SeepageLinearSystem::sumOverRanks(std::vector<Real>& v) const {
  if (t_->comm->getSize() == 1) return;
  std::vector<Real> sum(v.size());
  Teuchos::reduceAll<int, Real>(*t_->comm, Teuchos::REDUCE_SUM, static_cast<int>(v.size()),
                                v.data(), sum.data());
  v.swap(sum);
}

}  // namespace argine
