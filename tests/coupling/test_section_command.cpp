// sphslope section: a ground profile cut out of a raster along a line, on rasters the test writes (ESRI ASCII grids,
// with a .prj for the coordinate system, and a GDAL VRT for an elevation unit). Reference: a plane z = a + b x + c y,
// which bilinear interpolation between cell centres reproduces exactly, so every sample is the closed form to the
// 1 mm the profile is rounded to.
#include "test_paths.hpp"
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "test_support.hpp"

namespace test_section_command {

namespace fs = std::filesystem;

namespace {

// The plane's elevation (m) at (x, y).
double plane(double x, double y) { return 100.0 + 0.5 * (x - 1000.0) - 0.25 * (y - 2000.0); }

// An ASCII grid of 6 x 5 cells of 2 m, lower-left corner (1000, 2000), holding the plane at the cell centres;
// `hole`: the cell at column 2, row 1 (from the top) holds no data.
void write_grid(const fs::path& file, bool hole = false) {
  std::ofstream out(file);
  out << "ncols 6\nnrows 5\nxllcorner 1000\nyllcorner 2000\ncellsize 2\nNODATA_value -9999\n";
  for (int row = 0; row < 5; ++row) {
    const double y = 2000.0 + (5 - row - 0.5) * 2.0;
    for (int column = 0; column < 6; ++column) {
      const double x = 1000.0 + (column + 0.5) * 2.0;
      out << (hole && row == 1 && column == 2 ? -9999.0 : plane(x, y)) << (column == 5 ? "\n" : " ");
    }
  }
}

const char* const utm33n =
    "PROJCS[\"WGS_1984_UTM_Zone_33N\",GEOGCS[\"GCS_WGS_1984\",DATUM[\"D_WGS_1984\",SPHEROID[\"WGS_1984\",6378137,"
    "298.257223563]],PRIMEM[\"Greenwich\",0],UNIT[\"Degree\",0.0174532925199433]],PROJECTION[\"Transverse_Mercator\"],"
    "PARAMETER[\"False_Easting\",500000],PARAMETER[\"False_Northing\",0],PARAMETER[\"Central_Meridian\",15],"
    "PARAMETER[\"Scale_Factor\",0.9996],PARAMETER[\"Latitude_Of_Origin\",0],UNIT[\"Meter\",1]]";
const char* const wgs84 =
    "GEOGCS[\"GCS_WGS_1984\",DATUM[\"D_WGS_1984\",SPHEROID[\"WGS_1984\",6378137,298.257223563]],PRIMEM[\"Greenwich\","
    "0],UNIT[\"Degree\",0.0174532925199433]]";

struct Profile {
  std::vector<double> x, y;
};

// The CSV rows after the "x_m,y_m" header in the program's output (its notes on stderr come with it).
Profile csv_rows(const std::string& output) {
  Profile p;
  std::istringstream in(output);
  std::string line;
  bool header = false;
  while (std::getline(in, line)) {
    if (line == "x_m,y_m") {
      header = true;
      continue;
    }
    if (!header || line.rfind("section:", 0) == 0) continue;
    const auto comma = line.find(',');
    if (comma == std::string::npos) continue;
    p.x.push_back(std::stod(line.substr(0, comma)));
    p.y.push_back(std::stod(line.substr(comma + 1)));
  }
  return p;
}

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

}  // namespace

TEST_CASE("section: a profile cut out of a raster along a line is the plane it holds, to 1 mm", "[section][cli]") {
  TemporaryFolder folder("section-plane");
  write_grid(folder.path / "plane.asc");
  std::ofstream(folder.path / "plane.prj") << utm33n;
  // from (1001, 2001) to (1011, 2009): 12.806 m, a sample every 2 m and one at the end
  const ProgramRun run = run_sphslope("section " + quoted(folder.path / "plane.asc") + " --line 1001,2001,1011,2009 --step 2");
  INFO(run.output);
  REQUIRE(run.status == 0);
  CHECK(run.output.find("coordinate system WGS 84 / UTM zone 33N, coordinates in metre") != std::string::npos);
  CHECK(run.output.find("the elevations carry no unit; they are taken as metres") != std::string::npos);
  const Profile p = csv_rows(run.output);
  const double length = std::hypot(10.0, 8.0);
  REQUIRE(p.x.size() == 8);  // 0, 2, ..., 12 and the end
  for (std::size_t i = 0; i < p.x.size(); ++i) {
    const double d = i + 1 < p.x.size() ? 2.0 * i : length;
    const double z = plane(1001.0 + 10.0 * d / length, 2001.0 + 8.0 * d / length);
    CHECK(std::abs(p.x[i] - d) <= 0.0005);
    CHECK(std::abs(p.y[i] - z) <= 0.0005 + 1e-9);
  }
  // a line of two segments, at the default step (half the 2 m cell): its distance runs on across the corner
  const ProgramRun bent =
      run_sphslope("section " + quoted(folder.path / "plane.asc") + " --line 1002,2002,1010,2002,1010,2008");
  REQUIRE(bent.status == 0);
  const Profile b = csv_rows(bent.output);
  REQUIRE(b.x.size() == 15);  // 0 to 14 m every 1 m
  CHECK(b.y[8] == Approx(plane(1010.0, 2002.0)).margin(0.0005));
  CHECK(b.y[14] == Approx(plane(1010.0, 2008.0)).margin(0.0005));
}

TEST_CASE("section: coordinates in US survey feet and elevations in feet are converted to metres", "[section][cli]") {
  TemporaryFolder folder("section-feet");
  write_grid(folder.path / "plane.asc");
  std::string feet = utm33n;
  feet.replace(feet.find("UNIT[\"Meter\",1]"), 15, "UNIT[\"Foot_US\",0.3048006096012192]");
  std::ofstream(folder.path / "plane.prj") << feet;
  const ProgramRun run = run_sphslope("section " + quoted(folder.path / "plane.asc") + " --line 1001,2001,1011,2009 --step 1");
  INFO(run.output);
  REQUIRE(run.status == 0);
  const Profile p = csv_rows(run.output);
  CHECK(p.x.back() == Approx(std::hypot(10.0, 8.0) * 1200.0 / 3937.0).margin(0.0005));
  // the elevations' unit from a VRT over the grid: feet
  std::ofstream(folder.path / "feet.vrt")
      << "<VRTDataset rasterXSize=\"6\" rasterYSize=\"5\"><GeoTransform>1000, 2, 0, 2010, 0, -2</GeoTransform>"
         "<VRTRasterBand dataType=\"Float64\" band=\"1\"><UnitType>ft</UnitType><SimpleSource><SourceFilename "
         "relativeToVRT=\"1\">plane.asc</SourceFilename><SourceBand>1</SourceBand></SimpleSource></VRTRasterBand>"
         "</VRTDataset>";
  const ProgramRun vrt = run_sphslope("section " + quoted(folder.path / "feet.vrt") + " --line 1001,2001,1011,2009 --step 1");
  INFO(vrt.output);
  REQUIRE(vrt.status == 0);
  CHECK(vrt.output.find("elevations in feet, converted to metres") != std::string::npos);
  CHECK(csv_rows(vrt.output).y.front() == Approx(plane(1001.0, 2001.0) * 0.3048).margin(0.0005));
}

TEST_CASE("section: the profile goes into a copy of a scene that sphslope checks", "[section][cli]") {
  TemporaryFolder folder("section-scene");
  write_grid(folder.path / "plane.asc");
  const nlohmann::json scene = {
      {"format", "sphslope-scene/1"},
      {"name", "a slope cut out of a raster"},
      {"section",
       {{"bottom_y_m", 90},
        {"profile_lines", {{{"material", "soil"}, {"points_m", {{0, 100}, {1, 100}}}}}},
        {"materials", {{{"name", "soil"}, {"unit_weight_kN_m3", 20}, {"cohesion_kPa", 10}, {"friction_angle_deg", 20}}}}}},
      {"analyses", {{"lem", nlohmann::json::object()}}}};
  std::ofstream(folder.path / "in.json") << scene.dump(2);
  const ProgramRun run = run_sphslope("section " + quoted(folder.path / "plane.asc") + " --line 1011,2009,1001,2001 --scene " +
                                      quoted(folder.path / "in.json") + " -o " + quoted(folder.path / "out.json"));
  INFO(run.output);
  REQUIRE(run.status == 0);
  const nlohmann::json written = read_json(folder.path / "out.json");
  const nlohmann::json& points = written["section"]["profile_lines"][0]["points_m"];
  REQUIRE(points.size() == 14);  // every 1 m over 12.806 m, and the end
  CHECK(points[0][1].get<double>() == Approx(plane(1011.0, 2009.0)).margin(0.0005));
  CHECK(written["section"]["materials"] == scene["section"]["materials"]);  // the rest is kept
  const ProgramRun check = run_sphslope("check " + quoted(folder.path / "out.json"));
  INFO(check.output);
  CHECK(check.status == 0);
}

TEST_CASE("section: bad rasters and lines exit 2 naming what is wrong", "[section][cli]") {
  TemporaryFolder folder("section-bad");
  write_grid(folder.path / "plane.asc");
  write_grid(folder.path / "hole.asc", /*hole=*/true);
  write_grid(folder.path / "geo.asc");
  std::ofstream(folder.path / "geo.prj") << wgs84;
  std::ofstream(folder.path / "text.asc") << "not a raster\n";
  const struct {
    std::string arguments, message;
  } cases[] = {
      {quoted(folder.path / "plane.asc") + " --line 1001,2001,1013,2009",
       "--line: vertex 1 (1013, 2009) lies outside the raster's cell centres (x 1001 to 1011, y 2001 to 2009)"},
      {quoted(folder.path / "hole.asc") + " --line 1001,2007,1011,2007", "--line: the line crosses cells without data at"},
      {quoted(folder.path / "geo.asc") + " --line 1001,2001,1011,2009", "longitude and latitude in degrees (WGS 84)"},
      {quoted(folder.path / "text.asc") + " --line 1001,2001,1011,2009", "not a raster GDAL can read"},
      {quoted(folder.path / "plane.asc") + " --line 1001,2001,1011", "--line: give the line's vertices as X0,Y0,X1,Y1"},
      {quoted(folder.path / "plane.asc") + " --line 1001,2001,1011,2009 --step 0.0001", "--step: must be at least 0.001 m"},
      {quoted(folder.path / "plane.asc") + " --line 1001,2001,1011,2009 --scene x.json", "--scene and -o go together"},
  };
  for (const auto& c : cases) {
    const ProgramRun run = run_sphslope("section " + c.arguments);
    INFO(c.arguments);
    INFO(run.output);
    CHECK(run.status == 2);
    CHECK(run.output.find("error: ") != std::string::npos);
    CHECK(run.output.find(c.message) != std::string::npos);
  }
}

namespace {

// A DXF drawing of Griffiths & Lane's 2:1 slope: the ground as an LWPOLYLINE drawn from right to left on layer
// GROUND, a layer boundary as a POLYLINE on CLAY, the piezometric line as a LINE on WATER; $INSUNITS `units` (none
// when 0); `extra`: one more entity section text (e.g. a second line on a layer).
void write_drawing(const fs::path& file, int units, const std::string& extra = "") {
  std::ofstream out(file);
  auto pair = [&](int code, const std::string& value) { out << code << "\n" << value << "\n"; };
  pair(0, "SECTION");
  pair(2, "HEADER");
  if (units != 0) {
    pair(9, "$INSUNITS");
    pair(70, std::to_string(units));
  }
  pair(0, "ENDSEC");
  pair(0, "SECTION");
  pair(2, "ENTITIES");
  pair(0, "LWPOLYLINE");
  pair(8, "GROUND");
  pair(90, "4");
  pair(70, "0");
  for (const auto& [x, y] : std::vector<std::pair<int, int>>{{52, 0}, {32, 0}, {12, 10}, {0, 10}}) {
    pair(10, std::to_string(x));
    pair(20, std::to_string(y));
  }
  pair(0, "POLYLINE");
  pair(8, "CLAY");
  pair(66, "1");
  pair(70, "0");
  for (const auto& [x, y] : std::vector<std::pair<int, int>>{{0, 4}, {52, -4}}) {
    pair(0, "VERTEX");
    pair(8, "CLAY");
    pair(10, std::to_string(x));
    pair(20, std::to_string(y));
  }
  pair(0, "SEQEND");
  pair(0, "LINE");
  pair(8, "WATER");
  pair(10, "0");
  pair(20, "8");
  pair(11, "52");
  pair(21, "0");
  out << extra;
  pair(0, "ENDSEC");
  pair(0, "EOF");
}

const nlohmann::json drawn_scene = {
    {"format", "sphslope-scene/1"},
    {"name", "a drawn section"},
    {"section",
     {{"bottom_y_m", -10},
      {"profile_lines", {{{"material", "soil"}, {"points_m", {{0, 1}, {1, 1}}}}}},
      {"materials",
       {{{"name", "soil"}, {"unit_weight_kN_m3", 20}, {"cohesion_kPa", 10}, {"friction_angle_deg", 20}},
        {{"name", "clay"}, {"unit_weight_kN_m3", 18}, {"cohesion_kPa", 20}, {"friction_angle_deg", 0}}}}}},
    {"analyses", {{"lem", nlohmann::json::object()}}}};

}  // namespace

TEST_CASE("section: a drawn section's layers become the scene's profile lines and piezometric line", "[section][cli]") {
  TemporaryFolder folder("section-drawing");
  write_drawing(folder.path / "slope.dxf", 6);  // $INSUNITS 6: metres
  std::ofstream(folder.path / "in.json") << drawn_scene.dump(2);
  const std::string into = " --scene " + quoted(folder.path / "in.json") + " -o " + quoted(folder.path / "out.json");
  const ProgramRun run = run_sphslope("section " + quoted(folder.path / "slope.dxf") +
                                      " --profile GROUND --profile CLAY=clay --water WATER" + into);
  INFO(run.output);
  REQUIRE(run.status == 0);
  const nlohmann::json section = read_json(folder.path / "out.json")["section"];
  const nlohmann::json ground = {{0.0, 10.0}, {12.0, 10.0}, {32.0, 0.0}, {52.0, 0.0}};  // reversed: x increasing
  CHECK(section["profile_lines"][0]["points_m"] == ground);
  CHECK(section["profile_lines"][0]["material"] == "soil");  // the scene's
  CHECK(section["profile_lines"][1]["points_m"] == nlohmann::json({{0.0, 4.0}, {52.0, -4.0}}));
  CHECK(section["profile_lines"][1]["material"] == "clay");
  CHECK(section["water"]["piezometric_line_m"] == nlohmann::json({{0.0, 8.0}, {52.0, 0.0}}));
  const ProgramRun lem = run_sphslope("lem " + quoted(folder.path / "out.json"));
  INFO(lem.output);
  CHECK(lem.status == 0);
  // a drawing in millimetres without $INSUNITS: refused until --units says so
  write_drawing(folder.path / "mm.dxf", 0);
  const std::string mm = "section " + quoted(folder.path / "mm.dxf") + " --profile GROUND" + into;
  const ProgramRun unstated = run_sphslope(mm);
  CHECK(unstated.status == 2);
  CHECK(unstated.output.find("the drawing states no length unit ($INSUNITS 0); give it with --units") !=
        std::string::npos);
  REQUIRE(run_sphslope(mm + " --units mm").status == 0);
  CHECK(read_json(folder.path / "out.json")["section"]["profile_lines"][0]["points_m"][1] ==
        nlohmann::json({0.012, 0.01}));
}

TEST_CASE("section: bad drawings exit 2 naming the layer", "[section][cli]") {
  TemporaryFolder folder("section-bad-drawing");
  std::ofstream(folder.path / "in.json") << drawn_scene.dump(2);
  const std::string into = " --scene " + quoted(folder.path / "in.json") + " -o " + quoted(folder.path / "out.json");
  write_drawing(folder.path / "slope.dxf", 6);
  write_drawing(folder.path / "twice.dxf", 6, "0\nLINE\n8\nWATER\n10\n0\n20\n9\n11\n52\n21\n1\n");
  write_drawing(folder.path / "back.dxf", 6,
                "0\nLWPOLYLINE\n8\nBACK\n90\n3\n70\n0\n10\n0\n20\n0\n10\n5\n20\n1\n10\n3\n20\n2\n");
  const struct {
    std::string arguments, message;
  } cases[] = {
      {quoted(folder.path / "slope.dxf") + " --profile ROCK" + into,
       "no polyline on layer \"ROCK\" (layers with lines: CLAY, GROUND, WATER)"},
      {quoted(folder.path / "twice.dxf") + " --profile GROUND --water WATER" + into,
       "layer \"WATER\" holds 2 lines; join them into one polyline"},
      {quoted(folder.path / "back.dxf") + " --profile BACK" + into, "turns back at vertex 2 (3, 2) m"},
      {quoted(folder.path / "slope.dxf") + " --profile GROUND --profile CLAY" + into,
       "has no section.profile_lines[1] to take its material from"},
      {quoted(folder.path / "slope.dxf") + " --profile GROUND", "a drawing goes into a scene"},
      {quoted(folder.path / "slope.dxf") + " --profile GROUND --units yards" + into, "--units: \"yards\" is not"},
  };
  for (const auto& c : cases) {
    const ProgramRun run = run_sphslope("section " + c.arguments);
    INFO(c.arguments);
    INFO(run.output);
    CHECK(run.status == 2);
    CHECK(run.output.find(c.message) != std::string::npos);
  }
}

}  // namespace test_section_command
