// Non-circular critical slip-surface search: search_noncircular().
//
// A pattern search over the vertices of a polyline, after Greco (1996, "Efficient Monte Carlo technique for
// locating critical slip surface", J. Geotech. Eng. 122(7):517-525): the vertices of a trial surface move one at a
// time, a move is kept when it lowers the factor of safety, and the move length shrinks when no vertex can
// improve. Greco draws the move directions at random; here they are fixed (each end along the ground, each inner
// vertex up, down, left and right, then the whole inner surface up and down), so that a search is reproducible,
// and a kept move is repeated with doubled length while it keeps improving (Hooke & Jeeves 1961, "Direct search"
// solution of numerical and statistical problems", J. ACM 8(2):212-229). Per method:
//   1. the method's critical circle from the circular search, inscribed as `initial_segments` chords of equal angle
//      (doubled, up to 256, while that polygon is not an admissible start);
//   2. the pattern search at that number of segments, from a move of 1/20 of the circle's entry-exit chord down to
//      `tolerance` of it;
//   3. every segment halved (a vertex at each midpoint) and step 2 again from a quarter of the previous first move,
//      until the surface has `segments` segments;
//   4. each method tries the other methods' final surfaces and continues from one that beats its own;
//   5. the surface is recomputed through the public path (slice_polyline, factor_of_safety with forces); if it does
//      not beat the critical circle, the circle is the result (from_circle).
// Bishop takes moments about the centre of its critical circle throughout (moment_point() below). The Ordinary
// method is not searched: its normal force W cos(a) - u l ignores the interslice forces, which off a circle leaves
// the base normals a moment about any point, and the search drives its factor of safety to nonsense (0.43 against
// the circle's 1.29 on Griffiths & Lane's slope); its result is its critical circle.
// Every trial surface must be admissible for slice_polyline (ends on the ground, below it, above the base,
// concave upward) and obey the entry/exit limits and the minimum depth of the circular search.
#include <chrono>

#include "search_internal.hpp"

namespace slope::detail {
namespace {

constexpr double infinite = std::numeric_limits<double>::infinity();

// The arc of a circular mass between its ends as `n` chords of equal angle, left to right.
std::vector<Point> inscribed(const SlipMass& mass, int n) {
  const Point left = mass.direction > 0 ? mass.entry : mass.exit;
  const Point right = mass.direction > 0 ? mass.exit : mass.entry;
  const Circle& c = mass.circle;
  const double t0 = std::atan2(left.x - c.xc, c.yc - left.y);
  const double t1 = std::atan2(right.x - c.xc, c.yc - right.y);
  std::vector<Point> points{left};
  for (int k = 1; k < n; ++k) {
    const double t = t0 + (t1 - t0) * k / n;
    points.push_back({c.xc + c.radius * std::sin(t), c.yc - c.radius * std::cos(t)});
  }
  points.push_back(right);
  return points;
}

// A vertex at the midpoint of every segment.
std::vector<Point> halved(const std::vector<Point>& points) {
  std::vector<Point> out;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    out.push_back(points[i]);
    out.push_back({0.5 * (points[i].x + points[i + 1].x), 0.5 * (points[i].y + points[i + 1].y)});
  }
  out.push_back(points.back());
  return out;
}

// The pattern search of one method on one polyline.
class VertexSearch {
 public:
  VertexSearch(SearchEngine& engine, std::size_t method_index, std::vector<Point> start,
               std::optional<Point> moment_point)
      : engine_(engine), method_index_(method_index), points_(std::move(start)) {
    trial_.moment_point = moment_point;
    best_ = value(points_);
  }

  double best() const { return best_; }
  const std::vector<Point>& points() const { return points_; }
  long trials() const { return trials_; }
  const std::optional<Point>& moment_point() const { return trial_.moment_point; }

  // Moves vertices from a move of `step` down to `min_step` (m).
  void optimise(double step, double min_step) {
    if (!std::isfinite(best_)) return;
    while (step >= min_step) {
      bool improved = false;
      for (std::size_t i = 0; i < points_.size(); ++i) improved |= move_vertex(i, step);
      improved |= move_inner(step);
      if (!improved) step *= 0.5;
    }
  }

  // Starts again from `points` (the same surface with more vertices, say).
  void restart(std::vector<Point> points) {
    points_ = std::move(points);
    best_ = infinite;
    best_ = value(points_);
  }

  // Continues from `other` when it beats the current surface; returns whether it did.
  bool adopt_if_better(const std::vector<Point>& other) {
    const double v = value(other);
    if (!(v < best_)) return false;
    best_ = v;
    points_ = other;
    return true;
  }

 private:
  double value(const std::vector<Point>& points) {
    ++trials_;
    trial_.points = points;
    if (engine_.admit(trial_) != SearchEngine::Admit::ok) return infinite;
    const double fs = engine_.evaluate(method_index_, std::isfinite(best_) ? best_ : 0.0);
    return std::isfinite(fs) ? fs : infinite;
  }

  // Tries the moves of one vertex; a kept move is repeated with doubled length while it improves.
  bool move_vertex(std::size_t i, double step) {
    const bool end = i == 0 || i + 1 == points_.size();
    static constexpr std::array<std::array<double, 2>, 4> directions{{{0, -1}, {0, 1}, {1, 0}, {-1, 0}}};
    for (const auto& d : directions) {
      if (end && d[0] == 0.0) continue;  // the ends move along the ground only
      double length = step;
      bool kept = false;
      while (try_move(i, d[0] * length, d[1] * length, end)) {
        kept = true;
        length *= 2.0;
      }
      if (kept) return true;
    }
    return false;
  }

