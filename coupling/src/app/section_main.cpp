// sphslope section (this program, sphslope-section, which `sphslope section` runs): a ground profile cut out of a
// terrain raster that GDAL reads (GeoTIFF, ESRI .bil/.hdr, ASCII grid, ...) along a line given in the raster's
// coordinates. The elevation is the bilinear interpolation of the four cell centres around each sample; x is the
// distance along the line from its first vertex, y the elevation, both in metres, rounded to 1 mm. The profile goes
// to stdout as CSV, or into a copy of a scene as section.profile_lines[0].points_m. A drawing (DXF, read by dxflib)
// gives the profile lines and the piezometric line of a scene from its layers. A separate program because GDAL
// and its hundred libraries take some 40 ms to load, which every other command would pay.
// Exit status: 0 written; 2 invalid input (the message names the file, the option or the point that is wrong).
#include <dl_creationadapter.h>
#include <dl_dxf.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <map>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace {

constexpr int invalid_input = 2;
constexpr double max_cells = 2.0e8;       // 1.6 GB of elevations in memory
constexpr double max_points = 1.0e6;      // the scene's limit on a profile line's vertices
constexpr double us_survey_foot = 1200.0 / 3937.0;

using Point = std::array<double, 2>;

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

std::string point_text(const Point& p) { return "(" + number(p[0]) + ", " + number(p[1]) + ")"; }

// The elevations of band 1, on the grid of cell centres, with the units and the georeferencing.
struct Raster {
  int columns = 0, rows = 0;
  double transform[6] = {};  // x = t0 + (column + 1/2) t1, y = t3 + (row + 1/2) t5 at a cell centre (no rotation)
  std::vector<double> z;     // row-major, as stored
  std::optional<double> nodata;
  double xy_metres = 1.0;    // metres per unit of the coordinates
  double z_metres = 1.0;     // metres per unit of the elevations
  std::vector<std::string> notes;

  double at(int column, int row) const { return z[static_cast<std::size_t>(row) * columns + column]; }
  double cell_size() const { return std::min(std::abs(transform[1]), std::abs(transform[5])); }
  Point centre(double column, double row) const {
    return {transform[0] + (column + 0.5) * transform[1], transform[3] + (row + 0.5) * transform[5]};
  }
};

// Metres per unit of the coordinates: the coordinate system's linear unit; degrees are refused.
double coordinate_unit(GDALDatasetH dataset, const std::string& path, std::vector<std::string>& notes) {
  const char* wkt = GDALGetProjectionRef(dataset);
  if (wkt == nullptr || *wkt == '\0') {
    notes.push_back(path + ": no coordinate system; the coordinates are taken as metres");
    return 1.0;
  }
  OGRSpatialReferenceH srs = OSRNewSpatialReference(wkt);
  if (srs == nullptr) throw InputError(path + ": its coordinate system cannot be read");
  const char* name = OSRGetName(srs);
  const std::string crs = name != nullptr ? name : "unnamed";
  const bool geographic = OSRIsGeographic(srs) != 0;
  char* unit_name = nullptr;
  const double metres = OSRGetLinearUnits(srs, &unit_name);
  const std::string unit = unit_name != nullptr ? unit_name : "";
  OSRDestroySpatialReference(srs);
  if (geographic)
    throw InputError(path + ": its coordinates are longitude and latitude in degrees (" + crs +
                     "); reproject it to a projected coordinate system in metres first, e.g. "
                     "gdalwarp -t_srs EPSG:32633 in.tif out.tif");
  if (!(metres > 0.0)) throw InputError(path + ": the coordinate system " + crs + " has no linear unit");
  notes.push_back(path + ": coordinate system " + crs + ", coordinates in " + unit +
                  (metres == 1.0 ? "" : " (" + number(metres) + " m each)"));
  return metres;
}

