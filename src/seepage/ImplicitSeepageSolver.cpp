#include "argine/seepage/ImplicitSeepageSolver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "SeepageLinearSystem.hpp"
#include "argine/core/Error.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/seepage/SeepagePointTerms.hpp"
#include "argine/seepage/SeepageStepControl.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {

namespace {

/// One row of the theta-scheme residual R = storage/dt + theta F(p) + (1 - theta) F(p_old) - Q
/// (the step's iteration and linearise() for the tests use this one formula).
Real thetaResidual(Real storage, Real flux, Real flux_old, Real supply, Real dt, Real theta) {
  return storage / dt + theta * flux + (1 - theta) * flux_old - supply;
}
constexpr int kNone = -1;
}  // namespace

struct ImplicitSeepageSolver::Impl {
  const Mesh& mesh;
  MaterialPoints& points;
  MaterialTable table;
  int nodes_per_element = 0;

  // Liquid-carrying located points, host copies (the skeleton is fixed: they never change).
  struct Point {
    int index;      // into `points`
    int material;   // material id
    Real porosity;  // n
    Real volume;    // V (m^2 per metre)
    int dof[kMaxElementNodes];
    // entry[a][b]: index of A(dof[a], dof[b]) in the linear system's value array (-1: row
    // not owned), fixed for the stage: the matrix is assembled without index lookups.
    int entry[kMaxElementNodes][kMaxElementNodes];
    PointShape shape;
  };
  // Per liquid point, refreshed once per step (old level) and once per Picard iteration
  // (current iterate): the SWRC/HCC are evaluated once per point and iteration, not once per
  // term (residual storage, residual flux, matrix).
  std::vector<Real> point_p_old, point_s_old, point_rho_old, point_p, point_mobility;
  // The hand-over from the points: the nodal start is the L2 projection of their p_L, which
  // stores a slightly different liquid mass than they hold unless p_L is linear. Until the
  // first accepted step the old level is the points' own p_L (pressure_from_points, per
  // liquid point), so that step's storage change starts from the mass they hold and the
  // projection's difference is not created or destroyed (the run's liquid mass is kept
  // across the explicit -> implicit hand-over). Cleared by setNodalPressure and handOver.
  bool old_level_from_points = false;
  std::vector<Real> pressure_from_points;
  std::vector<Real> matrix_values;
  std::vector<Point> liquid_points;
  std::vector<int> dof_of_node, node_of_dof;
  std::unique_ptr<SeepageLinearSystem> system;

  ImplicitSeepageSpec settings;
  Real gravity = kStandardGravity;
  Real reference_density = 1000;  // rho_L0 of the supplied water
  Real time = 0, next_step = 1;
  // The last accepted step and its nodal increments (the adaptive step's time error).
  Real last_step = 0;
  std::vector<Real> last_increment;
  Real accepted_step = 0;  ///< the length of the last converged step (0: none yet)
  SeepageTotals totals;

  // Per unknown: prescribed pressure, supply (kg/s per m), switchable, held at p = 0.
  std::vector<char> fixed, switchable, held;
  std::vector<Real> fixed_value, supply;

  std::vector<Real> p;  // nodal p_L, every unknown on every rank

  // Time-dependent conditions (a stage's plan): re-evaluated for every step (at()).
  std::unique_ptr<SeepageBoundaryPlan> plan;
  // The plan's condition owning each unknown (kNone: none), for the inflow per condition.
  std::vector<int> condition_of_dof;

  void applyConditions(const SeepageBoundaryConditions& conditions, bool keep_held);

  Impl(const Mesh& m, MaterialPoints& pts, const std::vector<MaterialSpec>& materials)
      : mesh(m), points(pts), table(materials), nodes_per_element(m.nodesPerElement()) {}

  int dofs() const { return static_cast<int>(node_of_dof.size()); }
  const PointMaterial& material(const Point& point) const { return table.host(point.material); }

  Real interpolate(const Point& point, const std::vector<Real>& nodal) const {
    Real local[kMaxElementNodes];
    for (int a = 0; a < nodes_per_element; ++a) local[a] = nodal[point.dof[a]];
    return interpolateAtPoint(point.shape, nodes_per_element, local);
  }

  bool touchesOwnedRow(const Point& point) const {
    for (int a = 0; a < nodes_per_element; ++a)
      if (system->owns(point.dof[a])) return true;
    return false;
  }

