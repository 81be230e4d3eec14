#pragma once
/// @file ImplicitSeepageSolver.hpp
/// The implicit seepage path (SPEC.md "The implicit path", doc/theory.md): the liquid mass
/// balance with a fixed skeleton on the background mesh's ACTIVE nodes (nodes of elements
/// holding liquid-carrying points), integrated at the material points (SeepagePointTerms.hpp),
/// a theta scheme in time (1: backward Euler, 1/2: Crank-Nicolson) and the mass-conservative
/// modified Picard iteration of Celia et al. (1990) for the SWRC non-linearity:
///
///   (C^m/dt + theta K^m) dp = -R(p^m),   p^{m+1} = p^m + dp,
///
/// R the residual with the actual content change (SeepagePointTerms.hpp), C^m the storage
/// slope matrix, K^m the conductivity matrix, both at the last iterate. Converged when the
/// last update changed no nodal p_L by more than the pressure tolerance and the free nodes'
/// residual is below the mass tolerance. Ponding and seepage faces by an active-set loop
/// around Picard (SeepageBoundary.hpp). The step adapts to the Picard iteration count and the
/// largest saturation change; a step that does not converge is halved and redone.
///
/// `Nonlinear Solver: newton` (ImplicitSeepageSpec::iteration) replaces the Picard matrix by
/// the full Jacobian of the same residual (SeepagePointTerms.hpp, N1-N6):
///
///   (C^m/dt + theta (K^m + K'^m)) dp = -R(p^m),   K'_ab = sum_p V N_b dm/dp grad N_a . d_p
///                                                         + (liquid compressibility terms),
///
/// d_p = grad p + rho_L g e_y the point's flux gradient: non-symmetric, hence GMRES or the
/// direct solver (CG is refused by the deck). The storage slope C is Picard's (with the
/// minimum-suction regularisation, exact above s_reg), so Newton is exact, and converges
/// quadratically, wherever every point's suction is 0 or above s_reg. The same loop, tolerances,
/// active set, prescribed and held nodes, adaptive step and Reuse Matrix (a chord iteration
/// on the Jacobian: modified Newton) serve both; only the matrix differs.
///
/// Parallel layout: Tpetra rows (active nodes) are split in contiguous blocks over the ranks
/// of `comm`; each rank assembles its own rows from the points touching them (the mesh and
/// the points are replicated on every rank for now), Belos + Ifpack2 solve, the update is
/// imported to every rank. The same kernels work with distributed points once the points are
/// partitioned (only the point loop's range and the import target change).

#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_RCP.hpp>

#include "argine/core/Types.hpp"
#include "argine/input/Deck.hpp"
#include "argine/seepage/SeepageBoundary.hpp"

namespace argine {

struct Mesh;
struct MaterialPoints;

/// What one time step did.
struct SeepageStepResult {
  bool converged = false;
  int picard_iterations = 0;  ///< non-linear (Picard or Newton) iterations, all passes
  int active_set_passes = 0;  ///< 1 when no switch changed
  int linear_iterations = 0;  ///< Krylov iterations over all Picard iterations
  Real max_saturation_change = 0;
  Real inflow = 0;  ///< liquid mass through the boundary over the step (kg/m)
  /// The same through each condition of the plan (conditionNames() order; P10): their sum
  /// is `inflow`.
  std::vector<Real> condition_inflow;
  Real storage_change = 0;  ///< change of the points' liquid mass over the step (kg/m)
  /// Free-node residual sum_i |R_i| (kg/s per m) at each iterate of the last active-set pass,
  /// the starting one first (the convergence history).
  std::vector<Real> residual_norms;
};

/// The residual and the iteration matrix of a step at trial pressures (linearise()).
struct SeepageLinearisation {
  int unknowns = 0;            ///< active nodes
  std::vector<int> node;       ///< mesh node of each unknown
  std::vector<Real> residual;  ///< R(p) by unknown (kg/s per m)
  std::vector<Real> matrix;    ///< dense, row-major unknowns x unknowns
};

/// Running totals of a solver since construction.
struct SeepageTotals {
  long long steps = 0, rejected_steps = 0, picard_iterations = 0, linear_iterations = 0;
  Real inflow = 0;          ///< (kg/m)
  Real storage_change = 0;  ///< (kg/m)
  /// Inflow through each condition of the current plan (kg/m, conditionNames() order), and
  /// that of its last accepted step (P10: the per-condition columns of the boundary-flux CSV).
  std::vector<Real> condition_inflow, condition_inflow_last_step;
};

class ImplicitSeepageSolver {
 public:
  /// `comm`: the ranks sharing the rows (null: Tpetra's default, MPI_COMM_WORLD).
  ImplicitSeepageSolver(const Mesh& mesh, MaterialPoints& points,
                        const std::vector<MaterialSpec>& materials,
                        Teuchos::RCP<const Teuchos::Comm<int>> comm = Teuchos::null);
  ~ImplicitSeepageSolver();
  ImplicitSeepageSolver(const ImplicitSeepageSolver&) = delete;
  ImplicitSeepageSolver& operator=(const ImplicitSeepageSolver&) = delete;