// Metres per unit of the elevations (the band's unit type): metres, feet or US survey feet; none: metres.
double elevation_unit(GDALRasterBandH band, const std::string& path, std::vector<std::string>& notes) {
  const char* type = GDALGetRasterUnitType(band);
  std::string unit = type != nullptr ? type : "";
  std::transform(unit.begin(), unit.end(), unit.begin(), [](unsigned char c) { return std::tolower(c); });
  if (unit.empty()) {
    notes.push_back(path + ": the elevations carry no unit; they are taken as metres");
    return 1.0;
  }
  for (const char* metre : {"m", "metre", "meter", "metres", "meters"})
    if (unit == metre) return 1.0;
  for (const char* foot : {"ft", "foot", "feet", "international foot"})
    if (unit == foot) {
      notes.push_back(path + ": elevations in feet, converted to metres (0.3048 m each)");
      return 0.3048;
    }
  for (const char* foot : {"us survey foot", "ftus", "us-ft"})
    if (unit == foot) {
      notes.push_back(path + ": elevations in US survey feet, converted to metres (1200/3937 m each)");
      return us_survey_foot;
    }
  throw InputError(path + ": elevation unit \"" + std::string(type) + "\" is not metres or feet");
}

void read_georeferencing(GDALDatasetH dataset, const std::string& path, Raster& raster) {
  if (GDALGetGeoTransform(dataset, raster.transform) != CE_None)
    throw InputError(path + ": the raster is not georeferenced (no origin and cell size)");
  if (raster.transform[2] != 0.0 || raster.transform[4] != 0.0)
    throw InputError(path + ": the raster's grid is rotated; warp it to a north-up grid first (gdalwarp)");
  if (raster.transform[1] == 0.0 || raster.transform[5] == 0.0) throw InputError(path + ": a cell size is zero");
}

Raster read_raster(const std::string& path) {
  GDALAllRegister();
  CPLPushErrorHandler(CPLQuietErrorHandler);
  GDALDatasetH dataset = GDALOpen(path.c_str(), GA_ReadOnly);
  CPLPopErrorHandler();
  if (dataset == nullptr)
    throw InputError(path + ": not a raster GDAL can read (" + std::string(CPLGetLastErrorMsg()) + ")");
  struct Closer {
    GDALDatasetH dataset;
    ~Closer() { GDALClose(dataset); }
  } closer{dataset};
  Raster raster;
  raster.columns = GDALGetRasterXSize(dataset);
  raster.rows = GDALGetRasterYSize(dataset);
  if (GDALGetRasterCount(dataset) < 1) throw InputError(path + ": the raster has no band");
  if (raster.columns < 2 || raster.rows < 2) throw InputError(path + ": the raster has fewer than 2 x 2 cells");
  if (static_cast<double>(raster.columns) * raster.rows > max_cells)
    throw InputError(path + ": " + std::to_string(raster.columns) + " x " + std::to_string(raster.rows) +
                     " cells is more than " + number(max_cells) + "; crop it around the line first (gdal_translate "
                     "-projwin)");
  read_georeferencing(dataset, path, raster);
  raster.xy_metres = coordinate_unit(dataset, path, raster.notes);
  GDALRasterBandH band = GDALGetRasterBand(dataset, 1);
  raster.z_metres = elevation_unit(band, path, raster.notes);
  int has_nodata = 0;
  const double nodata = GDALGetRasterNoDataValue(band, &has_nodata);
  if (has_nodata) raster.nodata = nodata;
  raster.z.resize(static_cast<std::size_t>(raster.columns) * raster.rows);
  if (GDALRasterIO(band, GF_Read, 0, 0, raster.columns, raster.rows, raster.z.data(), raster.columns, raster.rows,
                   GDT_Float64, 0, 0) != CE_None)
    throw InputError(path + ": its elevations cannot be read (" + std::string(CPLGetLastErrorMsg()) + ")");
  return raster;
}

// Where `p` lies on the grid of cell centres: (column, row) as real numbers; nullopt outside it.
std::optional<Point> grid_position(const Raster& raster, const Point& p) {
  const double column = (p[0] - raster.transform[0]) / raster.transform[1] - 0.5;
  const double row = (p[1] - raster.transform[3]) / raster.transform[5] - 0.5;
  const double tolerance = 1e-9;
  if (!(column >= -tolerance && column <= raster.columns - 1 + tolerance && row >= -tolerance &&
        row <= raster.rows - 1 + tolerance))
    return std::nullopt;
  return Point{std::clamp(column, 0.0, raster.columns - 1.0), std::clamp(row, 0.0, raster.rows - 1.0)};
}