  /// Flux terms F_a(p) of the owned rows, summed over ranks (every unknown).
  std::vector<Real> flux(const std::vector<Real>& nodal) const {
    std::vector<Real> out(dofs(), 0.0);
    for (const Point& point : liquid_points) {
      if (!touchesOwnedRow(point)) continue;
      const PointMaterial& mat = material(point);
      const Real pressure = interpolate(point, nodal);
      Real local[kMaxElementNodes], f[kMaxElementNodes] = {0, 0, 0, 0};
      for (int a = 0; a < nodes_per_element; ++a) local[a] = nodal[point.dof[a]];
      addPointFluxVector(point.shape, nodes_per_element, local,
                         point.volume * darcyMobility(mat, pressure),
                         liquidDensity(mat.liquid, pressure) * gravity, f);
      for (int a = 0; a < nodes_per_element; ++a)
        if (system->owns(point.dof[a])) out[point.dof[a]] += f[a];
    }
    system->sumOverRanks(out);
    return out;
  }

  /// p_L, S_L and rho_L at the old level of every liquid point (once per step).
  void cacheOldLevel(const std::vector<Real>& old) {
    point_p_old.resize(liquid_points.size());
    point_s_old.resize(liquid_points.size());
    point_rho_old.resize(liquid_points.size());
    for (std::size_t i = 0; i < liquid_points.size(); ++i) {
      const Point& point = liquid_points[i];
      const PointMaterial& mat = material(point);
      point_p_old[i] = old_level_from_points ? pressure_from_points[i] : interpolate(point, old);
      point_s_old[i] = saturationOfPressure(mat, point_p_old[i]);
      point_rho_old[i] = liquidDensity(mat.liquid, point_p_old[i]);
    }
  }

  /// The storage terms sum_p N_a n V [S rho]_{p_old}^{p} (kg/m) and the flux terms (as
  /// flux()) at `nodal` in one pass, owned rows summed over ranks,
  /// one SWRC/HCC evaluation per point; keeps p_L and the mobility of each point for
  /// assembleMatrix at the same iterate. Needs cacheOldLevel of the step.
  void storageAndFlux(const std::vector<Real>& nodal, std::vector<Real>& storage_out,
                      std::vector<Real>& flux_out) {
    storage_out.assign(dofs(), 0.0);
    flux_out.assign(dofs(), 0.0);
    point_p.resize(liquid_points.size());
    point_mobility.resize(liquid_points.size());
    for (std::size_t i = 0; i < liquid_points.size(); ++i) {
      const Point& point = liquid_points[i];
      if (!touchesOwnedRow(point)) continue;
      const PointMaterial& mat = material(point);
      const Real pressure = interpolate(point, nodal);
      const LiquidState state = saturationAndConductivity(mat, pressure);
      const Real rho_old = point_rho_old[i];
      const Real density_change = liquidDensityChange(mat, pressure, point_p_old[i], rho_old);
      const Real density = rho_old + density_change;  // rho_L(p_L), 4.13
      point_p[i] = pressure;
      point_mobility[i] = darcyMobilityOf(mat, density, state.conductivity);
      const Real change =
          point.porosity * point.volume *
          liquidContentChangeOf(state.saturation, point_s_old[i], rho_old, density_change);
      Real local[kMaxElementNodes], f[kMaxElementNodes] = {0, 0, 0, 0};
      for (int a = 0; a < nodes_per_element; ++a) local[a] = nodal[point.dof[a]];
      addPointFluxVector(point.shape, nodes_per_element, local, point.volume * point_mobility[i],
                         density * gravity, f);
      for (int a = 0; a < nodes_per_element; ++a)
        if (system->owns(point.dof[a])) {
          storage_out[point.dof[a]] += point.shape.value[a] * change;
          flux_out[point.dof[a]] += f[a];
        }
    }
    system->sumOverRanks(storage_out);
    system->sumOverRanks(flux_out);
  }

