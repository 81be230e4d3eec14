#pragma once
/// @file ExodusMesh.hpp
/// Reading and writing the background mesh as Exodus II (2D, TRI3 or QUAD4), with only the
/// generic exodus calls (ex_put_block, ex_put_conn, ex_put_set, ex_put_names, ...), which
/// exist both in Debian's 6.02 and in current SEACAS.
///
/// Numbering in the file: elements are written block by block (block order of
/// `Mesh::blocks`, and within a block the order of `ElementBlock::elements`); nodes, element
/// numbers in side sets and side numbers are 1-based in the file and 0-based in `Mesh`.

#include <string>
#include <vector>

#include "argine/mesh/Mesh.hpp"

namespace argine {

/// Writes the mesh definition (ex_put_init, coordinates named x and y, element blocks with
/// names and connectivity, node sets and side sets with names) to an Exodus file the caller
/// created with ex_create and still owns (the caller closes it). Throws RunError when an
/// exodus call fails, std::invalid_argument when the mesh is inconsistent.
void putMeshGeometry(int exoid, const Mesh& mesh, const std::string& title);

/// File element number (0-based) -> mesh element index: the order in which putMeshGeometry
/// writes the elements. Writers of element variables use it to order their values.
std::vector<int> exodusElementOrder(const Mesh& mesh);

/// Writes the mesh to `path` (overwriting it). The file is written to `path + ".tmp"` and
/// renamed, so a crash never leaves half a file. Throws InputError when the file cannot be
/// created, RunError when writing fails.
void writeExodusMesh(const std::string& path, const Mesh& mesh,
                     const std::string& title = "argine mesh");

/// Reads a 2D Exodus mesh of TRI/TRI3/TRIANGLE or QUAD/QUAD4 elements (one type for all
/// blocks). Unnamed blocks and sets are named block_<id>, nodelist_<id>, surface_<id>.
/// Clockwise elements are reordered counter-clockwise (their side-set sides renumbered).
/// Throws InputError naming the file for a missing or unreadable file, a 3D mesh, mixed or
/// unsupported element types, node or element numbers out of range, degenerate (zero area)
/// or non-convex elements.
Mesh readExodusMesh(const std::string& path);

}  // namespace argine