std::string extent_text(const Raster& raster) {
  const Point a = raster.centre(0, 0), b = raster.centre(raster.columns - 1, raster.rows - 1);
  return "x " + number(std::min(a[0], b[0])) + " to " + number(std::max(a[0], b[0])) + ", y " +
         number(std::min(a[1], b[1])) + " to " + number(std::max(a[1], b[1]));
}

// The elevation at `p` (bilinear between the four cell centres around it), in the raster's unit; nullopt where a
// cell it needs holds no data.
std::optional<double> elevation(const Raster& raster, const Point& grid) {
  const int c0 = std::min(static_cast<int>(grid[0]), raster.columns - 2);
  const int r0 = std::min(static_cast<int>(grid[1]), raster.rows - 2);
  const double u = grid[0] - c0, v = grid[1] - r0;
  const double weights[4] = {(1 - u) * (1 - v), u * (1 - v), (1 - u) * v, u * v};
  const double values[4] = {raster.at(c0, r0), raster.at(c0 + 1, r0), raster.at(c0, r0 + 1),
                            raster.at(c0 + 1, r0 + 1)};
  double z = 0.0;
  for (int k = 0; k < 4; ++k) {
    if (weights[k] == 0.0) continue;
    if (!std::isfinite(values[k]) || (raster.nodata && values[k] == *raster.nodata)) return std::nullopt;
    z += weights[k] * values[k];
  }
  return z;
}

double round_mm(double metres) { return std::round(metres * 1000.0) / 1000.0; }

// The point at distance `d` metres along `line`, whose vertices lie at `at_m` metres along it. `segment` (start at 1)
// is the segment the last call ended on: the distances come in increasing order, so the walk never starts over.
Point point_along(const std::vector<Point>& line, const std::vector<double>& at_m, double d, std::size_t& segment) {
  std::size_t& i = segment;
  while (i + 1 < line.size() && at_m[i] < d) ++i;
  const double length = at_m[i] - at_m[i - 1];
  const double t = length > 0.0 ? std::clamp((d - at_m[i - 1]) / length, 0.0, 1.0) : 0.0;
  return {line[i - 1][0] + t * (line[i][0] - line[i - 1][0]), line[i - 1][1] + t * (line[i][1] - line[i - 1][1])};
}

// The profile along `line` (raster coordinates), a sample every `step_m` metres and one at the line's end:
// [distance_m, elevation_m] rounded to 1 mm.
std::vector<Point> cut_profile(const Raster& raster, const std::vector<Point>& line, double step_m) {
  for (std::size_t i = 0; i < line.size(); ++i)
    if (!grid_position(raster, line[i]))
      throw InputError("--line: vertex " + std::to_string(i) + " " + point_text(line[i]) +
                       " lies outside the raster's cell centres (" + extent_text(raster) + ")");
  std::vector<double> at_m{0.0};
  for (std::size_t i = 1; i < line.size(); ++i)
    at_m.push_back(at_m.back() +
                   std::hypot(line[i][0] - line[i - 1][0], line[i][1] - line[i - 1][1]) * raster.xy_metres);
  const double length_m = at_m.back();
  if (!(length_m >= 0.002)) throw InputError("--line: the line is shorter than 2 mm");
  if (length_m / step_m + 1 > max_points)
    throw InputError("--step: " + number(step_m) + " m gives more than " + number(max_points) +
                     " points on a line of " + number(length_m) + " m; take a longer step");
  std::vector<double> distances;
  for (long k = 0; k * step_m <= length_m; ++k) distances.push_back(k * step_m);
  if (round_mm(length_m) > round_mm(distances.back())) distances.push_back(length_m);
  std::vector<Point> profile;
  std::size_t segment = 1;
  for (const double d : distances) {
    const Point p = point_along(line, at_m, d, segment);
    const auto z = elevation(raster, *grid_position(raster, p));
    if (!z)
      throw InputError("--line: the line crosses cells without data at " + number(round_mm(d)) + " m along it, " +
                       point_text(p));
    profile.push_back({round_mm(d), round_mm(*z * raster.z_metres)});
  }
  return profile;
}