  /// Liquid point i's share of the iteration matrix at `nodal`, the iterate of the last
  /// storageAndFlux (its point_p, point_mobility): Picard C/dt + theta K; Newton adds
  /// theta K' (SeepagePointTerms.hpp N3-N4), the rest of the exact dR/dp.
  void pointMatrix(std::size_t i, Real dt, const std::vector<Real>& nodal,
                   Real local[kMaxElementNodes][kMaxElementNodes]) const {
    const Point& point = liquid_points[i];
    const PointMaterial& mat = material(point);
    const Real theta = settings.theta;
    for (int a = 0; a < nodes_per_element; ++a)
      for (int b = 0; b < nodes_per_element; ++b) local[a][b] = 0;
    addPointStorageMatrix(point.shape, nodes_per_element,
                          point.porosity * point.volume *
                              storageSlope(mat, point_p[i], settings.min_suction_fraction) / dt,
                          local);
    addPointConductivityMatrix(point.shape, nodes_per_element,
                               theta * point.volume * point_mobility[i], local);
    if (settings.iteration != SeepageIteration::Newton) return;
    Real p_local[kMaxElementNodes];
    for (int a = 0; a < nodes_per_element; ++a) p_local[a] = nodal[point.dof[a]];
    const Real density = liquidDensity(mat.liquid, point_p[i]);
    const Real mobility_slope = darcyMobilityPressureDerivative(mat, point_p[i], point_mobility[i]);
    // N4: m g drho_L/dp with drho_L/dp = rho_L / K_L (4.13).
    const Real density_slope = point_mobility[i] * gravity * density / mat.liquid.bulk_modulus;
    addPointFluxJacobianCorrection(point.shape, nodes_per_element, p_local, density * gravity,
                                   theta * point.volume * mobility_slope,
                                   theta * point.volume * density_slope, local);
  }

  /// The iteration matrix (pointMatrix) at the iterate of the last storageAndFlux.
  void assembleMatrix(Real dt) {
    matrix_values.assign(system->entryCount(), 0.0);
    for (std::size_t i = 0; i < liquid_points.size(); ++i) {
      const Point& point = liquid_points[i];
      if (!touchesOwnedRow(point)) continue;
      Real local[kMaxElementNodes][kMaxElementNodes];
      pointMatrix(i, dt, p, local);
      for (int a = 0; a < nodes_per_element; ++a) {
        const int row = point.dof[a];
        if (!system->owns(row) || isFixed(row)) continue;
        for (int b = 0; b < nodes_per_element; ++b) {
          // Eliminated: a fixed unknown's update is 0 (keeps Picard's matrix symmetric).
          if (isFixed(point.dof[b])) continue;
          matrix_values[point.entry[a][b]] += local[a][b];
        }
      }
    }
    for (int row = system->firstOwned(); row < system->endOwned(); ++row)
      if (isFixed(row)) matrix_values[system->entry(row, row)] = 1;
    system->setValues(matrix_values);
  }

  bool isFixed(int dof) const { return fixed[dof] || held[dof]; }
  Real fixedValue(int dof) const { return fixed[dof] ? fixed_value[dof] : 0.0; }

  Real pointsLiquidMass(const std::vector<Real>& nodal) const {
    Real mass = 0;
    for (std::size_t i = 0; i < liquid_points.size(); ++i) {
      const Point& point = liquid_points[i];
      const Real pressure =
          old_level_from_points ? pressure_from_points[i] : interpolate(point, nodal);
      mass += point.porosity * point.volume * liquidContent(material(point), pressure);
    }
    return mass;
  }

  SeepageStepResult step(Real dt);
};

// ------------------------------------------------------------------ construction

