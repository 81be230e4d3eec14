#include "argine/output/ResultsWriter.hpp"

#include <cstdio>
#include <filesystem>
#include <system_error>

#include "argine/core/Error.hpp"

namespace argine {

namespace fs = std::filesystem;

namespace {

// Makes the output directory; returns it so it can run in the member initialiser list
// before the files are made.
// Returns `directory` after removing the files <stem>_points.e-sNNNN with NNNN > keep.
const std::string& preparedDirectory(const std::string& directory, const std::string& stem,
                                     int keep = 1) {
  std::error_code error;
  fs::create_directories(directory, error);
  if (error)
    throw InputError(directory, "cannot create the output directory (" + error.message() + ")");
  if (!fs::is_directory(directory))
    throw InputError(directory, "the output directory exists but is not a directory");

  // A longer earlier run with the same stem may have left later files of the points series;
  // ParaView would read them as part of this run.
  const std::string prefix = stem + "_points.e-s";
  for (const auto& entry : fs::directory_iterator(directory, error)) {
    const std::string name = entry.path().filename().string();
    const bool stale = name.size() == prefix.size() + 4 &&
                       name.compare(0, prefix.size(), prefix) == 0 &&
                       name.find_first_not_of("0123456789", prefix.size()) == std::string::npos &&
                       std::stoi(name.substr(prefix.size())) > keep;
    if (stale) {
      std::error_code ignored;
      fs::remove(entry.path(), ignored);
    }
  }
  return directory;
}

std::string gridFilePath(const std::string& directory, const std::string& stem) {
  return (fs::path(directory) / (stem + "_grid.e")).string();
}

}  // namespace

std::string ResultsWriter::pointsSeriesPath(const std::string& directory, const std::string& stem,
                                            int index) {
  std::string name = stem + "_points.e";
  if (index > 1) {
    char suffix[16];
    std::snprintf(suffix, sizeof(suffix), "-s%04d", index);
    name += suffix;
  }
  return (fs::path(directory) / name).string();
}

ResultsWriter::ResultsWriter(const std::string& directory, const std::string& stem,
                             const Mesh& mesh, const std::vector<std::string>& material_names,
                             const std::vector<std::string>& nodal_field_names,
                             const MaterialPoints& points)
    : directory_(preparedDirectory(directory, stem)),
      stem_(stem),
      material_names_(material_names),
      grid_(gridFilePath(directory, stem), mesh, nodal_field_names),
      points_(std::make_unique<PointsFile>(pointsSeriesPath(directory, stem, 1), material_names,
                                           points)) {}

ResultsWriter::ResultsWriter(const std::string& directory, const std::string& stem,
                             const Mesh& mesh, const std::vector<std::string>& material_names,
                             const std::vector<std::string>& nodal_field_names,
                             const ResultsResume& resume)
    : directory_(preparedDirectory(directory, stem, resume.points_file_count)),
      stem_(stem),
      material_names_(material_names),
      grid_(gridFilePath(directory, stem), mesh, nodal_field_names,
            ExodusResume{resume.grid_steps}),
      points_(
          std::make_unique<PointsFile>(pointsSeriesPath(directory, stem, resume.points_file_count),
                                       ExodusResume{resume.points_steps})),
      points_file_count_(resume.points_file_count) {}

ResultsResume ResultsWriter::resumePoint() const {
  return ResultsResume{grid_.steps(), points_file_count_, points_->steps()};
}

void ResultsWriter::write(Real time, const MaterialPoints& points,
                          const std::vector<NodalField>& nodal) {
  if (!points_->holds(points)) {
    auto next = std::make_unique<PointsFile>(
        pointsSeriesPath(directory_, stem_, points_file_count_ + 1), material_names_, points);
    points_ = std::move(next);  // closes the finished file
    ++points_file_count_;
  }
  grid_.write(time, nodal);
  points_->write(time, points);
}

}  // namespace argine
