#include "argine/simulation/FactorOfSafetyMonitor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "argine/simulation/SlipSurfaceStrength.hpp"
#include "argine/slopestability/Spencer.hpp"

namespace argine {

namespace {

constexpr Real kDegreesPerRadian = 180.0 / 3.14159265358979323846;

const std::vector<std::string> kHistoryColumns{
    "time",    "factor_of_safety", "bishop",    "ordinary_method", "centre_x", "centre_y", "radius",
    "entry_x", "exit_x",           "max_depth", "sliding_weight",  "circles",  "rejected"};

const std::vector<std::string> kSliceColumns{"time",
                                             "slice",
                                             "x_mid",
                                             "width",
                                             "base_y",
                                             "top_y",
                                             "base_angle_deg",
                                             "weight",
                                             "pore_pressure",
                                             "material",
                                             "cohesion",
                                             "friction_angle_deg",
                                             "suction_strength"};

std::unique_ptr<CsvWriter> openCsv(const std::string& path, const std::vector<std::string>& columns,
                                   const std::vector<std::uint64_t>& resume, std::size_t k) {
  if (k < resume.size()) return std::make_unique<CsvWriter>(path, columns, CsvResume{resume[k]});
  return std::make_unique<CsvWriter>(path, columns);
}

}  // namespace

SectionPoints sectionPointsOf(const MaterialPoints& points, Real gravity) {
  const auto host = [](const auto& view) {
    return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
  };
  const auto element = host(points.element);
  const auto position = host(points.position);
  const auto volume = host(points.volume);
  const auto mass_solid = host(points.mass_solid);
  const auto mass_liquid = host(points.mass_liquid);
  const auto pressure = host(points.pressure_liquid);
  const auto saturation = host(points.saturation);
  const auto material = host(points.material);
  SectionPoints out;
  for (int p = 0; p < points.count; ++p) {
    if (element(p) < 0) continue;
    out.x.push_back(position(p, 0));
    out.y.push_back(position(p, 1));
    out.volume.push_back(volume(p));
    out.weight.push_back((mass_solid(p) + mass_liquid(p)) * gravity);
    out.pore_pressure.push_back(pressure(p));
    out.saturation.push_back(saturation(p));
    out.material.push_back(material(p));
  }
  return out;
}

SlopeSection sectionForFactorOfSafety(const FactorOfSafetySpec& spec, const SectionPoints& points,
                                      const std::vector<MaterialSpec>& materials, Real gravity) {
  const Real water_unit_weight = materials.at(0).liquid.density * gravity;
  const SuctionStrength mode = spec.suction;
  const Real phi_b = spec.suction_friction_angle;
  MaterialStrength strength = [materials, mode, phi_b](int m, Real p_L, Real S_L) {
    return slipSurfaceStrength(materials.at(static_cast<std::size_t>(m)), mode, phi_b, p_L, S_L);
  };
  if (spec.ground_surface.empty())
    return sectionFromPoints(points, strength, spec.cell_size, nullptr, water_unit_weight);
  const Polyline ground(spec.ground_surface, "Factor Of Safety/Ground Surface (m)");
  return sectionFromPoints(points, strength, spec.cell_size, &ground, water_unit_weight);
}

CircleSearchGrid searchGridFor(const FactorOfSafetySpec& spec, const SlopeSection& section) {
  const Polyline& g = section.ground;
  const Real top = *std::max_element(g.y.begin(), g.y.end());
  const Real height = top - section.floor;
  CircleSearchGrid grid;
  // Unset centre abscissae: over the ground, or over the part of it the mass may occupy.
  std::array<Real, 2> ground_x{g.xFirst(), g.xLast()};
  if (spec.mass_x_range) {
    ground_x[0] = std::max(ground_x[0], (*spec.mass_x_range)[0]);
    ground_x[1] = std::min(ground_x[1], (*spec.mass_x_range)[1]);
  }
  const std::array<Real, 2> cx = spec.centre_x.value_or(ground_x);
  const std::array<Real, 2> cy = spec.centre_y.value_or(std::array<Real, 2>{top, top + 2 * height});
  const std::array<Real, 2> ty = spec.tangent_y.value_or(std::array<Real, 2>{section.floor, top});
  grid.centre_x_min = cx[0];
  grid.centre_x_max = cx[1];
  grid.centre_y_min = cy[0];
  grid.centre_y_max = cy[1];
  grid.tangent_y_min = ty[0];
  grid.tangent_y_max = ty[1];
  grid.centre_x_count = grid.centre_y_count = grid.tangent_count = spec.grid_count;
  grid.refinements = spec.refinements;
  grid.starts = spec.search_starts;
  grid.slice_count = spec.slices;
  grid.min_depth = spec.min_depth;
  if (spec.mass_x_range) {
    grid.mass_x_min = (*spec.mass_x_range)[0];
    grid.mass_x_max = (*spec.mass_x_range)[1];
  }
  return grid;
}

CriticalCircle criticalCircleOf(const FactorOfSafetySpec& spec, const MaterialPoints& points,
                                const std::vector<MaterialSpec>& materials, Real gravity) {
  const SectionPoints section_points = sectionPointsOf(points, gravity);
  if (section_points.size() == 0 || !(gravity > 0)) return CriticalCircle{};
  const SlopeSection section = sectionForFactorOfSafety(spec, section_points, materials, gravity);
  const CircleSearchGrid grid = searchGridFor(spec, section);
  if (!spec.spencer) return searchCriticalCircle(section, grid);
  return searchCriticalCircleBy(section, grid, [](const SlipMass& mass, const SlipCircle& c) {
    SpencerOptions about_centre;
    about_centre.use_moment_point = true;
    about_centre.moment_x = c.centre_x;
    about_centre.moment_y = c.centre_y;
    return spencer(mass.slices, about_centre, mass.end_forces).factor;
  });
}

FactorOfSafetyMonitor::FactorOfSafetyMonitor(const FactorOfSafetySpec& spec,
                                             const std::string& directory, const std::string& name,
                                             const std::vector<std::uint64_t>& resume_bytes)
    : spec_(spec) {
  history_ =
      openCsv(directory + "/" + name + "_factor_of_safety.csv", kHistoryColumns, resume_bytes, 0);
  if (spec.slice_table)
    slices_ =
        openCsv(directory + "/" + name + "_critical_slices.csv", kSliceColumns, resume_bytes, 1);
}

Real FactorOfSafetyMonitor::evaluate(Real time, const MaterialPoints& points,
                                     const std::vector<MaterialSpec>& materials, Real gravity) {
  last_ = criticalCircleOf(spec_, points, materials, gravity);
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  if (!last_.found) {
    history_->writeRow({time, nan, nan, nan, nan, nan, nan, nan, nan, nan, nan,
                        static_cast<Real>(last_.evaluated), static_cast<Real>(last_.rejected)});
    return nan;
  }
  Real depth = 0, weight = 0;
  for (const Slice& s : last_.mass.slices) {
    depth = std::max(depth, s.top_y - s.base_y);
    weight += s.weight;
  }
  const SlipCircle& c = last_.circle;
  history_->writeRow({time, last_.objective.value, last_.bishop.value, last_.ordinary.value,
                      c.centre_x, c.centre_y, c.radius, last_.mass.entry_x, last_.mass.exit_x,
                      depth, weight, static_cast<Real>(last_.evaluated),
                      static_cast<Real>(last_.rejected)});
  if (slices_) {
    int k = 0;
    for (const Slice& s : last_.mass.slices)
      slices_->writeRow({time, static_cast<Real>(k++), s.x_mid, s.width, s.base_y, s.top_y,
                         s.base_angle * kDegreesPerRadian, s.weight, s.pore_pressure,
                         static_cast<Real>(s.layer), s.cohesion,
                         s.friction_angle * kDegreesPerRadian, s.suction_strength});
  }
  return last_.objective.value;
}

std::vector<std::uint64_t> FactorOfSafetyMonitor::fileBytes() const {
  std::vector<std::uint64_t> bytes{history_->bytes()};
  if (slices_) bytes.push_back(slices_->bytes());
  return bytes;
}

}  // namespace argine
