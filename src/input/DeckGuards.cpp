// The Guards section (issue P8): physical guards checked after each explicit step.
#include "DeckParts.hpp"

namespace argine::input_detail {

GuardsSpec parseGuards(const DeckSection& guards) {
  GuardsSpec spec;
  spec.leaving_points =
      guards.word("Points Leaving Mesh") == "remove" ? LeavingPoints::Remove : LeavingPoints::Stop;
  spec.mass_balance_bound = guards.real("Mass Balance Bound");
  spec.kinetic_energy_bound = guards.real("Kinetic Energy Bound");
  return spec;
}

}  // namespace argine::input_detail
