// argine: the command-line entry. Parses the command, turns every input problem into one
// clear message with exit code 2 before anything runs, and every run fault into exit code 3.
#include <mpi.h>

#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <Kokkos_Core.hpp>

#include "argine/core/Error.hpp"
#include "argine/core/Version.hpp"
#include "argine/input/DeckReader.hpp"
#include "argine/input/DeckSchema.hpp"
#include "argine/mesh/MeshGeometry.hpp"
#include "argine/meshio/ExodusMesh.hpp"
#include "argine/meshio/GmshMesh.hpp"
#include "argine/meshio/MeshGenerators.hpp"
#include "argine/simulation/Setup.hpp"
#include "argine/simulation/Simulation.hpp"

namespace {

constexpr const char* kUsage = R"(usage: argine <command> [options]

commands:
  run DECK.yaml [--output DIR] [--quiet] [--restart CHECKPOINT]
                                           run every stage of a deck; results go to DIR
                                           (default: the deck's Output/Directory);
                                           --restart continues from a checkpoint written
                                           by a run of the same deck (Output/Checkpoint)
  check DECK.yaml                          validate the deck and its mesh, run nothing
  mesh DECK.yaml -o MESH.exo               write the mesh of the deck's Mesh section as Exodus
  mesh MESH.msh|MESH.geo -o MESH.exo       convert a gmsh mesh (or mesh a .geo) to Exodus
  schema                                   print the deck reference (Markdown)
  --help                                   this text
  --version                                the version

exit codes: 0 success, 1 usage error, 2 input error (the message names the key or file),
            3 run error (instability or fault; the last good output is kept)
)";

/// Arguments after the command word, with --flag VALUE options pulled out.
struct Arguments {
  std::vector<std::string> positional;
  std::string output;
  std::string mesh_output;
  std::string restart;
  bool quiet = false;
};

Arguments parseArguments(int argc, char** argv, int first) {
  Arguments arguments;
  for (int i = first; i < argc; ++i) {
    const std::string word = argv[i];
    const auto value = [&](const char* flag) {
      if (i + 1 >= argc) throw std::invalid_argument(std::string(flag) + " needs a value");
      return std::string(argv[++i]);
    };
    if (word == "--output") {
      arguments.output = value("--output");
    } else if (word == "-o") {
      arguments.mesh_output = value("-o");
    } else if (word == "--restart") {
      arguments.restart = value("--restart");
    } else if (word == "--quiet") {
      arguments.quiet = true;
    } else if (!word.empty() && word[0] == '-') {
      throw std::invalid_argument("unknown option " + word);
    } else {
      arguments.positional.push_back(word);
    }
  }
  return arguments;
}

const std::string& deckArgument(const Arguments& arguments, const char* command) {
  if (arguments.positional.size() != 1)
    throw std::invalid_argument(std::string(command) + " takes exactly one deck file");
  return arguments.positional.front();
}

int runCommand(const std::string& command, const Arguments& arguments) {
  if (command == "schema") {
    std::cout << argine::deckReferenceMarkdown();
    return argine::kExitOk;
  }
  if (command == "check") {
    const argine::Deck deck = argine::readDeck(deckArgument(arguments, "check"));
    argine::checkDeckSupported(deck);
    const argine::Mesh mesh = argine::loadMesh(deck);
    // (P8) Seeding checks Points Per Element against the element type: without it, check
    // called valid a deck that run then rejected.
    (void)argine::seedPoints(deck, mesh);
    std::printf("%s: valid (%zu materials, %zu stages; mesh %d nodes, %d %s elements)\n",
                deck.path.c_str(), deck.materials.size(), deck.stages.size(), mesh.numNodes(),
                mesh.numElements(), argine::exodusName(mesh.type));
    return argine::kExitOk;
  }
  if (command == "mesh") {
    if (arguments.mesh_output.empty()) throw std::invalid_argument("mesh needs -o MESH.exo");
    // A gmsh file is converted as it is; a deck's mesh (any source) is written as the run
    // would read it, checked as `check` would.
    const std::string input = deckArgument(arguments, "mesh");
    const std::string extension = std::filesystem::path(input).extension().string();
    const bool gmsh = extension == ".msh" || extension == ".geo";
    argine::Mesh mesh;
    std::string source = input;
    if (gmsh) {
      mesh = argine::loadGmshMesh(input);
    } else {
      const argine::MeshSpec spec = argine::readMeshSpec(input);
      mesh = argine::readDeckMesh(spec);
      source = argine::meshSource(spec);
    }
    argine::checkMeshQuality(mesh, source);
    argine::writeExodusMesh(arguments.mesh_output, mesh);
    std::printf("wrote %s (%d nodes, %d %s elements)\n", arguments.mesh_output.c_str(),
                mesh.numNodes(), mesh.numElements(), argine::exodusName(mesh.type));
    return argine::kExitOk;
  }
  if (command == "run") {
    const argine::Deck deck = argine::readDeck(deckArgument(arguments, "run"));
    argine::RunOptions options;
    options.output_directory = arguments.output.empty() ? deck.output.directory : arguments.output;
    options.quiet = arguments.quiet;
    options.restart = arguments.restart;
    argine::Simulation simulation(deck, options);
    simulation.run();
    return argine::kExitOk;
  }
  throw std::invalid_argument("unknown command '" + command + "'");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    std::fputs(kUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 1 : 0;
  }
  if (!std::strcmp(argv[1], "--version")) {
    std::printf("argine %s\n", argine::kVersion);
    return 0;
  }
  MPI_Init(&argc, &argv);
  int exit_code = argine::kExitOk;
  {
    Kokkos::ScopeGuard kokkos(argc, argv);
    try {
      exit_code = runCommand(argv[1], parseArguments(argc, argv, 2));
    } catch (const argine::InputError& error) {
      std::fprintf(stderr, "argine: input error: %s\n", error.what());
      exit_code = argine::kExitInputError;
    } catch (const argine::RunError& error) {
      std::fprintf(stderr, "argine: run stopped: %s\n", error.what());
      exit_code = argine::kExitRunError;
    } catch (const std::invalid_argument& error) {
      std::fprintf(stderr, "argine: %s\n%s", error.what(), kUsage);
      exit_code = 1;
    } catch (const std::exception& error) {
      std::fprintf(stderr, "argine: internal error: %s\n", error.what());
      exit_code = argine::kExitRunError;
    }
    // On several ranks an error may be raised on one rank only while the others wait in a
    // collective call: end them all at once, with the exit code (doc/parallel.md).
    int ranks = 1;
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    if (exit_code != argine::kExitOk && ranks > 1) {
      std::fflush(stdout);
      std::fflush(stderr);
      MPI_Abort(MPI_COMM_WORLD, exit_code);
    }
  }
  MPI_Finalize();
  return exit_code;
}
