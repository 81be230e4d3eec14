#pragma once
/// @file ExodusLayoutCheck.hpp
/// Checks that the netCDF variables and attributes the Exodus II library reads have the
/// shapes it assumes, before the library reads them. Found by fuzzing (issue P8): the
/// library sizes its buffers (and argine sizes the caller's) from the dimensions, e.g.
/// num_el_blk for the block ids, then reads the whole variable eb_prop1. A file whose
/// eb_prop1 has other dimensions made libexoIIv2c write past the end of a heap buffer,
/// which corrupted the heap (not seen by the sanitizers: libnetcdf is not instrumented).

#include <string>

namespace argine {

/// Throws InputError(path, ...) naming the variable or attribute whose shape differs from
/// the Exodus II layout: the coordinates, block/set ids, status and names, each block's
/// connectivity and element type, each set's entries, and the global attributes the library
/// reads into single numbers. Missing variables are left to the library (it reports them).
void checkExodusLayout(const std::string& path);

}  // namespace argine
