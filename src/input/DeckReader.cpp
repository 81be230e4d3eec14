#include "argine/input/DeckReader.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_DefaultSerialComm.hpp>
#include <Teuchos_GlobalMPISession.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_YamlParameterListCoreHelpers.hpp>

#include "DeckParts.hpp"
#include "ValueText.hpp"
#include "argine/core/Error.hpp"
#include "argine/input/DeckSchema.hpp"
#include "argine/input/DeckValidator.hpp"

namespace argine {

using namespace input_detail;

namespace {

/// The deck's text, read on rank 0 and broadcast, so all ranks fail or succeed together.
std::string broadcastDeckText(const std::string& path, const Teuchos::Comm<int>& comm) {
  int status = 0;  // 0: read, 1: could not open
  std::string text;
  if (comm.getRank() == 0) {
    std::ifstream file(path, std::ios::binary);
    if (file && !std::filesystem::is_directory(path)) {
      std::ostringstream content;
      content << file.rdbuf();
      text = content.str();
    } else {
      status = 1;
    }
  }
  Teuchos::broadcast<int, int>(comm, 0, &status);
  if (status != 0) throw InputError(path, "cannot open the deck file");
  int size = static_cast<int>(text.size());
  Teuchos::broadcast<int, int>(comm, 0, &size);
  text.resize(static_cast<std::size_t>(size));
  if (size > 0) Teuchos::broadcast<int, char>(comm, 0, size, &text[0]);
  return text;
}

/// Teuchos' parser message without its source-file and throw-count noise.
std::string parserMessage(const std::string& raw) {
  std::istringstream lines(raw);
  std::string line, message;
  while (std::getline(lines, line)) {
    const std::string t = trim(line);
    // The lexer text and the parser state after it are internals of the parser.
    if (t.rfind("Lexer text:", 0) == 0 || t.rfind("Parser was in state", 0) == 0) break;
    if (t.empty() || t.rfind("./packages/", 0) == 0 || t.rfind("/", 0) == 0 ||
        t.rfind("Throw number", 0) == 0 || t.rfind("Throw test", 0) == 0)
      continue;
    message += (message.empty() ? "" : "\n  ") + line;
  }
  const std::string suffix = " of parseYamlStream";
  for (auto at = message.find(suffix); at != std::string::npos; at = message.find(suffix))
    message.erase(at, suffix.size());
  const std::string prefix = "error: ";
  if (message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
  return message;
}

/// The keys written at the start of a line (no indentation), to explain a deck whose top
/// level is not the single map `argine:`.
std::vector<std::string> topLevelKeys(const std::string& text) {
  std::vector<std::string> keys;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.empty() || line[0] == ' ' || line[0] == '\t' || line[0] == '#' || line[0] == '\r')
      continue;
    if (line.rfind("---", 0) == 0 || line.rfind("...", 0) == 0 || line[0] == '%') continue;
    std::string key = trim(line.substr(0, line.find(':')));
    if (key.size() >= 2 && (key.front() == '"' || key.front() == '\'') && key.back() == key.front())
      key = key.substr(1, key.size() - 2);
    keys.push_back(key);
  }
  return keys;
}

/// The YAML text as a parameter list named after its single top-level key.
Teuchos::RCP<Teuchos::ParameterList> parseYaml(const std::string& text, const std::string& path) {
  const std::vector<std::string> top = topLevelKeys(text);
  if (top.size() != 1 || top.front() != "argine")
    throw InputError(path,
                     "a deck is one YAML map 'argine:' holding all keys; found top-level " +
                         std::string(top.empty() ? "nothing" : "'" + joinWords(top, "', '") + "'"));
  try {
    return Teuchos::getParametersFromYamlString(text);
  } catch (const std::exception& error) {
    throw InputError(path, "malformed YAML: " + parserMessage(error.what()));
  }
}

Teuchos::RCP<Teuchos::ParameterList> readYamlDeck(const std::string& path,
                                                  const Teuchos::Comm<int>& comm) {
  auto parameters = parseYaml(broadcastDeckText(path, comm), path);
  if (parameters->name() != "argine")
    throw InputError(path, "a deck is one YAML map 'argine:' holding all keys; found '" +
                               parameters->name() + ":'");
  return parameters;
}

std::string deckDirectory(const std::string& deck_path) {
  if (deck_path.empty()) return std::filesystem::current_path().string();
  return std::filesystem::absolute(deck_path).lexically_normal().parent_path().string();
}

/// MPI_COMM_WORLD, or a serial communicator when MPI is not running (tools, serial tests).
Teuchos::RCP<const Teuchos::Comm<int>> defaultComm() {
  if (Teuchos::GlobalMPISession::mpiIsInitialized() && !Teuchos::GlobalMPISession::mpiIsFinalized())
    return Teuchos::DefaultComm<int>::getComm();
  return Teuchos::rcp(new Teuchos::SerialComm<int>());
}

/// The list holding the deck keys: `parameters` itself, or its only sublist `argine`.
const Teuchos::ParameterList& deckKeys(const Teuchos::ParameterList& parameters) {
  if (parameters.numParams() == 1 && parameters.isSublist("argine"))
    return parameters.sublist("argine");
  return parameters;
}

}  // namespace

Deck readDeck(const std::string& path) {
  return readDeck(path, *defaultComm());
}

Deck readDeck(const std::string& path, const Teuchos::Comm<int>& comm) {
  return parseDeck(*readYamlDeck(path, comm), path);
}

Deck parseDeck(const Teuchos::ParameterList& parameters, const std::string& deck_path) {
  const Teuchos::ParameterList& keys = deckKeys(parameters);
  const std::string directory = deckDirectory(deck_path);
  validateParameters(keys, deckSchema(), directory);

  const DeckSection top(keys, deckSchema(), "", directory);
  Deck deck;
  if (!deck_path.empty()) deck.path = std::filesystem::absolute(deck_path).lexically_normal();
  deck.title = top.text("Title");
  deck.mesh = parseMesh(top.section("Mesh"));
  for (const auto& material : top.entries("Materials"))
    deck.materials.push_back(parseMaterial(material));
  for (const auto& stage : top.entries("Stages"))
    deck.stages.push_back(parseStage(stage, deck.mesh));
  deck.output = parseOutput(top.section("Output"));
  deck.initialisation = parseInitialisation(top.section("Initialisation"));  // issue P4
  deck.probes = parseProbes(top.section("Probes"));                          // issue P4
  deck.guards = parseGuards(top.section("Guards"));                          // issue P8
  deck.parallel.reproducible_sums =
      top.section("Parallel").boolean("Reproducible Sums");  // issue P7
  deck.factor_of_safety =
      parseFactorOfSafety(top.section("Factor Of Safety"), top.has("Factor Of Safety"));  // P13
  checkDeck(deck);
  return deck;
}

MeshSpec readMeshSpec(const std::string& path) {
  const auto parameters = readYamlDeck(path, *defaultComm());
  ListSchema mesh_only;
  mesh_only.add(*deckSchema().find("Mesh"));
  Teuchos::ParameterList mesh_list;
  if (parameters->isParameter("Mesh")) mesh_list.setEntry("Mesh", parameters->getEntry("Mesh"));
  const std::string directory = deckDirectory(path);
  validateParameters(mesh_list, mesh_only, directory);
  const MeshSpec mesh = parseMesh(DeckSection(mesh_list, mesh_only, "", directory).section("Mesh"));
  checkMeshSpec(mesh);
  return mesh;
}

}  // namespace argine
