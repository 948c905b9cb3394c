#include "sph/engine/vtk_output.hpp"

#include "sph/engine/atomic_file.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace sph {

namespace {

struct Appended {
  std::string header;  // XML DataArray elements
  std::string data;    // raw blocks, each prefixed by its UInt64 byte count
  template <class T>
  void add(const char* name, const char* type, int components, const std::vector<T>& values) {
    std::ostringstream os;
    os << "        <DataArray type=\"" << type << "\" Name=\"" << name << "\" NumberOfComponents=\"" << components
       << "\" format=\"appended\" offset=\"" << data.size() << "\"/>\n";
    header += os.str();
    const std::uint64_t bytes = values.size() * sizeof(T);
    data.append(reinterpret_cast<const char*>(&bytes), sizeof(bytes));
    data.append(reinterpret_cast<const char*>(values.data()), bytes);
  }
};

// A frame's point data gathered from one or more particle sets, in the order it is written.
struct Frame {
  std::vector<double> x, y, vx, vy, ux, uy, rho;  // position, velocity, displacement [m, m/s], density
  std::vector<std::pair<std::string, std::vector<double>>> scalars;  // registered fields, then derived ones
  std::vector<std::int32_t> material, kind, phase;  // phase: empty when the frame has one set
  std::vector<std::uint32_t> id;
  std::size_t size() const { return x.size(); }
};

std::vector<double>& scalar(Frame& f, const std::string& name) {
  for (auto& [n, v] : f.scalars)
    if (n == name) return v;
  f.scalars.emplace_back(name, std::vector<double>());
  return f.scalars.back().second;
}

void write_frame(const std::string& path, const Frame& f, double time) {
  const std::size_t n = f.size();
  std::vector<double> v3(3 * n);
  for (std::size_t i = 0; i < n; ++i) { v3[3 * i] = f.x[i]; v3[3 * i + 1] = f.y[i]; v3[3 * i + 2] = 0; }
  std::vector<std::int64_t> conn(n), offs(n);
  for (std::size_t i = 0; i < n; ++i) { conn[i] = static_cast<std::int64_t>(i); offs[i] = static_cast<std::int64_t>(i + 1); }
  std::vector<std::uint8_t> types(n, 1);  // VTK_VERTEX
  // all appended arrays share one data block: build sequentially
  Appended all;
  all.data.reserve(n * 8 * 20);
  all.add("Points", "Float64", 3, v3);
  const std::string points_xml = all.header;
  all.header.clear();
  all.add("connectivity", "Int64", 1, conn);
  all.add("offsets", "Int64", 1, offs);
  all.add("types", "UInt8", 1, types);
  const std::string cells_xml = all.header;
  all.header.clear();
  for (std::size_t i = 0; i < n; ++i) { v3[3 * i] = f.vx[i]; v3[3 * i + 1] = f.vy[i]; v3[3 * i + 2] = 0; }
  all.add("velocity", "Float64", 3, v3);
  for (std::size_t i = 0; i < n; ++i) { v3[3 * i] = f.ux[i]; v3[3 * i + 1] = f.uy[i]; v3[3 * i + 2] = 0; }
  all.add("displacement", "Float64", 3, v3);
  for (const auto& [name, values] : f.scalars) all.add(name.c_str(), "Float64", 1, values);
  all.add("density", "Float64", 1, f.rho);
  all.add("material", "Int32", 1, f.material);
  all.add("kind", "Int32", 1, f.kind);
  all.add("id", "UInt32", 1, f.id);
  if (!f.phase.empty()) all.add("phase", "Int32", 1, f.phase);
  const std::string pd_xml = all.header;

  std::ostringstream os;
  os << "<?xml version=\"1.0\"?>\n"
     << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
     << "  <UnstructuredGrid>\n"
     << "    <FieldData>\n"
     << "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" format=\"ascii\">";
  os.precision(17);
  os << time << "</DataArray>\n    </FieldData>\n"
     << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << n << "\">\n"
     << "      <Points>\n" << points_xml << "      </Points>\n"
     << "      <Cells>\n" << cells_xml << "      </Cells>\n"
     << "      <PointData Scalars=\"plastic_strain\" Vectors=\"velocity\">\n" << pd_xml << "      </PointData>\n"
     << "    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n   _";
  std::string out = os.str();
  out += all.data;
  out += "\n  </AppendedData>\n</VTKFile>\n";
  write_file_atomically(path, out);
}

// Appends the particles of `part` its phase keeps (all of them when it has none) to the frame. A scalar the part
// lacks is NaN for its particles; one the frame has not seen yet is NaN for the particles before.
void gather(const FramePart& part, Frame& f) {
  const ParticleSet& p = *part.particles;
  const std::size_t before = f.size();
  std::vector<std::size_t> keep;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (part.phase.empty() || part.phase[i] >= 0) keep.push_back(i);
  for (const std::size_t i : keep) {
    f.x.push_back(p.x[i]);
    f.y.push_back(p.y[i]);
    f.vx.push_back(p.vx[i]);
    f.vy.push_back(p.vy[i]);
    f.ux.push_back(p.x[i] - p.x0[i]);
    f.uy.push_back(p.y[i] - p.y0[i]);
    f.rho.push_back(p.rho[i]);
    f.material.push_back(p.material[i]);
    f.kind.push_back(p.kind[i]);
    f.id.push_back(p.id[i]);
    if (!part.phase.empty()) f.phase.push_back(part.phase[i]);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto append = [&](const std::string& name, const std::vector<double>& values) {
    std::vector<double>& column = scalar(f, name);
    column.resize(before, nan);
    for (const std::size_t i : keep) column.push_back(values[i]);
  };
  for (FieldId k = 0; k < p.field_count(); ++k)
    if (p.spec(k).write_vtu) append(p.spec(k).name, p.field(k));
  for (const DerivedField& d : part.derived) append(d.name, d.values);
  for (auto& [name, column] : f.scalars) column.resize(f.size(), nan);
}

}  // namespace

void write_vtu(const std::string& path, const ParticleSet& p, double time, const std::vector<DerivedField>& derived) {
  Frame f;
  gather({&p, derived, {}}, f);
  write_frame(path, f, time);
}

void write_vtu(const std::string& path, const std::vector<FramePart>& parts, double time) {
  Frame f;
  for (const FramePart& part : parts) gather(part, f);
  if (f.phase.size() != f.size()) throw std::invalid_argument("write_vtu: every part of a frame needs its phases");
  write_frame(path, f, time);
}

void write_pvd(const std::string& path, const std::vector<std::pair<double, std::string>>& frames) {
  std::ostringstream os;
  os.precision(17);
  os << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
     << "  <Collection>\n";
  for (const auto& [t, file] : frames)
    os << "    <DataSet timestep=\"" << t << "\" group=\"\" part=\"0\" file=\"" << file << "\"/>\n";
  os << "  </Collection>\n</VTKFile>\n";
  write_file_atomically(path, os.str());
}

}  // namespace sph
