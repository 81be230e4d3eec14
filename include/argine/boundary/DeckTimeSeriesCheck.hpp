#pragma once
/// @file DeckTimeSeriesCheck.hpp
/// Reads every time series of every stage of a deck (inline tables and CSV gauge files)
/// before anything runs, so a table whose times do not increase, or a bad file of a later
/// stage, is an InputError at `argine check` time instead of after hours of earlier stages.

#include "argine/input/Deck.hpp"

namespace argine {

/// Throws the InputError of the first time series of `deck` that cannot be read: `where` is
/// the deck key ("Stages/flood/Boundary Conditions/river/Total Head File") and the message
/// names the file, the row and what was expected.
void checkDeckTimeSeries(const Deck& deck);

}  // namespace argine