  /// Starts a stage: its settings, gravity and boundary conditions (seepageBoundaryPlan on the
  /// points' elements now),
  /// the nodal p_L from the points (projectPressureFromPoints). `table_origin` (s): the time
  /// the stage's tables count from; NaN: now (the rest of an explicit stage, P12: its start).
  void beginStage(const StageSpec& stage,
                  Real table_origin = std::numeric_limits<Real>::quiet_NaN());

  void setSettings(const ImplicitSeepageSpec& settings);
  void setGravity(Real gravity);  ///< magnitude (m/s^2), acting in -y
  /// Fixed conditions for every step (replaces a plan).
  void setBoundaryConditions(const SeepageBoundaryConditions& conditions);
  /// Conditions re-evaluated for every step: plan.at(t_n, t_n+1, theta) (values at the end of
  /// the step; supplies theta-weighted).
  void setBoundaryPlan(const SeepageBoundaryPlan& plan);
  /// Nodal p_L = the L2 projection of the points' p_L (sum_p V N_a N_b p_b = sum_p V N_a
  /// p_p): exact for a linear field, e.g. hydrostatic.
  void projectPressureFromPoints();
  /// Nodal p_L = f(x, y) at every active node.
  void setNodalPressure(const std::function<Real(Real, Real)>& pressure);

  /// One theta step of length dt. When it does not converge the state is left unchanged and
  /// converged = false.
  SeepageStepResult step(Real dt);
  /// Steps with the adaptive step size until time() reaches `end` (the last step is cut to
  /// land on it). Throws RunError when a step fails below the minimum step.
  void advanceTo(Real end);

  /// Hands the state to the points: p_L interpolated from the nodes, rho_L (4.13), S_L, k
  /// (SWRC, HCC), M_L = n V S_L rho_L: the points then hold exactly liquidMass().
  void handOver();

  /// For tests and diagnostics (one rank): the residual R of a step of length dt from the
  /// current state (the old level) at the trial nodal p_L (by mesh node, as nodalPressure()),
  /// and the matrix of the settings' Nonlinear Solver there (Picard: C/dt + theta K; Newton:
  /// the Jacobian dR/dp), before any boundary elimination (no node fixed or held). Leaves
  /// the state unchanged.
  SeepageLinearisation linearise(Real dt, const std::vector<Real>& trial);

  Real time() const;
  void setTime(Real time);
  /// The step advanceTo will try next (s).
  Real nextStep() const;
  /// The length of the last step advanceTo took and accepted (s; 0 before the first).
  Real lastAcceptedStep() const;
  /// Liquid mass of the liquid-carrying points at the current nodal p_L (kg/m).
  Real liquidMass() const;
  const SeepageTotals& totals() const;
  /// The names of the plan's conditions (empty without a plan), in the order of the
  /// per-condition inflows of SeepageStepResult and SeepageTotals.
  std::vector<std::string> conditionNames() const;
  /// p_L by mesh node (Pa); NaN at inactive nodes.
  std::vector<Real> nodalPressure() const;
  /// Mesh nodes held at p_L = 0 by the ponding / seepage-face switch.
  std::vector<int> heldNodes() const;
  int activeNodeCount() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace argine
