#include "argine/init/Initialisation.hpp"

#include <cstdio>

#include "argine/init/K0Procedure.hpp"
#include "argine/input/Deck.hpp"
#include "argine/physics/PointInitialisation.hpp"

namespace argine {

std::string initialisePoints(const Deck& deck, const Mesh& mesh, MaterialPoints& points) {
  initialisePointState(deck.materials, points);
  const InitialisationSpec& spec = deck.initialisation;
  if (spec.method == InitialisationSpec::Method::Uniform)
    return "initial state: uniform per material (Materials/<name>/Initial State)";
  const Real gravity = deck.stages.empty() ? kStandardGravity : deck.stages.front().gravity;
  if (spec.method == InitialisationSpec::Method::PorePressure)
    return applyPorePressure(spec, deck.materials, gravity, points);
  applyK0Procedure(K0Profile(spec, mesh, deck.materials, gravity), points);
  char line[256];
  std::snprintf(line, sizeof line,
                "initial state: K0 procedure, g = %.4g m/s2, %s phreatic surface, %s", gravity,
                spec.phreatic_surface.empty() ? "no" : "with",
                spec.max_suction >= 0 ? "suction capped" : "suction not capped");
  std::string text = line;
  if (spec.max_suction >= 0) {
    std::snprintf(line, sizeof line, " at %.4g Pa", spec.max_suction);
    text += line;
  }
  return text;
}

}  // namespace argine
