#pragma once
/// @file ColumnRun.hpp
/// One run of a one-element-wide soil column (the 1D verification cases): the deck's mesh
/// re-generated with a chosen number of elements over the height, the points seeded and
/// initialised, and the explicit solver driven by hand so that it stops exactly at each
/// sample time (the last step before a sample time is shortened to land on it).

#include <chrono>
#include <memory>
#include <vector>

#include "argine/input/Deck.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/physics/ExplicitTwoPhaseSolver.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine::verification {

/// A copy of `deck` whose generated rectangle becomes a column of `elements` square quads
/// over its height, one element wide: element size = height / elements, width = that size.
/// InputError when the deck does not generate a rectangle.
Deck columnDeck(const Deck& deck, int elements);

/// Host copies of the point fields a 1D profile needs, one entry per material point.
struct ColumnProfile {
  std::vector<int> element;          ///< containing background element
  std::vector<double> initial_y;     ///< y at seeding (m): the material coordinate
  std::vector<double> y;             ///< current y (m)
  std::vector<double> pressure;      ///< p_L (Pa, compression positive)
  std::vector<double> saturation;    ///< S_L (-)
  std::vector<double> displacement;  ///< solid displacement u_y (m)
  std::vector<double> strain_yy;     ///< accumulated vertical strain (-, tension positive)
  std::vector<double> stress_yy;     ///< vertical effective stress (Pa, tension positive)
  std::vector<double> volume;        ///< V (m^3 per m thickness)
  std::vector<double> liquid_mass;   ///< M_L (kg per m thickness)
};

/// A column run in progress. Holds the mesh and points the solver refers to, so it is
/// neither copied nor moved.
class ColumnRun {
 public:
  /// Loads the mesh of `deck`, seeds and initialises the points, and begins the deck's
  /// first stage (its duration is ignored: advanceTo decides how far to go).
  explicit ColumnRun(const Deck& deck);
  ColumnRun(const ColumnRun&) = delete;
  ColumnRun& operator=(const ColumnRun&) = delete;
  ~ColumnRun();

  /// Steps until time() == `time` (s) exactly: each step is the solver's choice, the last
  /// one shortened to land on `time`. Throws RunError when the solver goes unstable.
  void advanceTo(Real time);

  /// The point fields now.
  ColumnProfile profile() const;

  Real time() const { return solver_->time(); }
  /// Steps taken so far.
  long steps() const { return steps_; }
  /// Wall time spent in setup and stepping so far (s).
  double wallSeconds() const { return wall_seconds_; }
  /// Smallest and largest step taken so far (s), the shortened landing steps excluded.
  Real smallestStep() const { return smallest_step_; }
  Real largestStep() const { return largest_step_; }
  const ExplicitTwoPhaseSolver& solver() const { return *solver_; }
  const Mesh& mesh() const { return mesh_; }
  int pointCount() const { return points_.count; }

 private:
  Deck deck_;
  Mesh mesh_;
  MaterialPoints points_;
  std::unique_ptr<ExplicitTwoPhaseSolver> solver_;
  long steps_ = 0;
  double wall_seconds_ = 0;
  Real smallest_step_ = 0;
  Real largest_step_ = 0;
};

}  // namespace argine::verification
