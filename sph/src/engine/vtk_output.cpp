#include "sph/engine/vtk_output.hpp"

#include "sph/engine/atomic_file.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>
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

}  // namespace

void write_vtu(const std::string& path, const ParticleSet& p, double time, const std::vector<DerivedField>& derived) {
  const std::size_t n = p.size();
  std::vector<double> v3(3 * n);
  for (std::size_t i = 0; i < n; ++i) { v3[3 * i] = p.x[i]; v3[3 * i + 1] = p.y[i]; v3[3 * i + 2] = 0; }
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
  for (std::size_t i = 0; i < n; ++i) { v3[3 * i] = p.vx[i]; v3[3 * i + 1] = p.vy[i]; v3[3 * i + 2] = 0; }
  all.add("velocity", "Float64", 3, v3);
  for (std::size_t i = 0; i < n; ++i) { v3[3 * i] = p.x[i] - p.x0[i]; v3[3 * i + 1] = p.y[i] - p.y0[i]; v3[3 * i + 2] = 0; }
  all.add("displacement", "Float64", 3, v3);
  // the physics' own arrays, as registered, then the quantities it derives for output
  for (FieldId f = 0; f < p.field_count(); ++f)
    if (p.spec(f).write_vtu) all.add(p.spec(f).name.c_str(), "Float64", 1, p.field(f));
  for (const DerivedField& d : derived) all.add(d.name.c_str(), "Float64", 1, d.values);
  all.add("density", "Float64", 1, p.rho);
  std::vector<std::int32_t> mat(p.material.begin(), p.material.end()), kind(p.kind.begin(), p.kind.end());
  all.add("material", "Int32", 1, mat);
  all.add("kind", "Int32", 1, kind);
  all.add("id", "UInt32", 1, p.id);
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
