#pragma once
/// @file SeepageBoundary.hpp
/// Boundary conditions of the implicit seepage solver.
///
/// SeepageBoundaryConditions: the conditions at one instant as plain node lists:
///  - prescribed pressure (Dirichlet) p_L on nodes;
///  - supply: a prescribed volumetric inflow per node (m^2/s per metre thickness: the normal
///    inflow rate q times the node's tributary boundary length); none = impermeable, the
///    natural condition (the default everywhere else);
///  - switchable nodes (a supply node flagged `switchable`): the Signorini condition of a
///    saturated surface that runs off or a potential seepage face, p_L <= 0 and inflow <=
///    supply, with equality in one of them. A switchable node takes its supply while p_L < 0
///    and holds p_L = 0 when it would exceed 0; while held it returns to its supply once the
///    soil would take more than the supply. A seepage face is a switchable node with supply 0
///    (p_L = 0 where water flows out, no flow where p_L < 0); infiltration without ponding is
///    one with supply q L/2 (the surface saturates, p_L = 0, the excess runs off).
///
/// SeepageBoundaryPlan: a stage's conditions resolved ONCE to nodes (the skeleton is fixed),
/// with their time series (boundary/TimeSeries.hpp); at(t_n, t_n+1) gives the node lists of
/// one step. Where (the deck's BoundarySpec, the same keys as the explicit solver):
///  - `Side Set`: the set's sides of active elements (as the explicit HydraulicConditions);
///  - `Zone`: the free sides (boundary/FreeBoundary.hpp: sides of active elements whose
///    neighbour is empty or absent) whose midpoint lies in the zone (zoneContains), found on
///    the points at the stage start.
/// Each side of length L gives L/2 to each end node (linear edge shape functions). A node on
/// several conditions belongs to the first in deck order (as in the explicit solver).
/// What (values at the END of the step t_n+1, backward Euler; see at()):
///  - liquid pressure: p_L (constant) -> Dirichlet;
///  - pressure series: p(t) -> Dirichlet;
///  - total head H(t) (4.50): nodes with y <= H -> Dirichlet rho_L g (H - y); above the level,
///    by `Above Level`: constant pressure -> Dirichlet `Pressure Above Level`, linear suction ->
///    Dirichlet rho_L g (H - y) < 0, seepage face -> switchable node with supply 0;
///  - infiltration q(t) (m/s, rain positive): supply q L/2; `Ponding: false` (default):
///    switchable (runs off at p_L = 0); `Ponding: true`: the supply is always imposed (the
///    pressure may exceed 0: the pond's water is forced in), as in the explicit solver;
///  - seepage face: switchable with supply 0;
///  - impermeable: nothing (natural); solid conditions: ignored (fixed skeleton).

#include <string>
#include <vector>

#include "argine/boundary/LinearInX.hpp"
#include "argine/boundary/TimeSeries.hpp"
#include "argine/core/Types.hpp"
#include "argine/input/Deck.hpp"

namespace argine {

struct Mesh;
struct SideSet;
struct MaterialPoints;

struct SeepageBoundaryConditions {
  std::vector<int> pressure_nodes;  ///< mesh nodes with a prescribed p_L
  std::vector<Real> pressures;      ///< p_L there (Pa, compression positive)
  std::vector<int> supply_nodes;    ///< mesh nodes with a prescribed inflow or switch
  std::vector<Real> supplies;       ///< volumetric inflow (m^2/s per metre thickness)
  std::vector<char> switchable;     ///< 1: runoff / seepage-face node (p_L <= 0)

  /// Appends prescribed pressures (a node given twice keeps the last value).
  void addPressures(const std::vector<int>& nodes, const std::vector<Real>& values);
  /// Appends supplies; a node given twice sums its supplies and is switchable if either is.
  void addSupplies(const std::vector<int>& nodes, const std::vector<Real>& rates,
                   bool switchable_nodes);
};

/// The nodes of a side set and their tributary lengths (m): each side of length L gives L/2
/// to each of its end nodes (linear edge shape functions). Nodes ascending.
struct SideSetNodes {
  std::vector<int> nodes;
  std::vector<Real> lengths;
};
SideSetNodes sideSetNodeLengths(const Mesh& mesh, const SideSet& set);

/// One condition of a stage on its nodes (see the file comment).
struct SeepageCondition {
  std::string name;
  BoundaryKind kind = BoundaryKind::LiquidPressure;
  std::vector<int> nodes;       ///< mesh nodes it owns (first in deck order), ascending
  std::vector<Real> lengths;    ///< tributary lengths (m)
  std::vector<Real> abscissas;  ///< node x (m)
  std::vector<Real> heights;    ///< node y (m)
  TimeSeries series;            ///< pressure (Pa), head (m) or flux (m/s)
  LinearInX linear_in_x;        ///< pressure series: `series` at x0, linear to x1
  AboveLevel above = AboveLevel::ConstantPressure;
  Real pressure_above = 0;     ///< (Pa)
  bool ponding = false;        ///< infiltration: supply always imposed
  Real liquid_density = 1000;  ///< (kg/m^3) head -> pressure
};

class SeepageBoundaryPlan {
 public:
  std::vector<SeepageCondition> conditions;
  Real gravity = kStandardGravity;  ///< (m/s^2) of the head -> pressure conversion

  /// The node lists of the step t_start -> t_end of a theta scheme: Dirichlet values and the
  /// choice Dirichlet / switchable of a total head at t_end (the implicit end of the step:
  /// the unknowns are the end-of-step pressures); supplies theta q(t_end) + (1 - theta)
  /// q(t_start), the flux of the theta-weighted balance (backward Euler theta = 1: q(t_end);
  /// Crank-Nicolson: the trapezoidal mean, so a varying flux keeps second order; a varying
  /// Dirichlet value or level is taken at t_end by both).
  SeepageBoundaryConditions at(Real t_start, Real t_end, Real theta = 1) const;
  /// Whether any value changes in time (else at() is the same for every step).
  bool timeDependent() const;
};

/// The stage's conditions on the mesh and the points' active elements (for zones and for
/// side sets; the points' elements at the stage start). Throws InputError
/// ("Stages/<stage>/Boundary Conditions/<name>/Side Set") for a side set the mesh lacks, and
/// InputError at the time-series key for a missing gauge file.
/// `stage_start` (s): the simulation time at which the stage begins, the origin of its
/// tables' times (TimeOrigin::StageStart).
SeepageBoundaryPlan seepageBoundaryPlan(const Mesh& mesh, const MaterialPoints& points,
                                        const StageSpec& stage, Real stage_start = 0);

}  // namespace argine