ImplicitSeepageSolver::ImplicitSeepageSolver(const Mesh& mesh, MaterialPoints& points,
                                             const std::vector<MaterialSpec>& materials,
                                             Teuchos::RCP<const Teuchos::Comm<int>> comm)
    : impl_(std::make_unique<Impl>(mesh, points, materials)) {
  Impl& s = *impl_;
  PointShapes shapes;
  // The element's own (linear) shapes whatever the mesh's transfers use: the assembly is
  // element by element (its matrix graph the mesh's connectivity). evaluatePointShapes
  // stores every point's record (no chunk is computed).
  evaluatePointShapes(mesh, points, shapes, ShapeFamily::Linear);
  const auto shape_h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), shapes.stored_p);
  const auto element = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.element);
  const auto material = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.material);
  const auto porosity = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.porosity);
  const auto volume = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.volume);
  const auto connectivity =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);

  // Active nodes: nodes of elements holding liquid-carrying points, numbered in mesh order.
  s.dof_of_node.assign(mesh.numNodes(), kNone);
  std::vector<char> element_wet(mesh.numElements(), 0);
  for (int p = 0; p < points.count; ++p) {
    if (element(p) < 0 || !carriesLiquid(s.table.host(material(p)).phase)) continue;
    element_wet[element(p)] = 1;
    for (int a = 0; a < s.nodes_per_element; ++a) s.dof_of_node[connectivity(element(p), a)] = 0;
  }
  for (int node = 0; node < mesh.numNodes(); ++node)
    if (s.dof_of_node[node] == 0) {
      s.dof_of_node[node] = static_cast<int>(s.node_of_dof.size());
      s.node_of_dof.push_back(node);
    }
  if (s.node_of_dof.empty())
    throw InputError("Materials", "implicit seepage needs liquid-carrying material points");
  std::vector<std::vector<int>> element_dofs;
  for (int e = 0; e < mesh.numElements(); ++e) {
    if (!element_wet[e]) continue;
    std::vector<int> dofs;
    for (int a = 0; a < s.nodes_per_element; ++a) dofs.push_back(s.dof_of_node[connectivity(e, a)]);
    element_dofs.push_back(dofs);
  }
  for (int p = 0; p < points.count; ++p) {
    if (element(p) < 0 || !carriesLiquid(s.table.host(material(p)).phase)) continue;
    Impl::Point point{};
    point.index = p;
    point.material = material(p);
    point.porosity = porosity(p);
    point.volume = volume(p);
    point.shape = shape_h(p);
    for (int a = 0; a < s.nodes_per_element; ++a) point.dof[a] = s.dof_of_node[point.shape.node[a]];
    s.liquid_points.push_back(point);
    s.reference_density = s.table.host(point.material).liquid.density;
  }
  s.system = std::make_unique<SeepageLinearSystem>(comm, s.dofs(), element_dofs);
  for (Impl::Point& point : s.liquid_points)
    for (int a = 0; a < s.nodes_per_element; ++a)
      for (int b = 0; b < s.nodes_per_element; ++b)
        point.entry[a][b] = s.system->entry(point.dof[a], point.dof[b]);
  s.fixed.assign(s.dofs(), 0);
  s.switchable.assign(s.dofs(), 0);
  s.held.assign(s.dofs(), 0);
  s.fixed_value.assign(s.dofs(), 0.0);
  s.supply.assign(s.dofs(), 0.0);
  s.p.assign(s.dofs(), 0.0);
  setSettings(s.settings);
  projectPressureFromPoints();
}

ImplicitSeepageSolver::~ImplicitSeepageSolver() = default;

void ImplicitSeepageSolver::setSettings(const ImplicitSeepageSpec& settings) {
  // The deck refuses this pair (DeckParts.cpp); the check covers settings built in code.
  if (settings.iteration == SeepageIteration::Newton && settings.linear.solver == "CG")
    throw InputError("Implicit Seepage/Linear Solver/Solver",
                     "gmres or direct with Nonlinear Solver: newton (non-symmetric Jacobian)");
  impl_->settings = settings;
  impl_->next_step = settings.initial_step;
  impl_->last_step = 0;  // a new stage: no rate history for the time error
  impl_->system->setSolver(settings.linear);
}

void ImplicitSeepageSolver::setGravity(Real gravity) {
  impl_->gravity = gravity;
}

void ImplicitSeepageSolver::Impl::applyConditions(const SeepageBoundaryConditions& conditions,
                                                  bool keep_held) {
  const std::vector<char> was_held = held;
  std::fill(fixed.begin(), fixed.end(), 0);
  std::fill(switchable.begin(), switchable.end(), 0);
  std::fill(held.begin(), held.end(), 0);
  std::fill(supply.begin(), supply.end(), 0.0);
  // Nodes outside the active region carry no unknown: their conditions do not apply.
  for (std::size_t j = 0; j < conditions.supply_nodes.size(); ++j) {
    const int dof = dof_of_node.at(conditions.supply_nodes[j]);
    if (dof == kNone) continue;
    supply[dof] = reference_density * conditions.supplies[j];
    switchable[dof] = conditions.switchable[j];
    // A node that stays switchable keeps its switch from the last step (the active set's
    // starting guess); one that was Dirichlet or free starts free.
    if (keep_held && switchable[dof]) held[dof] = was_held[dof];
  }
  for (std::size_t j = 0; j < conditions.pressure_nodes.size(); ++j) {
    const int dof = dof_of_node.at(conditions.pressure_nodes[j]);
    if (dof == kNone) continue;
    fixed[dof] = 1;
    fixed_value[dof] = conditions.pressures[j];
    switchable[dof] = 0;
    held[dof] = 0;
    supply[dof] = 0;
  }
}

