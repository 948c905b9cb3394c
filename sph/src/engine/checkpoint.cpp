#include "sph/engine/checkpoint.hpp"

#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "sph/engine/atomic_file.hpp"

namespace sph {

namespace {

constexpr char kMagic[16] = "SPHSLOPE-CKPT\0\0";

std::uint64_t fnv1a(const char* data, std::size_t n) {
  std::uint64_t h = 1469598103934665603ull;
  for (std::size_t i = 0; i < n; ++i) {
    h ^= static_cast<unsigned char>(data[i]);
    h *= 1099511628211ull;
  }
  return h;
}

struct Writer {
  std::string buf;
  template <class T>
  void put(const T& v) { buf.append(reinterpret_cast<const char*>(&v), sizeof(T)); }
  template <class T>
  void put_vec(const std::vector<T>& v) {
    put<std::uint64_t>(v.size());
    if (!v.empty()) buf.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
};

struct Reader {
  const std::string& buf;
  std::size_t pos = 0;
  std::string path;
  void need(std::size_t n) {
    if (pos + n > buf.size()) throw std::runtime_error("checkpoint " + path + " is truncated");
  }
  template <class T>
  T get() {
    need(sizeof(T));
    T v;
    std::memcpy(&v, buf.data() + pos, sizeof(T));
    pos += sizeof(T);
    return v;
  }
  template <class T>
  void get_vec(std::vector<T>& v, std::size_t expected) {
    const auto n = get<std::uint64_t>();
    if (expected != static_cast<std::size_t>(-1) && n != expected)
      throw std::runtime_error("checkpoint " + path + ": array length mismatch");
    need(n * sizeof(T));
    v.resize(n);
    if (n > 0) std::memcpy(v.data(), buf.data() + pos, n * sizeof(T));  // an empty vector's data() may be null
    pos += n * sizeof(T);
  }
};

}  // namespace

std::string checkpoint_bytes(const ParticleSet& set, const RunState& s, const CheckpointFingerprint& fingerprint) {
  Writer w;
  ParticleSet& particles = const_cast<ParticleSet&>(set);  // read only: for_each_* are not const
  w.buf.reserve(set.size() * (static_cast<std::size_t>(particles.double_array_count()) * 8 + 16) + 4096);
  w.buf.append(kMagic, 16);
  w.put<std::uint32_t>(checkpoint_version);
  w.put<std::uint32_t>(0x01020304u);
  w.put<std::uint64_t>(set.size());
  std::vector<std::string_view> names;
  particles.for_each_checkpointed_double_array([&](std::string_view name, auto&) { names.push_back(name); });
  w.put<std::uint32_t>(static_cast<std::uint32_t>(names.size()));
  w.put<std::uint32_t>(fingerprint.materials);
  w.put<double>(fingerprint.particle_spacing);
  w.put<double>(fingerprint.h_over_dx);
  w.put<double>(s.time);
  w.put<std::uint64_t>(s.step);
  w.put<std::uint8_t>(s.rates_valid ? 1 : 0);
  w.put<std::uint8_t>(s.initial_stress_applied ? 1 : 0);
  w.put<double>(s.next_output_time);
  w.put<std::uint64_t>(s.frames_written);
  w.put_vec(s.frame_times);
  w.put<double>(s.initial_potential_energy);
  w.put<std::uint64_t>(s.energy_csv_bytes);
  for (std::string_view name : names) {  // the array names, so that a reader can match its own registry
    w.put<std::uint32_t>(static_cast<std::uint32_t>(name.size()));
    w.buf.append(name.data(), name.size());
  }
  particles.for_each_checkpointed_double_array([&](std::string_view, std::vector<double>& a) { w.put_vec(a); });
  w.put_vec(set.id);
  w.put_vec(set.material);
  w.put_vec(set.kind);
  w.put<std::uint64_t>(fnv1a(w.buf.data(), w.buf.size()));
  return std::move(w.buf);
}

void write_checkpoint(const std::string& path, const ParticleSet& set, const RunState& s,
                      const CheckpointFingerprint& fingerprint) {
  write_file_atomically(path, checkpoint_bytes(set, s, fingerprint));
}

std::string read_checkpoint_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("cannot open checkpoint " + path);
  return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

void read_checkpoint(const std::string& path, ParticleSet& set, RunState& state,
                     const CheckpointFingerprint& expected) {
  restore_checkpoint(read_checkpoint_file(path), path, set, state, expected);
}

void restore_checkpoint(const std::string& buf, const std::string& path, ParticleSet& set, RunState& state,
                        const CheckpointFingerprint& expected) {
  if (buf.size() < 16 + 8 || std::memcmp(buf.data(), kMagic, 16) != 0)
    throw std::runtime_error(path + " is not an sphslope checkpoint");
  std::uint64_t stored_sum;
  std::memcpy(&stored_sum, buf.data() + buf.size() - 8, 8);
  if (fnv1a(buf.data(), buf.size() - 8) != stored_sum)
    throw std::runtime_error("checkpoint " + path + " is corrupt or truncated (checksum mismatch)");
  Reader r{buf, 16, path};
  const auto version = r.get<std::uint32_t>();
  if (version != checkpoint_version)
    throw std::runtime_error("checkpoint " + path + " has version " + std::to_string(version) + ", expected " +
                             std::to_string(checkpoint_version));
  if (r.get<std::uint32_t>() != 0x01020304u) throw std::runtime_error("checkpoint " + path + ": wrong byte order");
  const auto n = r.get<std::uint64_t>();
  const auto ndouble = r.get<std::uint32_t>();
  const auto nmat = r.get<std::uint32_t>();
  const auto dx = r.get<double>();
  const auto hdx = r.get<double>();
  std::vector<std::string_view> own_names;
  set.for_each_checkpointed_double_array([&](std::string_view name, auto&) { own_names.push_back(name); });
  const bool count_differs = n != set.size() && !(expected.particles_may_leave && n <= set.size());
  if (count_differs || ndouble != own_names.size() || nmat != expected.materials ||
      dx != expected.particle_spacing || hdx != expected.h_over_dx)
    throw std::runtime_error("checkpoint " + path + " does not belong to this model (particles " + std::to_string(n) +
                             " vs " + std::to_string(set.size()) + ", materials " + std::to_string(nmat) + " vs " +
                             std::to_string(expected.materials) + ", or dx / h_over_dx differ)");
  RunState s;
  s.time = r.get<double>();
  s.step = r.get<std::uint64_t>();
  s.rates_valid = r.get<std::uint8_t>() != 0;
  s.initial_stress_applied = r.get<std::uint8_t>() != 0;
  s.next_output_time = r.get<double>();
  s.frames_written = r.get<std::uint64_t>();
  r.get_vec(s.frame_times, static_cast<std::size_t>(-1));
  s.initial_potential_energy = r.get<double>();
  s.energy_csv_bytes = r.get<std::uint64_t>();
  for (std::string_view own : own_names) {
    const auto length = r.get<std::uint32_t>();
    r.need(length);
    const std::string_view stored(buf.data() + r.pos, length);
    r.pos += length;
    if (stored != own)
      throw std::runtime_error("checkpoint " + path + " holds the particle array '" + std::string(stored) +
                               "' where this model has '" + std::string(own) + "' (written by another version?)");
  }
  ParticleSet& p = set;
  p.for_each_checkpointed_double_array([&](std::string_view, std::vector<double>& a) { r.get_vec(a, n); });
  r.get_vec(p.id, n);
  r.get_vec(p.material, n);
  r.get_vec(p.kind, n);
  // arrays a checkpoint does not keep (step workspace) are recomputed: size them, zero
  for (FieldId f = 0; f < p.field_count(); ++f)
    if (!p.spec(f).checkpoint) p.field(f).assign(n, 0.0);
  state = std::move(s);
}

}  // namespace sph
