#pragma once
/// @file DeckReader.hpp
/// Reading an input deck: YAML file -> parameter list -> schema validation -> Deck structs
/// -> cross-key checks, all before anything runs. Every problem is an InputError naming
/// the file or the key path and what was expected.
///
/// A deck is a YAML file with one top-level map `argine:` (see doc/deck-reference.md).

#include <string>

#include "argine/input/Deck.hpp"
#include "argine/mesh/Mesh.hpp"

namespace Teuchos {
class ParameterList;
template <typename Ordinal>
class Comm;
}  // namespace Teuchos

namespace argine {

/// Reads, validates and converts the deck at `path`. Rank 0 reads the file and broadcasts
/// its text over MPI_COMM_WORLD (a serial communicator when MPI is not initialised), so
/// every rank gets the same Deck or the same InputError.
Deck readDeck(const std::string& path);

/// As readDeck(path), over `comm`.
Deck readDeck(const std::string& path, const Teuchos::Comm<int>& comm);

/// Only the `Mesh` section of the deck at `path` (validated), for `argine mesh`: the rest
/// of the deck may still be unwritten.
MeshSpec readMeshSpec(const std::string& path);

/// Validates and converts a parameter list holding the deck's keys (the content of
/// `argine:`, or a list whose only entry is the sublist `argine`). `deck_path` is the deck
/// file the list came from: file keys are resolved relative to its directory (the working
/// directory when empty), and Deck::path is its absolute form.
Deck parseDeck(const Teuchos::ParameterList& parameters, const std::string& deck_path);

/// Checks that involve several keys (Minimum < Maximum Saturation, dilatancy <= friction,
/// one material per block, generator box and polygons, ...). parseDeck runs it; call it on
/// decks built in code.
void checkDeck(const Deck& deck);

/// Checks that every material's Block and every boundary condition's Node Set / Side Set
/// exists in `mesh`; the error names the key path and lists what the mesh has.
void checkDeckAgainstMesh(const Deck& deck, const Mesh& mesh);

}  // namespace argine
