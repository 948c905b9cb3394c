#include "sph/mps/model.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "sph/engine/fill.hpp"

namespace sph::mps {

Material Material::water(double mu) {
  Material m;
  m.type = Type::water;
  m.viscosity = mu;
  return m;
}

Material Material::granular_material(const HerschelBulkley& hb) {
  Material m;
  m.type = Type::granular;
  m.granular = hb;
  return m;
}

void Material::validate() const {
  if (type == Type::granular) granular.validate();
  if (!(density >= 0) || !std::isfinite(density))
    throw std::invalid_argument("mps material: density = " + std::to_string(density) +
                                " kg/m^3 is not allowed; allowed: > 0, or 0 for the settings' rest_density");
  if (type == Type::granular && !(grain_volume_fraction > 0 && grain_volume_fraction <= 1))
    throw std::invalid_argument("mps material: grain_volume_fraction = " + std::to_string(grain_volume_fraction) +
                                " is not allowed; allowed: (0, 1]");
  if (type == Type::granular) return;
  if (!(viscosity >= 0) || !std::isfinite(viscosity))
    throw std::invalid_argument("mps material: viscosity = " + std::to_string(viscosity) +
                                " Pa s is not allowed; allowed: a finite value >= 0");
}

Model::Model(const Settings& s, std::vector<Material> m)
    : settings(s), materials(std::move(m)), fields(Fields::register_in(particles)) {
  settings.validate();
  if (materials.empty()) throw std::invalid_argument("mps model: materials is empty; allowed: at least one");
  for (const Material& mat : materials) mat.validate();
  if (settings.pore_pressure == PorePressure::hydrostatic && !water_material())
    throw std::invalid_argument("mps model: pore_pressure = hydrostatic needs a water material; allowed without one: "
                                "none");
  dummy = particles.add_field({"dummy", true, true});
  gate = particles.add_field({"gate", true, false});
}

double Model::density_of(std::size_t m) const {
  const double d = materials.at(m).density;
  return d > 0 ? d : settings.rest_density;
}

double Model::grain_fraction_of(std::size_t m) const {
  const Material& mat = materials.at(m);
  return mat.type == Material::Type::granular ? mat.grain_volume_fraction : 0.0;
}

std::optional<std::size_t> Model::water_material() const {
  for (std::size_t m = 0; m < materials.size(); ++m)
    if (materials[m].type == Material::Type::water) return m;
  return std::nullopt;
}

bool Model::single_density() const {
  for (std::size_t m = 1; m < materials.size(); ++m)
    if (density_of(m) != density_of(0)) return false;
  return true;
}

std::size_t add_block(Model& model, double x_min, double y_min, double x_max, double y_max, std::uint16_t material) {
  if (material >= model.materials.size()) throw std::invalid_argument("mps add_block: no such material");
  const double dx = model.settings.particle_spacing;
  const auto points = lattice_points_in_region(x_min, y_min, x_max, y_max, dx, [](double, double) { return true; });
  model.particles.reserve(model.particles.size() + points.size());
  for (const Point& p : points)
    model.particles.add(p.x, p.y, model.particle_mass(material), model.density_of(material), material,
                        ParticleKind::material);
  return points.size();
}

std::size_t add_box(Model& model, double x_min, double x_max, double y_min, double height, std::uint16_t material) {
  if (material >= model.materials.size()) throw std::invalid_argument("mps add_box: no such material");
  const double dx = model.settings.particle_spacing;
  BoxWalls box;
  box.x_min = x_min;
  box.x_max = x_max;
  box.y_min = y_min;
  box.height = height;
  box.layers = 0;  // ceil(2h/dx) with h = r_e/2: ceil(r_e/dx) layers
  const std::size_t first = model.particles.size();
  const std::size_t count = add_box_walls(model.particles, box, dx, 0.5 * model.settings.effective_radius(),
                                          material, model.density_of(material));
  ParticleSet& p = model.particles;
  std::vector<double>& dummy = p.field(model.dummy);
  for (std::size_t i = first; i < p.size(); ++i) {
    const bool outer = p.y[i] < y_min - dx || p.x[i] < x_min - dx || p.x[i] > x_max + dx;
    dummy[i] = outer ? 1.0 : 0.0;
  }
  return count;
}

double gate_thickness(const Settings& s) {  // as add_box's walls: the layers that cover 2h = r_e
  return wall_layers_for(s.particle_spacing, 0.5 * s.effective_radius()) * s.particle_spacing;
}

std::size_t add_gate(Model& model, double x_min, double y_min, double height, std::uint16_t material) {
  if (material >= model.materials.size()) throw std::invalid_argument("mps add_gate: no such material");
  const Settings& st = model.settings;
  const double dx = st.particle_spacing;
  const auto layers = static_cast<std::size_t>(wall_layers_for(dx, 0.5 * st.effective_radius()));
  const auto rows = static_cast<std::size_t>(std::llround(height / dx));
  if (rows == 0) throw std::invalid_argument("mps add_gate: height below one spacing");
  ParticleSet& p = model.particles;
  const std::size_t first = p.size();
  p.reserve(first + layers * rows);
  for (std::size_t k = 0; k < layers; ++k)
    for (std::size_t l = 0; l < rows; ++l)
      p.add(x_min + (static_cast<double>(k) + 0.5) * dx, y_min + (static_cast<double>(l) + 0.5) * dx,
            model.particle_mass(material), model.density_of(material), material, ParticleKind::wall);
  std::vector<double>& dummy = p.field(model.dummy);
  std::vector<double>& gate = p.field(model.gate);
  for (std::size_t i = first; i < p.size(); ++i) {
    const std::size_t k = (i - first) / rows;
    dummy[i] = k == 0 || k + 1 == layers ? 0.0 : 1.0;
    gate[i] = 1.0;
  }
  return p.size() - first;
}

}  // namespace sph::mps
