#include "argine/probes/ProbeWriter.hpp"

#include <cmath>
#include <limits>

#include "argine/core/Error.hpp"
#include "argine/output/CsvWriter.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine {

namespace {

template <class View>
std::vector<Real> column(const View& view, int component) {
  auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
  std::vector<Real> values(host.extent(0));
  for (std::size_t p = 0; p < values.size(); ++p) values[p] = host(p, component);
  return values;
}

template <class View>
std::vector<Real> scalars(const View& view) {
  auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
  return std::vector<Real>(host.data(), host.data() + host.extent(0));
}

const std::vector<std::string> kPointColumns{"time",
                                             "id",
                                             "x",
                                             "y",
                                             "displacement_x",
                                             "displacement_y",
                                             "velocity_x",
                                             "velocity_y",
                                             "liquid_pressure",
                                             "saturation",
                                             "deviatoric_strain",
                                             "stress_xx",
                                             "stress_yy"};

std::vector<Real> pointRow(Real time, const ProbeSnapshot& s, int p) {
  return {time,
          static_cast<Real>(s.id[p]),
          s.x[p],
          s.y[p],
          s.ux[p],
          s.uy[p],
          s.vx[p],
          s.vy[p],
          s.pressure[p],
          s.saturation[p],
          s.deviatoric[p],
          s.sxx[p],
          s.syy[p]};
}

}  // namespace

ProbeSnapshot::ProbeSnapshot(const MaterialPoints& points) {
  id = [&] {
    auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.id);
    return std::vector<int>(host.data(), host.data() + host.extent(0));
  }();
  x = column(points.position, 0);
  y = column(points.position, 1);
  ux = column(points.displacement, 0);
  uy = column(points.displacement, 1);
  vx = column(points.velocity_solid, 0);
  vy = column(points.velocity_solid, 1);
  pressure = scalars(points.pressure_liquid);
  saturation = scalars(points.saturation);
  deviatoric = scalars(points.deviatoric_strain);
  sxx = column(points.stress_effective, XX);
  syy = column(points.stress_effective, YY);
  // Dry points carry no liquid mass (PointInitialisation): the profile skips them.
  const std::vector<Real> liquid_mass = scalars(points.mass_liquid);
  liquid.resize(id.size());
  for (std::size_t p = 0; p < id.size(); ++p) liquid[p] = liquid_mass[p] > 0;
  int largest = -1;
  for (int i : id) largest = std::max(largest, i);
  index_of_id.assign(largest + 1, -1);
  for (std::size_t p = 0; p < id.size(); ++p) index_of_id[id[p]] = static_cast<int>(p);
}

int nearestPoint(const ProbeSnapshot& points, const std::array<Real, 2>& position) {
  int best = -1;
  Real best_d2 = std::numeric_limits<Real>::infinity();
  for (std::size_t p = 0; p < points.x.size(); ++p) {
    const Real dx = points.x[p] - position[0], dy = points.y[p] - position[1];
    const Real d2 = dx * dx + dy * dy;
    if (d2 < best_d2) {
      best_d2 = d2;
      best = static_cast<int>(p);
    }
  }
  return best;
}

SegmentDistance segmentDistance(const std::array<Real, 2>& from, const std::array<Real, 2>& to,
                                Real x, Real y) {
  const Real dx = to[0] - from[0], dy = to[1] - from[1];
  const Real length = std::hypot(dx, dy);
  const Real t =
      std::clamp(((x - from[0]) * dx + (y - from[1]) * dy) / (length * length), Real(0), Real(1));
  SegmentDistance d;
  d.along = t * length;
  d.off = std::hypot(x - (from[0] + t * dx), y - (from[1] + t * dy));
  return d;
}

