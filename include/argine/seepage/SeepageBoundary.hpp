#pragma once
/// @file SeepageBoundary.hpp
/// Boundary conditions of the implicit seepage solver as plain node lists, so any source of
/// zones and time series (today the stage's side sets and constants) can feed them:
///  - prescribed pressure (Dirichlet) p_L on nodes;
///  - supply: a prescribed volumetric inflow per node (m^2/s per metre thickness: the normal
///    inflow rate q times the node's tributary boundary length); none = impermeable, the
///    natural condition (the default everywhere else);
///  - switchable nodes (a supply node flagged `switchable`): the Signorini condition of a
///    ponding surface or a potential seepage face, p_L <= 0 and inflow <= supply, with
///    equality in one of them. A switchable node takes its supply while p_L < 0 and holds
///    p_L = 0 when it would exceed 0; while held it returns to its supply once the soil
///    would take more than the supply. A seepage face is a switchable node with supply 0
///    (p_L = 0 where water flows out, no flow where p_L < 0); infiltration with ponding is
///    one with supply q L/2 > 0 (the surface saturates: ponding, p_L = 0, the excess runs off).

#include <string>
#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

struct Mesh;
struct SideSet;
struct StageSpec;

struct SeepageBoundaryConditions {
  std::vector<int> pressure_nodes;  ///< mesh nodes with a prescribed p_L
  std::vector<Real> pressures;      ///< p_L there (Pa, compression positive)
  std::vector<int> supply_nodes;    ///< mesh nodes with a prescribed inflow or switch
  std::vector<Real> supplies;       ///< volumetric inflow (m^2/s per metre thickness)
  std::vector<char> switchable;     ///< 1: ponding / seepage-face node (p_L <= 0)

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

/// The implicit conditions of a stage: LiquidPressure -> pressure on the side set's nodes;
/// Infiltration -> supply Flux x L/2, switchable when Ponding; SeepageFace -> switchable
/// with supply 0; LiquidFixity (impermeable) -> nothing (natural); solid conditions are
/// ignored (fixed skeleton). Throws InputError ("Stages/<stage>/Boundary Conditions/<name>")
/// for a side set the mesh lacks.
SeepageBoundaryConditions seepageBoundaryConditions(const Mesh& mesh, const StageSpec& stage);

}  // namespace argine
