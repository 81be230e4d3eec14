#include "argine/meshio/ExodusLayoutCheck.hpp"

#include <netcdf.h>

#include <string>
#include <vector>

#include "argine/core/Error.hpp"

namespace argine {

namespace {

/// Names as the Exodus II format defines them (exodusII_int.h); i counts from 1.
std::string numbered(const char* prefix, int i) {
  return prefix + std::to_string(i);
}

/// One open netCDF file; every finding becomes an InputError naming the file.
class LayoutCheck {
 public:
  LayoutCheck(const std::string& path, int ncid) : path_(path), ncid_(ncid) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(path_, what + " (not the Exodus II layout; damaged file?)");
  }

  /// Id of a dimension, or -1 when the file has none of that name.
  int dimension(const std::string& name) const {
    int id = -1;
    return nc_inq_dimid(ncid_, name.c_str(), &id) == NC_NOERR ? id : -1;
  }

  /// Length of a dimension, 0 when absent.
  std::size_t length(const std::string& name) const {
    const int id = dimension(name);
    std::size_t n = 0;
    if (id >= 0 && nc_inq_dimlen(ncid_, id, &n) != NC_NOERR) fail("dimension " + name);
    return id >= 0 ? n : 0;
  }

  /// When `variable` exists, its dimensions must be exactly `expected` (by name), which the
  /// library assumes when it reads the whole variable into a buffer of their size.
  void shape(const std::string& variable, const std::vector<std::string>& expected) const {
    int varid = -1;
    if (nc_inq_varid(ncid_, variable.c_str(), &varid) != NC_NOERR) return;
    int ndims = 0;
    if (nc_inq_varndims(ncid_, varid, &ndims) != NC_NOERR || ndims < 0 || ndims > NC_MAX_VAR_DIMS)
      fail("variable " + variable + " has an unreadable number of dimensions");
    std::vector<int> dims(static_cast<std::size_t>(ndims));
    if (ndims > 0 && nc_inq_vardimid(ncid_, varid, dims.data()) != NC_NOERR)
      fail("variable " + variable + " has unreadable dimensions");
    bool same = dims.size() == expected.size();
    for (std::size_t k = 0; same && k < dims.size(); ++k) same = dims[k] == dimension(expected[k]);
    if (!same) {
      std::string wanted;
      for (const auto& name : expected) wanted += (wanted.empty() ? "" : ", ") + name;
      fail("variable " + variable + " has " + std::to_string(ndims) +
           " dimensions other than the expected (" + wanted + ")");
    }
  }

  /// A global attribute the library reads into one number must hold one value.
  void scalarAttribute(const char* name) const {
    std::size_t n = 0;
    if (nc_inq_attlen(ncid_, NC_GLOBAL, name, &n) != NC_NOERR) return;
    if (n != 1)
      fail("global attribute '" + std::string(name) + "' has " + std::to_string(n) +
           " values; expected 1");
  }

  /// The element type attribute of a block's connectivity: text, at most 32 characters.
  void elementType(const std::string& variable) const {
    int varid = -1;
    if (nc_inq_varid(ncid_, variable.c_str(), &varid) != NC_NOERR) return;
    nc_type type = NC_NAT;
    std::size_t n = 0;
    if (nc_inq_att(ncid_, varid, "elem_type", &type, &n) != NC_NOERR) return;
    if (type != NC_CHAR || n < 1 || n > 33)
      fail("attribute elem_type of " + variable + " must be text of 1 to 32 characters");
  }

 private:
  std::string path_;
  int ncid_;
};

/// Closes the netCDF file on every way out.
struct NetcdfFile {
  int id;
  ~NetcdfFile() { nc_close(id); }
};

}  // namespace

void checkExodusLayout(const std::string& path) {
  int ncid = -1;
  if (nc_open(path.c_str(), NC_NOWRITE, &ncid) != NC_NOERR)
    throw InputError(path, "cannot open as a netCDF file (an Exodus II mesh is one)");
  NetcdfFile file{ncid};
  const LayoutCheck check(path, ncid);
  int variables = 0;
  if (nc_inq_nvars(ncid, &variables) != NC_NOERR) check.fail("unreadable list of variables");

  // ex_open and ex_inquire read these into single numbers.
  for (const char* name :
       {"api_version", "api version", "version", "floating_point_word_size",
        "floating point word size", "file_size", "int64_status", "maximum_name_length"})
    check.scalarAttribute(name);

  check.shape("coordx", {"num_nodes"});
  check.shape("coordy", {"num_nodes"});
  check.shape("coord", {"num_dim", "num_nodes"});

  // Ids, status and names of blocks and sets: ex_id_lkup allocates the count from the
  // dimension and reads the whole variable.
  struct Kind {
    const char* count;
    const char* ids;
    const char* status;
    const char* names;
  };
  for (const Kind& kind : {Kind{"num_el_blk", "eb_prop1", "eb_status", "eb_names"},
                           Kind{"num_node_sets", "ns_prop1", "ns_status", "ns_names"},
                           Kind{"num_side_sets", "ss_prop1", "ss_status", "ss_names"}}) {
    check.shape(kind.ids, {kind.count});
    check.shape(kind.status, {kind.count});
    check.shape(kind.names, {kind.count, "len_name"});
  }

  // A count beyond the number of variables is impossible (each block or set has its own
  // variables); checked first so that a damaged count does not make these loops long.
  const auto count = [&](const char* name) {
    const std::size_t n = check.length(name);
    if (n > static_cast<std::size_t>(variables))
      check.fail("dimension " + std::string(name) + " says " + std::to_string(n) +
                 ", but the file has only " + std::to_string(variables) + " variables");
    return static_cast<int>(n);
  };
  const int blocks = count("num_el_blk");
  for (int i = 1; i <= blocks; ++i) {
    const std::string connect = numbered("connect", i);
    check.shape(connect, {numbered("num_el_in_blk", i), numbered("num_nod_per_el", i)});
    check.elementType(connect);
  }
  const int node_sets = count("num_node_sets");
  for (int i = 1; i <= node_sets; ++i)
    check.shape(numbered("node_ns", i), {numbered("num_nod_ns", i)});
  const int side_sets = count("num_side_sets");
  for (int i = 1; i <= side_sets; ++i) {
    check.shape(numbered("elem_ss", i), {numbered("num_side_ss", i)});
    check.shape(numbered("side_ss", i), {numbered("num_side_ss", i)});
  }
}

}  // namespace argine