// ---- drawn sections (DXF)

// The polylines of a drawing (POLYLINE and LWPOLYLINE, and LINE as a polyline of two points) by layer, and its
// $INSUNITS.
struct Drawing : DL_CreationAdapter {
  std::map<std::string, std::vector<std::vector<Point>>> lines;  // layer -> its polylines, in the drawing's units
  int units = 0;                                                  // $INSUNITS (0: not stated)
  std::vector<Point>* open = nullptr;                             // the polyline taking vertices

  void addPolyline(const DL_PolylineData&) override {
    auto& layer = lines[getAttributes().getLayer()];
    layer.emplace_back();
    open = &layer.back();
  }
  void addVertex(const DL_VertexData& v) override {
    if (open != nullptr) open->push_back({v.x, v.y});
  }
  void endSequence() override { open = nullptr; }
  void addLine(const DL_LineData& l) override {
    lines[getAttributes().getLayer()].push_back({{l.x1, l.y1}, {l.x2, l.y2}});
    open = nullptr;
  }
  void setVariableInt(const std::string& key, int value, int) override {
    if (key == "$INSUNITS") units = value;
  }
};

// Metres per drawing unit: --units when given, else the drawing's $INSUNITS; neither is an error.
double drawing_unit(const std::string& path, int insunits, const std::string& given) {
  const std::map<std::string, double> names{{"m", 1.0},     {"mm", 0.001},  {"cm", 0.01},
                                            {"km", 1000.0}, {"ft", 0.3048}, {"in", 0.0254},
                                            {"us-ft", us_survey_foot}};
  if (!given.empty()) {
    const auto it = names.find(given);
    if (it == names.end()) throw InputError("--units: \"" + given + "\" is not m, mm, cm, km, ft, in or us-ft");
    return it->second;
  }
  const std::map<int, double> codes{{1, 0.0254}, {2, 0.3048},   {4, 0.001},         {5, 0.01},
                                    {6, 1.0},    {7, 1000.0},   {21, us_survey_foot}};
  const auto it = codes.find(insunits);
  if (it == codes.end())
    throw InputError(path + ": the drawing states no length unit ($INSUNITS " + std::to_string(insunits) +
                     "); give it with --units m|mm|cm|km|ft|in|us-ft");
  return it->second;
}

// The one polyline on `layer`, in metres, with x increasing (a line drawn from right to left is reversed).
std::vector<Point> layer_line(const Drawing& drawing, const std::string& path, const std::string& layer,
                              double metres) {
  const auto it = drawing.lines.find(layer);
  if (it == drawing.lines.end() || it->second.empty()) {
    std::string layers;
    for (const auto& entry : drawing.lines) layers += (layers.empty() ? "" : ", ") + entry.first;
    throw InputError(path + ": no polyline on layer \"" + layer + "\" (layers with lines: " +
                     (layers.empty() ? "none" : layers) + ")");
  }
  if (it->second.size() > 1)
    throw InputError(path + ": layer \"" + layer + "\" holds " + std::to_string(it->second.size()) +
                     " lines; join them into one polyline");
  std::vector<Point> line = it->second.front();
  if (line.size() < 2)
    throw InputError(path + ": the polyline on layer \"" + layer + "\" has fewer than 2 vertices");
  if (line.back()[0] < line.front()[0]) std::reverse(line.begin(), line.end());
  for (Point& p : line) p = {round_mm(p[0] * metres), round_mm(p[1] * metres)};
  for (std::size_t i = 1; i < line.size(); ++i)
    if (!(line[i][0] > line[i - 1][0]))
      throw InputError(path + ": the polyline on layer \"" + layer + "\" turns back at vertex " +
                       std::to_string(i) + " " + point_text(line[i]) + " m; a section's lines must have x increasing");
  return line;
}

