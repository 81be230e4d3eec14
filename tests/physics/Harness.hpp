#pragma once
// Small scenes for the explicit two-phase solver tests: stage specs and a run loop.

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../transfer/TestScenes.hpp"
#include "argine/core/Error.hpp"
#include "argine/physics/ExplicitTwoPhaseSolver.hpp"
#include "argine/physics/PointInitialisation.hpp"

namespace argine::test {

/// A stage with the given solver, gravity, damping and boundaries; automatic time step with
/// the given criteria (or fixed when fixed_step > 0).
inline StageSpec makeStage(const std::string& name, SolverKind solver, Real gravity, Real damping,
                           std::vector<BoundarySpec> boundaries,
                           std::vector<CriterionKind> criteria = {CriterionKind::CflUndrained,
                                                                  CriterionKind::Mieremet},
                           Real fixed_step = 0, Real safety = 0.5) {
  StageSpec stage;
  stage.name = name;
  stage.solver = solver;
  stage.gravity = gravity;
  stage.local_damping = damping;
  stage.boundaries = std::move(boundaries);
  stage.time_step.automatic = fixed_step <= 0;
  stage.time_step.fixed_step = fixed_step;
  stage.time_step.safety_factor = safety;
  stage.time_step.criteria = std::move(criteria);
  stage.duration = 1;
  return stage;
}

/// Runs the solver to `end` (s), calling `each` after every step.
inline void runUntil(ExplicitTwoPhaseSolver& solver, Real end,
                     const std::function<void()>& each = nullptr) {
  while (solver.time() < end * (1 - 1e-12)) {
    const Real dt = std::min(solver.chooseTimeStep().time_step, end - solver.time());
    solver.step(dt);
    if (each) each();
  }
}

/// The message of the RunError that `action` throws; records a test failure and returns ""
/// when it throws none.
inline std::string runErrorMessage(const std::function<void()>& action) {
  try {
    action();
  } catch (const RunError& error) {
    return error.what();
  }
  ADD_FAILURE() << "expected RunError";
  return "";
}

/// A one-element-wide column of ny quads, width w, height h, all material 0, initialised.
struct Column {
  Mesh mesh;
  MaterialPoints points;
  std::vector<MaterialSpec> materials;
  Column(int ny, Real w, Real h, const MaterialSpec& material)
      : mesh(rectangleMesh(1, ny, w, h, ElementType::Quad4)),
        points(seedUniform(mesh)),
        materials{material} {
    initialisePointState(materials, points);
  }
};

}  // namespace argine::test
