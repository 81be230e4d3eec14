#pragma once
/// @file GmshMesh.hpp
/// Background meshes from gmsh (deck `Mesh/Gmsh File`): an MSH 4.1 file (ASCII or binary) of
/// 3-node triangles or 4-node quadrangles in the xy plane, or a .geo file meshed on the fly by
/// Debian's gmsh program when it is installed. Physical groups name everything:
/// - each physical surface becomes an element block (a material's `Block`), named as in gmsh;
/// - each physical curve becomes a side set and a node set of its name (boundary conditions);
///   a curve inside the mesh gets, per segment, the side of the element on the segment's left
///   (gmsh orients a curve's segments along the curve);
/// - each physical point becomes a node set of its name.
/// Every group must have a name, every surface element must lie in exactly one physical
/// surface, and one element type serves the whole mesh. Nodes are numbered in the order of
/// their gmsh tags (only nodes of surface elements are kept), elements block by block in the
/// order of the physical surfaces' tags.

#include <string>

#include "argine/mesh/Mesh.hpp"
#include "argine/meshio/GmshFile.hpp"

namespace argine {

/// Reads a gmsh MSH 4.1 mesh. Throws InputError naming `path` for anything argine cannot use:
/// a 3D or non-planar mesh, second-order or mixed element types, unnamed or missing physical
/// groups, a surface element in no or in two physical surfaces, a physical curve whose
/// segments are not element sides, and everything readGmshFile refuses.
Mesh readGmshMesh(const std::string& path);

/// The Mesh of an MSH file's contents (`path` names them in errors).
Mesh gmshMesh(const std::string& path, const GmshFile& file);

/// Meshes a .geo file with the gmsh program (`gmsh -2 -format msh41`, the program on PATH or
/// the one the environment variable ARGINE_GMSH names) into a temporary file and reads it.
/// Throws InputError naming `geo_path` when gmsh is not installed (saying how to install it or
/// to give an .msh file instead) or when gmsh fails (with the end of its messages).
Mesh meshGeoFile(const std::string& geo_path);

/// readGmshMesh for .msh files, meshGeoFile for .geo files (by the extension).
Mesh loadGmshMesh(const std::string& path);

}  // namespace argine