void ImplicitSeepageSolver::setBoundaryConditions(const SeepageBoundaryConditions& conditions) {
  impl_->plan.reset();
  impl_->totals.condition_inflow.clear();
  impl_->totals.condition_inflow_last_step.clear();
  impl_->applyConditions(conditions, false);
}

void ImplicitSeepageSolver::setBoundaryPlan(const SeepageBoundaryPlan& plan) {
  impl_->plan = std::make_unique<SeepageBoundaryPlan>(plan);
  Impl& s = *impl_;
  s.condition_of_dof.assign(s.dofs(), kNone);
  for (std::size_t c = 0; c < plan.conditions.size(); ++c)
    for (const int node : plan.conditions[c].nodes) {
      const int dof = s.dof_of_node.at(node);
      if (dof != kNone && s.condition_of_dof[dof] == kNone)
        s.condition_of_dof[dof] = static_cast<int>(c);
    }
  s.totals.condition_inflow.assign(plan.conditions.size(), 0);
  s.totals.condition_inflow_last_step.assign(plan.conditions.size(), 0);
  impl_->applyConditions(plan.at(impl_->time, impl_->time, impl_->settings.theta), false);
}

void ImplicitSeepageSolver::beginStage(const StageSpec& stage, Real table_origin) {
  setSettings(stage.seepage);
  setGravity(stage.gravity);
  const Real origin = std::isnan(table_origin) ? impl_->time : table_origin;
  setBoundaryPlan(seepageBoundaryPlan(impl_->mesh, impl_->points, stage, origin));
  projectPressureFromPoints();
}

void ImplicitSeepageSolver::projectPressureFromPoints() {
  Impl& s = *impl_;
  s.last_step = 0;  // a state set from outside: no rate history
  const auto pressure =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.points.pressure_liquid);
  // Consistent L2 projection: sum_p V N_a N_b p_b = sum_p V N_a p_p.
  s.system->beginAssembly();
  std::vector<Real> rhs(s.dofs(), 0.0);
  for (const auto& point : s.liquid_points) {
    if (!s.touchesOwnedRow(point)) continue;
    Real local[kMaxElementNodes][kMaxElementNodes] = {};
    addPointStorageMatrix(point.shape, s.nodes_per_element, point.volume, local);
    for (int a = 0; a < s.nodes_per_element; ++a) {
      if (!s.system->owns(point.dof[a])) continue;
      s.system->add(point.dof[a], point.dof, local[a], s.nodes_per_element);
      rhs[point.dof[a]] += point.volume * point.shape.value[a] * pressure(point.index);
    }
  }
  s.system->endAssembly();
  s.system->solve(rhs, s.p);
  s.pressure_from_points.resize(s.liquid_points.size());
  for (std::size_t i = 0; i < s.liquid_points.size(); ++i)
    s.pressure_from_points[i] = pressure(s.liquid_points[i].index);
  s.old_level_from_points = true;
}

void ImplicitSeepageSolver::setNodalPressure(const std::function<Real(Real, Real)>& pressure) {
  Impl& s = *impl_;
  s.last_step = 0;                  // a state set from outside: no rate history
  s.old_level_from_points = false;  // the caller's nodal field is the start
  const auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.mesh.coordinates);
  for (int dof = 0; dof < s.dofs(); ++dof) {
    const int node = s.node_of_dof[dof];
    s.p[dof] = pressure(X(node, 0), X(node, 1));
  }
}

// ------------------------------------------------------------------ time stepping

