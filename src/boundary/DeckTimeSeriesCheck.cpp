#include "argine/boundary/DeckTimeSeriesCheck.hpp"

#include "argine/boundary/HydraulicConditions.hpp"

namespace argine {

void checkDeckTimeSeries(const Deck& deck) {
  for (const StageSpec& stage : deck.stages)
    for (const BoundarySpec& boundary : stage.boundaries) {
      (void)makeTimeSeries(boundary.hydraulic.series, 0);  // InputError(where) when bad
      (void)makeLinearInX(boundary.hydraulic, 0);          // its end series, when given
    }
}

}  // namespace argine
