#pragma once
/// @file HydraulicRun.hpp
/// A deck run for the hydraulic-condition verification cases (V4, V6): the deck's mesh and
/// points, the explicit solver driven by hand to exact sample times, and the liquid volume
/// through each hydraulic condition summed over every step (what Simulation writes into
/// <name>_boundary_flux.csv), next to the storage change of the points.

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "argine/input/Deck.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/physics/ExplicitTwoPhaseSolver.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine::verification {

class HydraulicRun {
 public:
  /// Sets up the points after initialisePointState (e.g. a hydrostatic p_L profile).
  using Initialiser = std::function<void(const std::vector<MaterialSpec>&, MaterialPoints&)>;
  /// Loads the mesh, seeds and initialises the points as the deck's Initialisation says (as
  /// `argine run` does; then `initialise`, if given), begins the first stage.
  explicit HydraulicRun(const Deck& deck, const Initialiser& initialise = nullptr);
  HydraulicRun(const HydraulicRun&) = delete;
  HydraulicRun& operator=(const HydraulicRun&) = delete;
  ~HydraulicRun();

  /// Steps until time() == `time` exactly (the last step shortened), summing the fluxes.
  void advanceTo(Real time);

  Real time() const { return solver_->time(); }
  long steps() const { return steps_; }
  double wallSeconds() const { return wall_seconds_; }
  /// Processor time of the set-up and the steps (s): the wall time on an idle core, which
  /// the accuracy-against-cost studies chart (the machine is usually shared).
  double cpuSeconds() const { return cpu_seconds_; }
  /// Liquid volume (m^3/m) that entered through the condition `name` since the start.
  Real inflow(const std::string& name) const;
  /// The sum over every condition.
  Real totalInflow() const;
  /// (sum of the points' M_L - initial) / rho_L (m^3/m).
  Real storageChange() const;
  const std::map<std::string, Real>& inflows() const { return inflow_; }
  const ExplicitTwoPhaseSolver& solver() const { return *solver_; }
  const MaterialPoints& points() const { return points_; }
  const Mesh& mesh() const { return mesh_; }

 private:
  Deck deck_;
  Mesh mesh_;
  MaterialPoints points_;
  std::unique_ptr<ExplicitTwoPhaseSolver> solver_;
  std::map<std::string, Real> inflow_;
  Real initial_liquid_mass_ = 0;
  long steps_ = 0;
  double wall_seconds_ = 0;
  double cpu_seconds_ = 0;
};

/// Sum of the points' liquid masses (kg/m).
Real liquidMass(const MaterialPoints& points);

}  // namespace argine::verification