Drawing read_drawing(const std::string& path) {
  std::ifstream probe(path);
  if (!probe) throw InputError(path + ": cannot read the drawing");
  Drawing drawing;
  DL_Dxf dxf;
  if (!dxf.in(path, &drawing)) throw InputError(path + ": not a DXF drawing dxflib can read");
  return drawing;
}

// What goes into the scene: its profile lines in order (points in metres, and a material, empty: the scene's line
// at that place keeps its own) and, when given, the piezometric line.
struct SceneLines {
  std::vector<std::pair<std::vector<Point>, std::string>> profile_lines;
  std::optional<std::vector<Point>> water;
};

// The scene `scene_path` with its section.profile_lines (and water) replaced by `lines`, the rest kept, into
// `out_path`.
void write_into_scene(const std::string& scene_path, const std::string& out_path, const SceneLines& lines) {
  std::ifstream in(scene_path);
  if (!in) throw InputError("--scene: cannot read " + scene_path);
  nlohmann::ordered_json scene;
  try {
    scene = nlohmann::ordered_json::parse(in);
  } catch (const nlohmann::json::parse_error& error) {
    throw InputError("--scene: " + scene_path + " is not JSON (" + error.what() + ")");
  }
  const nlohmann::ordered_json old_lines = scene["section"]["profile_lines"];
  nlohmann::ordered_json new_lines = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < lines.profile_lines.size(); ++i) {
    const auto& [points, material] = lines.profile_lines[i];
    nlohmann::ordered_json line = old_lines.is_array() && i < old_lines.size() && old_lines[i].is_object()
                                      ? old_lines[i]
                                      : nlohmann::ordered_json::object();
    if (!material.empty()) line["material"] = material;
    if (!line.contains("material"))
      throw InputError("--scene: " + scene_path + " has no section.profile_lines[" + std::to_string(i) +
                       "] to take its material from; name it (--profile LAYER=MATERIAL)");
    line["points_m"] = points;
    new_lines.push_back(line);
  }
  scene["section"]["profile_lines"] = new_lines;
  if (lines.water) scene["section"]["water"]["piezometric_line_m"] = *lines.water;
  std::ofstream out(out_path);
  out << scene.dump(2) << "\n";
  if (!out) throw InputError("-o: cannot write " + out_path);
}

struct Options {
  std::string raster, scene, output;
  std::vector<double> line;
  double step_m = 0.0;                // 0: half the smaller cell size
  std::vector<std::string> profiles;  // a drawing's layers, LAYER[=MATERIAL], in the order of profile_lines
  std::string water;                  // a drawing's layer of the piezometric line
  std::string units;                  // a drawing's length unit, when it states none
};

bool is_drawing(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".dxf";
}

// A drawn section into a copy of the scene: each --profile layer's polyline becomes a profile line, --water's the
// piezometric line.
int take_drawing(const Options& options) {
  if (options.scene.empty() || options.output.empty())
    throw InputError("a drawing goes into a scene: give --scene IN.json -o OUT.json");
  if (options.profiles.empty())
    throw InputError("--profile: name the drawing's layer of the ground (LAYER[=MATERIAL])");
  if (!options.line.empty()) throw InputError("--line is for rasters; a drawing's lines are its layers (--profile)");
  const Drawing drawing = read_drawing(options.raster);
  const double metres = drawing_unit(options.raster, drawing.units, options.units);
  SceneLines lines;
  for (const std::string& profile : options.profiles) {
    const auto equals = profile.find('=');
    const std::string layer = profile.substr(0, equals);
    lines.profile_lines.emplace_back(layer_line(drawing, options.raster, layer, metres),
                                     equals == std::string::npos ? "" : profile.substr(equals + 1));
    std::cerr << "section: layer \"" << layer << "\": profile_lines[" << lines.profile_lines.size() - 1 << "], "
              << lines.profile_lines.back().first.size() << " vertices\n";
  }
  if (!options.water.empty()) lines.water = layer_line(drawing, options.raster, options.water, metres);
  write_into_scene(options.scene, options.output, lines);
  std::cerr << "section: " << options.raster << ": " << number(metres) << " m per drawing unit; wrote "
            << options.output << "\n";
  return 0;
}

