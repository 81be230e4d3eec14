#include "argine/output/ExodusFile.hpp"

#include <exodusII.h>

#include <filesystem>
#include <system_error>

#include "argine/core/Error.hpp"

namespace argine {

namespace {
// Longest block/variable name kept in our files (the format default is 32 characters;
// material names from decks may be longer).
constexpr int kMaxNameLength = 64;
}  // namespace

void checkExodus(int status, const std::string& path, const char* call) {
  if (status >= 0) return;
  const char* message = nullptr;
  const char* function = nullptr;
  int code = 0;
  ex_get_err(&message, &function, &code);
  std::string detail = "exodus error " + std::to_string(status);
  if (message != nullptr && *message != '\0') detail += ": " + std::string(message);
  throw RunError(path + ": " + call + " failed (" + detail + ")");
}

void defineNodalVariables(int exoid, const std::string& path,
                          const std::vector<std::string>& names) {
  if (names.empty()) return;
  checkExodus(ex_put_variable_param(exoid, EX_NODAL, static_cast<int>(names.size())), path,
              "ex_put_variable_param");
  std::vector<char*> pointers;
  for (const auto& name : names) pointers.push_back(const_cast<char*>(name.c_str()));
  checkExodus(
      ex_put_variable_names(exoid, EX_NODAL, static_cast<int>(names.size()), pointers.data()), path,
      "ex_put_variable_names");
}

ExodusFile::ExodusFile(const std::string& path, const std::function<void(int exoid)>& define)
    : path_(path) {
  const std::string temporary = path + ".part";
  int cpu_word_size = sizeof(Real);
  int io_word_size = sizeof(Real);
  const int exoid = ex_create(temporary.c_str(), EX_CLOBBER, &cpu_word_size, &io_word_size);
  checkExodus(exoid, temporary, "ex_create");
  try {
    checkExodus(ex_set_max_name_length(exoid, kMaxNameLength), temporary, "ex_set_max_name_length");
    define(exoid);
  } catch (...) {
    ex_close(exoid);
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
  checkExodus(ex_close(exoid), temporary, "ex_close");

  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error)
    throw RunError(temporary + ": cannot rename to " + path + " (" + error.message() + ")");

  int open_cpu_word_size = sizeof(Real);
  int open_io_word_size = 0;  // as stored in the file
  float version = 0.0f;
  exoid_ = ex_open(path.c_str(), EX_WRITE, &open_cpu_word_size, &open_io_word_size, &version);
  checkExodus(exoid_, path, "ex_open");
}

ExodusFile::ExodusFile(const std::string& path, ExodusResume resume) : path_(path) {
  int cpu_word_size = sizeof(Real);
  int io_word_size = 0;
  float version = 0.0f;
  exoid_ = ex_open(path.c_str(), EX_WRITE, &cpu_word_size, &io_word_size, &version);
  if (exoid_ < 0) throw InputError(path, "cannot reopen the results file of the checkpointed run");
  const int stored = static_cast<int>(ex_inquire_int(exoid_, EX_INQ_TIME));
  if (stored < resume.steps) {
    ex_close(exoid_);
    exoid_ = -1;
    throw InputError(path, "holds " + std::to_string(stored) + " time steps, fewer than the " +
                               std::to_string(resume.steps) +
                               " the checkpoint recorded: not the checkpointed run's file");
  }
  steps_ = resume.steps;
}

ExodusFile::~ExodusFile() {
  if (exoid_ >= 0) ex_close(exoid_);
}

int ExodusFile::beginStep(Real time) {
  const int step = steps_ + 1;
  checkExodus(ex_put_time(exoid_, step, &time), path_, "ex_put_time");
  steps_ = step;
  return step;
}

void ExodusFile::putNodal(int step, int variable, const std::vector<Real>& values) {
  checkExodus(ex_put_var(exoid_, step, EX_NODAL, variable, 1, static_cast<int64_t>(values.size()),
                         values.data()),
              path_, "ex_put_var");
}

void ExodusFile::finishStep() {
  checkExodus(ex_update(exoid_), path_, "ex_update");
}

}  // namespace argine