SeepageStepResult ImplicitSeepageSolver::Impl::step(Real dt) {
  SeepageStepResult result;
  const Real theta = settings.theta;
  // Conditions of the step, at its end (SeepageBoundaryPlan::at); a rejected step restores
  // the switches and the next attempt re-evaluates them for its own step.
  const std::vector<char> held_old = held;
  if (plan) applyConditions(plan->at(time, time + dt, theta), true);
  const std::vector<Real> p_old = p;
  const std::vector<Real> flux_old = flux(p_old);
  cacheOldLevel(p_old);

  std::vector<Real> residual(dofs()), terms_scale(dofs()), s, f;
  // R = storage/dt + theta F(p) + (1 - theta) F(p_old) - Q (Q on free supply nodes only).
  auto evaluate = [&]() {
    storageAndFlux(p, s, f);
    for (int i = 0; i < dofs(); ++i) {
      const Real q = isFixed(i) ? 0.0 : supply[i];
      residual[i] = thetaResidual(s[i], f[i], flux_old[i], q, dt, theta);
      terms_scale[i] = std::fabs(s[i] / dt) + std::fabs(theta * f[i]) +
                       std::fabs((1 - theta) * flux_old[i]) + std::fabs(q);
    }
  };
  const Real mass_floor = 1e-15 * pointsLiquidMass(p_old) / dt;

  bool settled = false;
  for (int pass = 0; pass < settings.max_active_set_iterations && !settled; ++pass) {
    ++result.active_set_passes;
    for (int i = 0; i < dofs(); ++i)
      if (isFixed(i)) p[i] = fixedValue(i);
    bool converged = false;
    Real last_update = std::numeric_limits<Real>::infinity();
    Real previous_update = std::numeric_limits<Real>::infinity();
    result.residual_norms.clear();
    std::vector<Real> update;
    Real free_residual = 0, scale = 0, previous_residual = 0;
    auto freeResidual = [&]() {
      evaluate();
      free_residual = 0;
      scale = 0;
      for (int i = 0; i < dofs(); ++i)
        if (!isFixed(i)) {
          free_residual += std::fabs(residual[i]);
          scale += terms_scale[i];
        }
    };
    for (int m = 0; m <= settings.max_picard_iterations; ++m) {
      freeResidual();
      // Newton's backtracking: far from the solution (a sharp wetting front, the first
      // iteration of a step) the full Newton update can raise the residual and, repeated,
      // diverge; the update is halved (at most kMaxCuts times) until the free residual
      // falls. Near the solution the full update is taken (quadratic convergence), and
      // once the residual meets the mass tolerance nothing is cut (round-off noise).
      // Picard keeps its plain updates (its results do not change).
      constexpr int kMaxCuts = 6;
      Real converged_residual = std::max(settings.mass_tolerance * scale, mass_floor);
      for (int cut = 0; settings.iteration == SeepageIteration::Newton && m > 0 && cut < kMaxCuts &&
                        free_residual > converged_residual && !(free_residual < previous_residual);
           ++cut) {
        for (int i = 0; i < dofs(); ++i) {
          update[i] *= 0.5;
          p[i] -= update[i];
        }
        last_update *= 0.5;
        freeResidual();
      }
      if (!std::isfinite(free_residual)) break;  // diverged: the step is halved
      converged_residual = std::max(settings.mass_tolerance * scale, mass_floor);
      previous_residual = free_residual;
      result.residual_norms.push_back(free_residual);
      if (m > 0 && last_update <= settings.pressure_tolerance &&
          free_residual <= converged_residual) {
        converged = true;
        break;
      }
      if (m == settings.max_picard_iterations) break;
      // Reuse Matrix: the matrix of the pass's first iteration (the fixed set changes it
      // between passes) serves the later ones (chord iteration) while the updates at least
      // halve; a slower iteration gets a fresh matrix.
      const bool refactor = !settings.reuse_matrix || m == 0 || last_update > 0.5 * previous_update;
      if (refactor) assembleMatrix(dt);
      std::vector<Real> rhs(dofs());
      for (int i = 0; i < dofs(); ++i) rhs[i] = isFixed(i) ? 0.0 : -residual[i];
      result.linear_iterations += system->solve(rhs, update, refactor);
      ++result.picard_iterations;
      previous_update = last_update;
      last_update = 0;
      for (int i = 0; i < dofs(); ++i) {
        p[i] += update[i];
        last_update = std::max(last_update, std::fabs(update[i]));
      }
    }
    if (!converged) {
      p = p_old;
      held = held_old;
      result.converged = false;
      return result;
    }
    // Signorini switches: a free switchable node may not exceed p = 0; a held one returns to
    // its supply when the soil would take more than the supply (its residual is the inflow
    // that holds p = 0).
    settled = true;
    for (int i = 0; i < dofs(); ++i) {
      if (!switchable[i]) continue;
      if (!held[i] && p[i] > settings.pressure_tolerance) {
        held[i] = 1;
        settled = false;
      } else if (held[i] &&
                 residual[i] > supply[i] + settings.mass_tolerance * terms_scale[i] + mass_floor) {
        held[i] = 0;
        settled = false;
      }
    }
  }
  if (!settled) {
    p = p_old;
    held = held_old;
    result.converged = false;
    return result;
  }
  // Mass balance of the step: storage change = inflow (supplies + reactions of held and
  // prescribed nodes) + dt x free-node residual (bounded by the mass tolerance).
  Real inflow = 0;
  result.condition_inflow.assign(plan ? plan->conditions.size() : 0, 0);
  for (int i = 0; i < dofs(); ++i) {
    const Real node_inflow = isFixed(i) ? residual[i] : supply[i];
    inflow += node_inflow;
    if (plan && condition_of_dof[i] != kNone)
      result.condition_inflow[condition_of_dof[i]] += node_inflow * dt;
  }
  result.inflow = inflow * dt;
  Real storage_change = 0, max_ds = 0;
  for (std::size_t i = 0; i < liquid_points.size(); ++i) {
    const Point& point = liquid_points[i];
    const PointMaterial& mat = material(point);
    // The old level's p_L, S_L and rho_L as cached for the step: one SWRC per point here.
    const Real p_new = interpolate(point, p), s_new = saturationOfPressure(mat, p_new);
    storage_change += point.porosity * point.volume *
                      liquidContentChangeFrom(mat, p_new, s_new, point_p_old[i], point_s_old[i],
                                              point_rho_old[i]);
    max_ds = std::max(max_ds, std::fabs(s_new - point_s_old[i]));
  }
  result.storage_change = storage_change;
  result.max_saturation_change = max_ds;
  result.converged = true;
  return result;
}

