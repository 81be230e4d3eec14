#pragma once
/// @file ExodusFile.hpp
/// An Exodus II results file open for appending time steps, with the few steps every
/// results file shares: created atomically, one time value per step, flushed after each
/// step so a killed run leaves a file readable up to its last complete step.

#include <functional>
#include <string>
#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

/// Throws RunError "<path>: <call> failed (exodus error N: message)" when an exodus call
/// returned an error (status < 0); warnings (status > 0) pass.
void checkExodus(int status, const std::string& path, const char* call);

/// Declares the nodal result variables of a file being defined (ex_put_variable_param +
/// ex_put_variable_names); their 1-based exodus index is their position in `names` + 1.
void defineNodalVariables(int exoid, const std::string& path,
                          const std::vector<std::string>& names);

/// Where a restarted run continues a results file: after its first `steps` time steps (what
/// a checkpoint recorded); the next step written is steps + 1, overwriting any step a killed
/// run wrote after the checkpoint (the restarted run writes the same steps again).
struct ExodusResume {
  int steps = 0;
};

/// One open Exodus II results file; closed by the destructor.
class ExodusFile {
 public:
  /// Makes `path` without ever showing a half-initialised file under that name: `define`
  /// writes the fixed part (init, coordinates, blocks, variable names) into `path`.part,
  /// which is then closed, renamed to `path` and reopened for appending time steps.
  ExodusFile(const std::string& path, const std::function<void(int exoid)>& define);
  /// Reopens `path`, written by the checkpointed run, for appending after `resume.steps`
  /// steps. Throws InputError naming the file when it cannot be opened or holds fewer steps.
  ExodusFile(const std::string& path, ExodusResume resume);
  ~ExodusFile();
  ExodusFile(const ExodusFile&) = delete;
  ExodusFile& operator=(const ExodusFile&) = delete;

  const std::string& path() const { return path_; }
  /// Number of time steps written so far.
  int steps() const { return steps_; }
  /// The exodus id of the open file (for reading back its fixed part).
  int id() const { return exoid_; }

  /// Starts time step steps()+1 at `time` (ex_put_time); returns its 1-based number.
  int beginStep(Real time);
  /// Writes nodal variable `variable` (1-based) of time step `step`, one value per node.
  void putNodal(int step, int variable, const std::vector<Real>& values);
  /// Flushes the step to disk (ex_update) so it is readable even if the run is killed.
  void finishStep();

 private:
  std::string path_;
  int exoid_ = -1;
  int steps_ = 0;
};

}  // namespace argine