  bool try_move(std::size_t i, double dx, double dy, bool end) {
    candidate_ = points_;
    candidate_[i].x += dx;
    candidate_[i].y = end ? engine_.prepared().ground_at(candidate_[i].x) : candidate_[i].y + dy;
    return keep_if_better();
  }

  // The whole inner surface down, then up, by `step`.
  bool move_inner(double step) {
    for (double dy : {-step, step}) {
      candidate_ = points_;
      for (std::size_t i = 1; i + 1 < candidate_.size(); ++i) candidate_[i].y += dy;
      if (keep_if_better()) return true;
    }
    return false;
  }

  bool keep_if_better() {
    const double v = value(candidate_);
    if (!(v < best_)) return false;
    best_ = v;
    points_.swap(candidate_);
    return true;
  }

  SearchEngine& engine_;
  std::size_t method_index_;
  std::vector<Point> points_, candidate_;
  SlipPolyline trial_;
  double best_ = infinite;
  long trials_ = 0;
};

// Bishop satisfies moment equilibrium about one point only: on a non-circular surface its factor of safety depends
// on that point, and a search that moved the point with the surface would chase the point, not the surface. It
// keeps the centre of its critical circle.
std::optional<Point> moment_point(const SlipMass& circle, Method method) {
  if (method == Method::bishop) return Point{circle.circle.xc, circle.circle.yc};
  return std::nullopt;
}

double chord_length(const std::vector<Point>& p) { return std::hypot(p.back().x - p.front().x, p.back().y - p.front().y); }

// Steps 1-3 for one method.
VertexSearch optimise_from_circle(SearchEngine& engine, std::size_t k, const SlipMass& circle,
                                  const NonCircularOptions& options) {
  int segments = std::max(2, options.initial_segments);
  VertexSearch search(engine, k, inscribed(circle, segments), moment_point(circle, engine.method(k)));
  // a thin or sharply curved mass: the coarse polygon may be shallower than the minimum depth or not admissible
  while (!std::isfinite(search.best()) && segments < 256) {
    segments *= 2;
    search.restart(inscribed(circle, segments));
  }
  const double chord = chord_length(search.points());
  double first_move = chord / 20.0;
  const double min_move = options.tolerance * chord;
  search.optimise(first_move, min_move);
  while (segments * 2 <= options.segments && std::isfinite(search.best())) {
    segments *= 2;
    first_move = std::max(first_move / 4.0, min_move);
    search.restart(halved(search.points()));
    search.optimise(first_move, min_move);
  }
  return search;
}

// Step 5 for one method: its best polyline through the public path, or its critical circle when the polyline does
// not beat it (or the method was not searched).
NonCircularSurface final_surface(const Section& section, const CriticalSurface& circle, const VertexSearch* search,
                                 const SliceOptions& slicing) {
  NonCircularSurface out;
  out.method = circle.method;
  out.circle_factor_of_safety = circle.result.factor_of_safety;
  out.searched = search != nullptr;
  if (search != nullptr) {
    out.trial_surfaces = search->trials();
    SlipPolyline surface;
    surface.points = search->points();
    surface.moment_point = search->moment_point();
    std::optional<SlipMass> mass = slice_polyline(section, surface, slicing);
    if (mass) {
      FsResult fs = factor_of_safety(*mass, circle.method, true);
      out.polyline_factor_of_safety = fs.factor_of_safety;
      if (fs.factor_of_safety && *fs.factor_of_safety < *circle.result.factor_of_safety) {
        out.mass = std::move(mass);
        out.result = std::move(fs);
      }
    }
  }
  if (!out.mass) {
    out.from_circle = circle.mass.has_value();
    out.mass = circle.mass;
    out.result = circle.result;
  }
  return out;
}

}  // namespace
}  // namespace slope::detail

namespace slope {

NonCircularResult search_noncircular(const Section& section, const SearchResult& circular,
                                     const SearchOptions& options, const NonCircularOptions& noncircular) {
  const auto started = std::chrono::steady_clock::now();
  NonCircularResult result;
  std::vector<Method> methods;
  for (const CriticalSurface& c : circular.methods) methods.push_back(c.method);
  detail::SearchEngine engine(section, methods, options);
  std::vector<std::optional<detail::VertexSearch>> searches(methods.size());
  for (std::size_t k = 0; k < methods.size(); ++k)
    if (circular.methods[k].mass && circular.methods[k].result.factor_of_safety && methods[k] != Method::ordinary)
      searches[k].emplace(detail::optimise_from_circle(engine, k, *circular.methods[k].mass, noncircular));
  // 4. each method from the other methods' surfaces
  for (std::size_t k = 0; k < methods.size(); ++k) {
    if (!searches[k]) continue;
    const double chord = detail::chord_length(searches[k]->points());
    for (std::size_t j = 0; j < methods.size(); ++j)
      if (j != k && searches[j] && searches[k]->adopt_if_better(searches[j]->points()))
        searches[k]->optimise(chord / 80.0, noncircular.tolerance * chord);
  }
  // 5. the result per method, through the public path
  for (std::size_t k = 0; k < methods.size(); ++k) {
    NonCircularSurface out = detail::final_surface(section, circular.methods[k],
                                                   searches[k] ? &*searches[k] : nullptr, options.slicing);
    result.trial_surfaces += out.trial_surfaces;
    result.methods.push_back(std::move(out));
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

}  // namespace slope