SeepageStepResult ImplicitSeepageSolver::step(Real dt) {
  Impl& s = *impl_;
  const SeepageStepResult result = s.step(dt);
  if (result.converged) {
    s.old_level_from_points = false;  // the nodal field holds the points' mass from now on
    s.time += dt;
    ++s.totals.steps;
    s.totals.inflow += result.inflow;
    if (s.totals.condition_inflow.size() == result.condition_inflow.size()) {
      for (std::size_t k = 0; k < result.condition_inflow.size(); ++k)
        s.totals.condition_inflow[k] += result.condition_inflow[k];
      s.totals.condition_inflow_last_step = result.condition_inflow;
    }
    s.totals.storage_change += result.storage_change;
  } else {
    ++s.totals.rejected_steps;
  }
  s.totals.picard_iterations += result.picard_iterations;
  s.totals.linear_iterations += result.linear_iterations;
  return result;
}

void ImplicitSeepageSolver::advanceTo(Real end) {
  Impl& s = *impl_;
  const Real tolerance = 1e-12 * std::max<Real>(std::fabs(end), 1);
  // The step's start and its increments: buffers kept across steps (no allocation a step).
  std::vector<Real> start, increment;
  while (s.time < end - tolerance) {
    const Real planned =
        s.settings.adaptive ? std::min(s.next_step, s.settings.max_step) : s.settings.initial_step;
    const Real dt = std::min(planned, end - s.time);
    if (s.settings.adaptive) start = s.p;
    const SeepageStepResult result = step(dt);
    if (!result.converged) {
      if (!s.settings.adaptive || dt <= s.settings.min_step) {
        std::ostringstream out;
        out << "implicit seepage: the step of " << dt << " s at t = " << s.time
            << " s did not converge (Picard/Newton iterations and active-set passes exhausted)";
        throw RunError(out.str());
      }
      s.next_step = std::max(0.5 * dt, s.settings.min_step);
      continue;
    }
    s.accepted_step = dt;
    if (!s.settings.adaptive) continue;
    // The time error needs the previous step's nodal rate (SeepageStepControl.hpp).
    increment.resize(s.p.size());
    for (std::size_t i = 0; i < increment.size(); ++i) increment[i] = s.p[i] - start[i];
    SeepageStepOutcome outcome;
    outcome.dt = dt;
    outcome.iterations = result.picard_iterations;
    outcome.max_saturation_change = result.max_saturation_change;
    if (s.last_step > 0)
      outcome.time_error = seepageTimeError(dt, increment, s.last_step, s.last_increment);
    std::swap(s.last_increment, increment);  // increment's storage serves the next step
    s.last_step = dt;
    if (dt < planned * (1 - 1e-9)) continue;  // cut to land on `end`: keep the planned step
    s.next_step = nextSeepageStep(outcome, s.settings);
  }
}