ProbeWriter::ProbeWriter(const ProbesSpec& spec, const std::string& directory,
                         const std::string& stem, const MaterialPoints& points,
                         const std::vector<std::uintmax_t>& resume_bytes)
    : spec_(spec) {
  const std::size_t files = spec_.points.size() + spec_.sections.size();
  if (!resume_bytes.empty() && resume_bytes.size() != files)
    throw InputError("Probes", "the checkpoint records " + std::to_string(resume_bytes.size()) +
                                   " probe files, the deck makes " + std::to_string(files));
  auto open = [&](const std::string& path, const std::vector<std::string>& columns) {
    const std::size_t k = point_files_.size() + section_files_.size();
    if (resume_bytes.empty()) return std::make_unique<CsvWriter>(path, columns);
    return std::make_unique<CsvWriter>(path, columns, CsvResume{resume_bytes[k]});
  };
  const ProbeSnapshot snapshot(points);
  for (const PointProbeSpec& probe : spec_.points) {
    const int p = nearestPoint(snapshot, probe.position);
    const std::string where = "Probes/Points/" + probe.name + "/Position (m)";
    if (p < 0) throw InputError(where, "there are no material points to follow");
    const Real distance =
        std::hypot(snapshot.x[p] - probe.position[0], snapshot.y[p] - probe.position[1]);
    if (distance > probe.tolerance)
      throw InputError(where, "the nearest material point (id " + std::to_string(snapshot.id[p]) +
                                  " at " + std::to_string(snapshot.x[p]) + ", " +
                                  std::to_string(snapshot.y[p]) + ") lies " +
                                  std::to_string(distance) + " m away, beyond Tolerance (m) " +
                                  std::to_string(probe.tolerance));
    point_ids_.push_back(snapshot.id[p]);
    point_files_.push_back(
        open(directory + "/" + stem + "_probe_" + probe.name + ".csv", kPointColumns));
  }
  for (const SectionProbeSpec& section : spec_.sections) {
    std::vector<std::string> columns;
    if (section.kind == SectionProbeSpec::Kind::Band) {
      columns = kPointColumns;
      columns.insert(columns.begin() + 2, "distance");
    } else {
      columns = {"time", "sample", "distance", "x", "y", "liquid_pressure", "saturation", "points"};
    }
    section_files_.push_back(
        open(directory + "/" + stem + "_section_" + section.name + ".csv", columns));
  }
}

ProbeWriter::~ProbeWriter() = default;

std::vector<std::string> ProbeWriter::paths() const {
  std::vector<std::string> all;
  for (const auto& f : point_files_) all.push_back(f->path());
  for (const auto& f : section_files_) all.push_back(f->path());
  return all;
}

std::vector<std::uintmax_t> ProbeWriter::fileBytes() const {
  std::vector<std::uintmax_t> bytes;
  for (const auto& f : point_files_) bytes.push_back(f->bytes());
  for (const auto& f : section_files_) bytes.push_back(f->bytes());
  return bytes;
}

void ProbeWriter::write(Real time, const MaterialPoints& points) {
  if (spec_.empty()) return;
  const ProbeSnapshot s(points);
  for (std::size_t k = 0; k < point_ids_.size(); ++k) {
    const int id = point_ids_[k];
    const int p = id < static_cast<int>(s.index_of_id.size()) ? s.index_of_id[id] : -1;
    if (p < 0)
      throw RunError("probe '" + spec_.points[k].name + "': point " + std::to_string(id) +
                     " no longer exists");
    point_files_[k]->writeRow(pointRow(time, s, p));
  }
  for (std::size_t k = 0; k < spec_.sections.size(); ++k) {
    const SectionProbeSpec& section = spec_.sections[k];
    const Real half = 0.5 * section.band_width;
    if (section.kind == SectionProbeSpec::Kind::Band) {
      for (std::size_t p = 0; p < s.x.size(); ++p) {
        const SegmentDistance d = segmentDistance(section.from, section.to, s.x[p], s.y[p]);
        if (d.off > half) continue;
        std::vector<Real> row = pointRow(time, s, static_cast<int>(p));
        row.insert(row.begin() + 2, d.along);
        section_files_[k]->writeRow(row);
      }
      continue;
    }
    const Real length =
        std::hypot(section.to[0] - section.from[0], section.to[1] - section.from[1]);
    for (int i = 0; i < section.samples; ++i) {
      const Real t = static_cast<Real>(i) / (section.samples - 1);
      const Real x = section.from[0] + t * (section.to[0] - section.from[0]);
      const Real y = section.from[1] + t * (section.to[1] - section.from[1]);
      // Inverse-distance weights (a point on the sample gets all the weight).
      Real weight = 0, pressure = 0, saturation = 0;
      int count = 0;
      bool exact = false;
      for (std::size_t p = 0; p < s.x.size() && !exact; ++p) {
        if (!s.liquid[p]) continue;
        // The box test first: hypot for every point and sample was 12 % of the 72 h flood's
        // CPU time (its 11 sections at 72 outputs, 33,702 points). Same distances as before.
        const Real dx = s.x[p] - x, dy = s.y[p] - y;
        if (std::fabs(dx) > half || std::fabs(dy) > half) continue;
        const Real d = std::hypot(dx, dy);
        if (d > half) continue;
        ++count;
        if (d < 1e-12 * (1 + length)) {
          weight = 1;
          pressure = s.pressure[p];
          saturation = s.saturation[p];
          exact = true;
          break;
        }
        weight += 1 / d;
        pressure += s.pressure[p] / d;
        saturation += s.saturation[p] / d;
      }
      const Real nan = std::numeric_limits<Real>::quiet_NaN();
      const bool any = count > 0;
      section_files_[k]->writeRow({time, static_cast<Real>(i), t * length, x, y,
                                   any ? pressure / weight : nan, any ? saturation / weight : nan,
                                   static_cast<Real>(count)});
    }
  }
}

}  // namespace argine