int cut(const Options& options) {
  if (is_drawing(options.raster)) return take_drawing(options);
  if (options.line.size() < 4 || options.line.size() % 2 != 0)
    throw InputError("--line: give the line's vertices as X0,Y0,X1,Y1[,...] in the raster's coordinates (got " +
                     std::to_string(options.line.size()) + " numbers)");
  if (options.scene.empty() != options.output.empty())
    throw InputError("--scene and -o go together: the scene to copy and the file to write");
  const Raster raster = read_raster(options.raster);
  for (const std::string& note : raster.notes) std::cerr << "section: " << note << "\n";
  const double step_m = options.step_m > 0.0 ? options.step_m : 0.5 * raster.cell_size() * raster.xy_metres;
  if (!(step_m >= 0.001)) throw InputError("--step: must be at least 0.001 m (got " + number(step_m) + ")");
  std::vector<Point> line;
  for (std::size_t i = 0; i + 1 < options.line.size(); i += 2) line.push_back({options.line[i], options.line[i + 1]});
  const std::vector<Point> profile = cut_profile(raster, line, step_m);
  const auto [lowest, highest] = std::minmax_element(
      profile.begin(), profile.end(), [](const Point& a, const Point& b) { return a[1] < b[1]; });
  std::cerr << "section: " << profile.size() << " points, every " << number(step_m) << " m over "
            << number(profile.back()[0]) << " m; elevations " << number((*lowest)[1]) << " to "
            << number((*highest)[1]) << " m\n";
  if (!options.scene.empty()) {
    write_into_scene(options.scene, options.output, SceneLines{{{profile, ""}}, std::nullopt});
    std::cerr << "section: wrote " << options.output << " (section.profile_lines[0].points_m)\n";
    return 0;
  }
  std::cout << "x_m,y_m\n";
  for (const Point& p : profile) std::cout << number(p[0]) << "," << number(p[1]) << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"sphslope section: a ground profile cut out of a terrain raster (any format GDAL reads) along a line "
               "in the raster's coordinates: x the distance along the line, y the elevation, in metres. CSV on "
               "stdout, or into a copy of a scene (--scene IN -o OUT). Or a drawn section (.dxf): its --profile layers "
               "become the scene's profile lines, its --water layer the piezometric line. Exit status: 0 written; 2 "
               "invalid input.",
               "sphslope section"};
  Options options;
  app.add_option("FILE", options.raster, "Terrain raster (GeoTIFF, ESRI .bil/.hdr, ASCII grid, ...) or drawing (.dxf)")
      ->required()
      ->type_name("FILE");
  app.add_option("--line", options.line, "A raster's: the line's vertices in its coordinates, X0,Y0,X1,Y1[,...]")
      ->delimiter(',')
      ->type_name("X,Y,...");
  app.add_option("--profile", options.profiles,
                 "A drawing's (DXF): the layer whose one polyline is the next profile line (the first the ground), "
                 "with the material below it, or the scene's line at that place keeps its material")
      ->type_name("LAYER[=MATERIAL]");
  app.add_option("--water", options.water, "A drawing's: the layer of the piezometric line")->type_name("LAYER");
  app.add_option("--units", options.units,
                 "A drawing's length unit when it states none ($INSUNITS): m, mm, cm, km, ft, in, us-ft");
  app.add_option("--step", options.step_m, "Distance between samples in metres (default: half the cell size)");
  app.add_option("--scene", options.scene, "Scene whose section.profile_lines[0] takes the profile")->type_name("FILE");
  app.add_option("-o,--output", options.output, "The scene file to write (with --scene)")->type_name("FILE");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? 0 : invalid_input;
  }
  try {
    return cut(options);
  } catch (const InputError& error) {
    std::cerr << "error: " << error.what() << "\n";
    return invalid_input;
  }
}