// ------------------------------------------------------------------ hand-over and queries

void ImplicitSeepageSolver::handOver() {
  Impl& s = *impl_;
  s.old_level_from_points = false;  // the points take the nodal field's state below
  auto pressure =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.points.pressure_liquid);
  auto density = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.points.density_liquid);
  auto saturation = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.points.saturation);
  auto conductivity =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.points.conductivity);
  auto mass = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.points.mass_liquid);
  for (const auto& point : s.liquid_points) {
    const PointMaterial& mat = s.material(point);
    const Real p = s.interpolate(point, s.p);
    const LiquidState state = saturationAndConductivity(mat, p);
    const int i = point.index;
    pressure(i) = p;
    density(i) = liquidDensity(mat.liquid, p);  // 4.13
    saturation(i) = state.saturation;
    conductivity(i) = state.conductivity;
    mass(i) = point.porosity * point.volume * liquidContent(mat, p);  // 4.47
  }
  Kokkos::deep_copy(s.points.pressure_liquid, pressure);
  Kokkos::deep_copy(s.points.density_liquid, density);
  Kokkos::deep_copy(s.points.saturation, saturation);
  Kokkos::deep_copy(s.points.conductivity, conductivity);
  Kokkos::deep_copy(s.points.mass_liquid, mass);
}

SeepageLinearisation ImplicitSeepageSolver::linearise(Real dt, const std::vector<Real>& trial) {
  Impl& s = *impl_;
  SeepageLinearisation out;
  out.unknowns = s.dofs();
  out.node = s.node_of_dof;
  std::vector<Real> nodal(s.dofs());
  for (int i = 0; i < s.dofs(); ++i) nodal[i] = trial.at(s.node_of_dof[i]);
  const Real theta = s.settings.theta;
  const std::vector<Real> flux_old = s.flux(s.p);
  s.cacheOldLevel(s.p);
  std::vector<Real> storage, flux;
  s.storageAndFlux(nodal, storage, flux);
  out.residual.resize(s.dofs());
  for (int i = 0; i < s.dofs(); ++i)
    out.residual[i] = thetaResidual(storage[i], flux[i], flux_old[i], s.supply[i], dt, theta);
  out.matrix.assign(static_cast<std::size_t>(s.dofs()) * s.dofs(), 0.0);
  for (std::size_t i = 0; i < s.liquid_points.size(); ++i) {
    const Impl::Point& point = s.liquid_points[i];
    Real local[kMaxElementNodes][kMaxElementNodes];
    s.pointMatrix(i, dt, nodal, local);
    for (int a = 0; a < s.nodes_per_element; ++a)
      for (int b = 0; b < s.nodes_per_element; ++b)
        out.matrix[static_cast<std::size_t>(point.dof[a]) * s.dofs() + point.dof[b]] += local[a][b];
  }
  return out;
}

Real ImplicitSeepageSolver::time() const {
  return impl_->time;
}
void ImplicitSeepageSolver::setTime(Real time) {
  impl_->time = time;
}
Real ImplicitSeepageSolver::nextStep() const {
  return impl_->next_step;
}
Real ImplicitSeepageSolver::lastAcceptedStep() const {
  return impl_->accepted_step;
}
Real ImplicitSeepageSolver::liquidMass() const {
  return impl_->pointsLiquidMass(impl_->p);
}
std::vector<std::string> ImplicitSeepageSolver::conditionNames() const {
  std::vector<std::string> names;
  if (impl_->plan)
    for (const auto& condition : impl_->plan->conditions) names.push_back(condition.name);
  return names;
}

const SeepageTotals& ImplicitSeepageSolver::totals() const {
  return impl_->totals;
}
int ImplicitSeepageSolver::activeNodeCount() const {
  return impl_->dofs();
}

std::vector<Real> ImplicitSeepageSolver::nodalPressure() const {
  std::vector<Real> out(impl_->mesh.numNodes(), std::numeric_limits<Real>::quiet_NaN());
  for (int dof = 0; dof < impl_->dofs(); ++dof) out[impl_->node_of_dof[dof]] = impl_->p[dof];
  return out;
}

std::vector<int> ImplicitSeepageSolver::heldNodes() const {
  std::vector<int> out;
  for (int dof = 0; dof < impl_->dofs(); ++dof)
    if (impl_->held[dof]) out.push_back(impl_->node_of_dof[dof]);
  return out;
}

}  // namespace argine
