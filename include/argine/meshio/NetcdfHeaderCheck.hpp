#pragma once
/// @file NetcdfHeaderCheck.hpp
/// A sanity check of a netCDF classic header (CDF-1, CDF-2, CDF-5: what Exodus II files
/// are) before the netCDF library opens the file. Found by fuzzing (issue P8): a damaged
/// header whose list counts or lengths exceed the file makes libnetcdf's nc_open allocate
/// and clear gigabytes (a 963-byte file took > 10 s and 1.7 GB). Every count and length of
/// the header must fit in the bytes that follow it. HDF5-based (netCDF-4) files are left to
/// the library.

#include <string>

namespace argine {

/// Throws InputError(path, ...) saying which part of the header is impossible. Returns
/// without checking when the file is not a netCDF classic file (the open then fails or
/// reads it as what it is).
void checkNetcdfClassicHeader(const std::string& path);

}  // namespace argine
