#pragma once
// The particle set of the engine: core fields every particle method needs, plus per-particle arrays that each
// physics registers by name (a "state block"). Everything that must treat every array alike — the reorder by cell,
// checkpoints, VTU frames, the memory estimate — iterates this registry, so a physics adds state without touching
// the engine. Structure of arrays, one contiguous std::vector per field. SI units; 2-D, "mass" per metre of
// out-of-plane width (kg/m).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sph {

// What a particle is, for every physics: `material` is the continuum the physics integrates (the soil model's soil,
// the fluid's water, the MPS's grains and water), `wall` a boundary particle (fixed walls, and the fluid's rigid
// bodies). Stored as 0 and 1 in checkpoints and frames.
enum class ParticleKind : std::uint8_t { material = 0, wall = 1 };

using FieldId = std::uint32_t;

struct FieldSpec {
  std::string name;         // unique; VTU array name when written
  bool checkpoint = true;   // part of the state a resumed run needs (false: recomputed, e.g. step workspace)
  bool write_vtu = false;   // written to every VTU frame
};

class ParticleSet {
 public:
  // --- core fields ---------------------------------------------------------------------------------------------
  std::vector<double> x, y;    // position [m]
  std::vector<double> vx, vy;  // velocity [m/s] (walls: whatever their physics gives them)
  std::vector<double> rho;     // density [kg/m^3]
  std::vector<double> mass;    // [kg/m]
  std::vector<double> x0, y0;  // initial position [m] (displacement = x - x0)
  std::vector<std::uint32_t> id;        // original index, stable across reordering
  std::vector<std::uint16_t> material;  // index into the physics' material list
  std::vector<std::uint8_t> kind;       // ParticleKind
  static constexpr int core_double_count = 8;

  std::size_t size() const { return x.size(); }
  std::size_t count(ParticleKind k) const;
  double total_mass(ParticleKind k) const;  // [kg/m] the summed mass of the particles of kind k

  // Appends one particle at rest; every registered field starts at 0. Returns its index.
  std::size_t add(double px, double py, double particle_mass, double density, std::uint16_t material_id,
                  ParticleKind particle_kind);
  void reserve(std::size_t n);
  // Removes the particles i with drop[i] != 0 from every array (core and registered), keeping the order of the
  // others (drop has size()). Returns how many were removed. Indices held elsewhere are invalid afterwards.
  std::size_t remove(const std::vector<std::uint8_t>& drop);

  // --- registered fields ---------------------------------------------------------------------------------------
  // Registers a per-particle array (zero for the particles already present), or returns the existing one of that
  // name (then the spec must match). Throws std::invalid_argument on a clash with a core field name.
  FieldId add_field(const FieldSpec& spec);
  std::optional<FieldId> find_field(std::string_view name) const;
  std::vector<double>& field(FieldId f) { return fields_[f]; }
  const std::vector<double>& field(FieldId f) const { return fields_[f]; }
  const FieldSpec& spec(FieldId f) const { return specs_[f]; }
  std::size_t field_count() const { return fields_.size(); }
  int double_array_count() const { return core_double_count + static_cast<int>(fields_.size()); }

  // Calls f(std::vector<T>&) for every per-particle array: core doubles, registered fields, then id, material,
  // kind. The order is fixed for a given registry.
  template <class F>
  void for_each_array(F&& f) {
    for_each_double_array(f);
    f(id);
    f(material);
    f(kind);
  }
  template <class F>
  void for_each_double_array(F&& f) {
    f(x); f(y); f(vx); f(vy); f(rho); f(mass); f(x0); f(y0);
    for (auto& a : fields_) f(a);
  }
  // Core doubles and the registered fields a checkpoint keeps, with their names.
  template <class F>
  void for_each_checkpointed_double_array(F&& f) {
    const char* core[] = {"x", "y", "vx", "vy", "density", "mass", "x0", "y0"};
    std::vector<double>* arrays[] = {&x, &y, &vx, &vy, &rho, &mass, &x0, &y0};
    for (int k = 0; k < core_double_count; ++k) f(std::string_view(core[k]), *arrays[k]);
    for (std::size_t k = 0; k < fields_.size(); ++k)
      if (specs_[k].checkpoint) f(std::string_view(specs_[k].name), fields_[k]);
  }

 private:
  std::vector<FieldSpec> specs_;
  std::vector<std::vector<double>> fields_;
};

}  // namespace sph
