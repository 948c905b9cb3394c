#pragma once
// Limits on hostile input: every size of a scene file that has no physical reason to be large is bounded, so a
// crafted file is refused (exit status 2, a message naming the JSON path, the limit and why) instead of
// overflowing the stack, exhausting memory or keeping the program busy for hours. The limits are far above anything
// a real scene needs; docs/reliability.md ("Limits on hostile input") lists them with the same reasons.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace coupling {

// Largest scene file read. A surveyed profile of 1 000 000 vertices is about 25 MB of text; the parsed JSON takes
// up to some 16 bytes of memory per byte of text (a number is a 16-byte value), so this keeps a hostile file below
// about 2 GiB of memory. Checked before the file is read.
inline constexpr std::uintmax_t max_scene_file_bytes = 128u * 1024u * 1024u;
inline constexpr std::string_view max_scene_file_reason =
    "a surveyed profile of 1 000 000 points is about 25 MB; the parsed document needs up to 16 times its size in "
    "memory";

// Deepest nesting of objects and arrays. A scene nests 6 levels (the top level, section, profile_lines, a line,
// points_m, a point); free-form "notes" may nest more, but not hundreds of levels. Copying and printing a JSON value
// (nlohmann::json) recurse once per level, so a file nested 300 000 levels deep overflowed the stack. Checked on the
// text, before parsing.
inline constexpr std::size_t max_nesting_depth = 256;
inline constexpr std::string_view max_nesting_reason =
    "a scene nests 6 levels; each level costs stack space when the document is copied or printed";

// Most elements of an array of the scene. `what` names the elements in the message, `reason` says why the limit is
// safe; both are shown to the user:
//   section.profile_lines[0].points_m: too many points (got 1000001; at most 1000000 allowed: ...)
struct SizeLimit {
  std::size_t max;
  std::string_view what;
  std::string_view reason;
};

namespace limits {

// section.profile_lines[i].points_m and section.water.piezometric_line_m.
inline constexpr SizeLimit polyline_points{
    1'000'000, "points",
    "surveyed profiles have up to some 100 000 vertices; every point is checked against the other lines"};
// section.profile_lines: the crossing check compares every pair of lines.
inline constexpr SizeLimit profile_lines{
    200, "profile lines", "a section has a few dozen layers at most; every pair of lines is checked for crossings"};
// section.materials.
inline constexpr SizeLimit materials{
    1000, "materials", "a section has a few dozen soils at most; each one is a material of the SPH model"};
// section.surcharges: each strip load is integrated over every slice of every trial surface.
inline constexpr SizeLimit surcharges{
    1000, "surcharges", "each strip load is integrated over every slice of every trial surface"};
// section.line_loads: every load is placed on every trial surface.
inline constexpr SizeLimit line_loads{1000, "line loads", "every line load is placed on every trial surface"};
// section.reinforcement: every element is intersected with every trial surface.
inline constexpr SizeLimit reinforcement{
    1000, "reinforcement elements", "every element is intersected with every trial surface of the search"};
// analyses.lem.surfaces: each surface is sliced and solved with every method.
inline constexpr SizeLimit slip_surfaces{
    100, "surfaces", "each given slip surface is sliced and solved with every method, and reported slice by slice"};
// analyses.lem.surfaces[i].points_m: every vertex is a slice boundary.
inline constexpr SizeLimit slip_surface_points{
    10'000, "points", "every vertex of a slip surface is a slice boundary: a surface of 10 000 slices is far finer "
                      "than the method of slices needs"};
// analyses.lem.probabilistic.variables: every sample draws each variable.
inline constexpr SizeLimit random_variables{
    50, "variables", "every sample draws each variable, and a Latin hypercube keeps a permutation of the samples for "
                     "each"};
// analyses.lem.probabilistic.correlations: each joins two variables.
inline constexpr SizeLimit random_correlations{
    50, "correlations", "each correlation joins two of the variables, of which there are 50 at most"};
// bodies: each body is filled with particles separately.
inline constexpr SizeLimit bodies{1000, "bodies", "each body is filled with particles and checked separately"};
// bodies[i].polygon_m: filling tests lattice points against the polygon's edges.
inline constexpr SizeLimit polygon_vertices{
    100'000, "vertices", "particles are placed by testing lattice points against every edge of the polygon"};
// Lists of names in which each name may appear once: analyses.lem.methods (7 names), analyses.sph.ignore_loads (3),
// analyses.sph.walls.sides (3), analyses.compare.acceptance.methods (7).
inline constexpr SizeLimit name_list{
    64, "names", "each name may be listed once, and no list has more than seven names to choose from"};
// analyses.isph.solids: each solid is filled with wall particles separately.
inline constexpr SizeLimit solids{1000, "solids", "each solid is filled with wall particles and checked separately"};

}  // namespace limits

// Most faults printed for one scene; the rest are counted ("... and 12345 more faults"). A hostile file with a
// million bad points would otherwise print a million lines.
inline constexpr std::size_t max_reported_faults = 200;

// The first place where `text`, read as JSON, nests objects and arrays deeper than `max_depth`, as a message
// "<JSON path>: nested deeper than 256 levels (...)"; nullopt when it does not. Looks only at brackets outside
// strings, so it never recurses and costs one pass over the text; it does not validate the JSON otherwise.
std::optional<std::string> nesting_depth_fault(std::string_view text, std::size_t max_depth = max_nesting_depth);

}  // namespace coupling
