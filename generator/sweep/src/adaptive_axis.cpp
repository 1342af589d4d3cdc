// SPDX-License-Identifier: Apache-2.0
// The error-controlled dy axis (adaptive_axis.hpp): refinement rounds, then the symmetric node set of a mirrored
// sweep and the cells' errors on the final axis.
#include "adaptive_axis.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "ctab/sweep/cell_error.hpp"
#include "parallel_loop.hpp"

namespace ctab::gen::detail {

namespace {

// A split cell whose thirds' error is not below this share of its own has reached the solver's own scatter (the
// strips entering and leaving a patch): its error no longer falls with the step, and refining further would only
// chase it. A smooth function's error falls to 1/9 per split, a kink's to 1/3. Chosen: 0.6.
constexpr double kNoiseDecay = 0.6;

// Smallest half width of a roll guess's first bracket [rad] (RollGuess::spread_rad).
constexpr double kMinRollSpread_rad = 1e-6;

// Two nodes closer than this are one (a mirrored node and its image from the other side) [m].
constexpr double kSameNode_m = 1e-12;

// One solved lateral shift: every load of every solved side (side * n_loads + load).
struct Point {
  double dy_m = 0.0;
  std::optional<RollGuess> guess;  // from the neighbours' rolls: a faster search, the same roll (rigid_wheelset_pose)
  CaseRoll roll;
  std::vector<CaseWheel> wheels;
  std::vector<WheelSample> samples;
};

// A decided cell between two points, with its errors (n_loads x kCellErrorQuantities).
struct Cell {
  std::size_t a = 0, b = 0;
  std::vector<double> errors;
};

struct Context {
  const SweepSetup& setup;
  const SweepPlan& plan;
  const AxisTolerance& tolerance;
  tables::Table scratch;  // one row of the table's shape: the zone-rule slots of a sample
  [[nodiscard]] std::size_t loads() const noexcept { return plan.load_values.size(); }
  [[nodiscard]] std::size_t per_point() const noexcept { return plan.sides * loads(); }
};

// Solves points[first..] (their dy set), one task per point (its roll, every wheel solve, the samples: one barrier
// per round), dynamically scheduled.
void solve_points(const Context& c, std::vector<Point>& points, std::size_t first) {
  const std::size_t per_point = c.per_point(), loads = c.loads();
  std::vector<WheelContactWorkspace> workspaces(static_cast<std::size_t>(c.plan.threads));
  parallel_loop(points.size() - first, c.plan.threads, true, [&](std::size_t k) {
    Point& p = points[first + k];
    WheelContactWorkspace& workspace = workspaces[static_cast<std::size_t>(omp_get_thread_num())];
    p.roll = solve_case_roll(c.setup, p.dy_m, p.guess ? &*p.guess : nullptr);
    p.wheels.resize(per_point);
    p.samples.resize(per_point);
    tables::Table scratch = c.scratch;
    for (std::size_t r = 0; r < per_point; ++r) {
      p.wheels[r] = solve_case_wheel(c.setup, r / loads, p.dy_m, p.roll, c.plan.load_values[r % loads], workspace);
      store_case_wheel(scratch, c.setup, 0, r % loads, r / loads, p.wheels[r]);
      p.samples[r] = wheel_sample(scratch, 0, r % loads, r / loads);
    }
  });
}

bool any_discontinuous(const Context& c, const Point& a, const Point& b) {
  for (std::size_t r = 0; r < c.per_point(); ++r)
    if (discontinuous(a.samples[r], b.samples[r], c.tolerance)) return true;
  return false;
}

struct Check {
  std::vector<double> errors;
  bool jump = false;
  double worst = 0.0;  // largest error / tolerance
};

// The checks c1, c2 of cell (a, b): a jump between any two neighbouring samples, else the interpolation errors.
Check check_cell(const Context& c, const Point& a, const Point& c1, const Point& c2, const Point& b) {
  Check check;
  check.errors.assign(c.loads() * tables::kCellErrorQuantities, 0.0);
  check.jump = any_discontinuous(c, a, c1) || any_discontinuous(c, c1, c2) || any_discontinuous(c, c2, b);
  if (check.jump) return check;
  for (std::size_t r = 0; r < c.per_point(); ++r)
    for (const Point* inner : {&c1, &c2}) {
      const double t = (inner->dy_m - a.dy_m) / (b.dy_m - a.dy_m);
      const CellErrors e = interpolation_error(a.samples[r], b.samples[r], inner->samples[r], t);
      check.worst = std::max(check.worst, tolerance_ratio(e, c.tolerance));
      double* const out = &check.errors[(r % c.loads()) * tables::kCellErrorQuantities];
      for (std::size_t q = 0; q < tables::kCellErrorQuantities; ++q) out[q] = std::max(out[q], e[q]);
    }
  return check;
}

void release(Point& p) {
  p.wheels = {};
  p.samples = {};
}

// Refines the cells between consecutive points (the coarse axis, already solved) round by round; the decided
// cells in axis order.
std::vector<Cell> refine(const Context& c, std::vector<Point>& points) {
  const std::vector<double> unmeasured(c.loads() * tables::kCellErrorQuantities, tables::kCellNotMeasured);
  struct Open {
    std::size_t a, b;
    double parent_worst;  // the split cell's error / tolerance (infinite: none, or a jump)
  };
  constexpr double kNone = std::numeric_limits<double>::infinity();
  std::vector<Open> open;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) open.push_back({i, i + 1, kNone});
  std::vector<Cell> cells;
  while (!open.empty()) {
    std::vector<Open> checked;
    const std::size_t first = points.size();
    for (const auto& [a, b, parent_worst] : open) {
      const double low = points[a].dy_m, width = points[b].dy_m - low;
      const bool jump = any_discontinuous(c, points[a], points[b]);
      if (width <= tables::kJumpCellWidth_m || (!jump && width < c.tolerance.min_step_m)) {
        cells.push_back({a, b, unmeasured});
        continue;
      }
      checked.push_back({a, b, parent_worst});
      const double roll_a = points[a].roll.roll_rad, roll_b = points[b].roll.roll_rad;
      const double spread = std::max(std::abs(roll_b - roll_a), kMinRollSpread_rad);
      points.push_back({low + width / 3.0, RollGuess{roll_a + (roll_b - roll_a) / 3.0, spread}, {}, {}, {}});
      points.push_back({low + 2.0 * width / 3.0, RollGuess{roll_a + 2.0 * (roll_b - roll_a) / 3.0, spread}, {}, {}, {}});
    }
    solve_points(c, points, first);
    open.clear();
    for (std::size_t j = 0; j < checked.size(); ++j) {
      const auto [a, b, parent_worst] = checked[j];
      const std::size_t c1 = first + 2 * j, c2 = c1 + 1;
      Check check = check_cell(c, points[a], points[c1], points[c2], points[b]);
      const double third = (points[b].dy_m - points[a].dy_m) / 3.0;
      const bool falling = check.worst <= kNoiseDecay * parent_worst;
      if (check.jump || (check.worst > 1.0 && third >= c.tolerance.min_step_m && falling)) {
        const double worst = check.jump ? kNone : check.worst;
        open.insert(open.end(), {{a, c1, worst}, {c1, c2, worst}, {c2, b, worst}});
      } else {
        cells.push_back({a, b, std::move(check.errors)});
        release(points[c1]);
        release(points[c2]);
      }
    }
  }
  std::sort(cells.begin(), cells.end(),
            [&](const Cell& x, const Cell& y) { return points[x.a].dy_m < points[y.a].dy_m; });
  return cells;
}

// The nodes of decided cells (points, increasing dy).
std::vector<std::size_t> nodes_of(const std::vector<Cell>& cells) {
  std::vector<std::size_t> nodes;
  for (const Cell& cell : cells) nodes.push_back(cell.a);
  if (!cells.empty()) nodes.push_back(cells.back().b);
  return nodes;
}

// The node (a point of `nodes`) within kSameNode_m of `dy`, or points.size().
std::size_t node_at(const std::vector<Point>& points, const std::vector<std::size_t>& nodes, double dy) {
  const auto at = std::lower_bound(nodes.begin(), nodes.end(), dy - kSameNode_m,
                                   [&](std::size_t node, double v) { return points[node].dy_m < v; });
  return at != nodes.end() && points[*at].dy_m <= dy + kSameNode_m ? *at : points.size();
}

// A mirrored sweep's nodes: each node's image -dy joins (a node already within kSameNode_m is kept), solved in one
// more round; the result is symmetric to kSameNode_m.
std::vector<std::size_t> mirror_closed(const Context& c, std::vector<Point>& points,
                                       const std::vector<std::size_t>& nodes) {
  std::vector<double> magnitudes;
  for (const std::size_t node : nodes) magnitudes.push_back(std::abs(points[node].dy_m));
  std::sort(magnitudes.begin(), magnitudes.end());
  std::vector<double> targets;
  for (const double m : magnitudes)
    if (targets.empty() || m - targets.back() > 3.0 * kSameNode_m) targets.push_back(m);
  std::vector<double> all;  // -m descending, then +m ascending (0 once)
  for (auto m = targets.rbegin(); m != targets.rend(); ++m)
    if (*m > kSameNode_m) all.push_back(-*m);
  all.insert(all.end(), targets.begin(), targets.end());
  const std::size_t first = points.size();
  std::vector<std::size_t> closed;
  for (const double dy : all) {
    std::size_t node = node_at(points, nodes, dy);
    if (node >= first) {  // not a node yet: its image's roll mirrored is the guess
      const std::size_t image = node_at(points, nodes, -dy);
      std::optional<RollGuess> guess;
      if (image < first) guess = RollGuess{-points[image].roll.roll_rad, kMinRollSpread_rad};
      node = points.size();
      points.push_back({dy, guess, {}, {}, {}});
    }
    closed.push_back(node);
  }
  solve_points(c, points, first);
  return closed;
}

// The decided cell (index in `cells`) that contains dy.
std::size_t cell_containing(const std::vector<Point>& points, const std::vector<Cell>& cells, double dy) {
  const auto after = std::upper_bound(cells.begin(), cells.end(), dy,
                                      [&](double v, const Cell& cell) { return v < points[cell.a].dy_m; });
  return after == cells.begin() ? 0 : static_cast<std::size_t>(after - cells.begin()) - 1;
}

// Errors of the final cells: of the decided cell each lies in and, mirrored, of the one its image lies in (the
// larger; unmeasured where either is).
std::vector<double> final_errors(const Context& c, const std::vector<Point>& points, const std::vector<Cell>& cells,
                                 const std::vector<std::size_t>& nodes) {
  const std::size_t per_cell = c.loads() * tables::kCellErrorQuantities;
  std::vector<double> errors;
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
    const double middle = 0.5 * (points[nodes[i]].dy_m + points[nodes[i + 1]].dy_m);
    const std::vector<double>& own = cells[cell_containing(points, cells, middle)].errors;
    const std::vector<double>& image = c.plan.mirrored ? cells[cell_containing(points, cells, -middle)].errors : own;
    for (std::size_t e = 0; e < per_cell; ++e)
      errors.push_back(own[e] == tables::kCellNotMeasured || image[e] == tables::kCellNotMeasured
                           ? tables::kCellNotMeasured
                           : std::max(own[e], image[e]));
  }
  return errors;
}

tables::Table scratch_table(const TableConfig& config, const SweepPlan& plan) {
  tables::Table t;
  t.lateral_displacement_m = {0.0};
  t.second_axis = plan.load_values;
  t.n_slots = config.patch_slots;
  t.strip_samples = config.strip_samples;
  t.allocate();
  return t;
}

}  // namespace

AdaptiveAxis decide_adaptive_axis(const TableConfig& config, const SweepSetup& setup, const SweepPlan& plan) {
  const Context c{setup, plan, *config.axis_tolerance, scratch_table(config, plan)};
  std::vector<Point> points;
  for (const double dy : plan.dy_m) points.push_back({dy, std::nullopt, {}, {}, {}});
  solve_points(c, points, 0);
  const std::vector<Cell> cells = refine(c, points);
  std::vector<std::size_t> nodes = nodes_of(cells);
  if (plan.mirrored) nodes = mirror_closed(c, points, nodes);
  AdaptiveAxis axis;
  axis.coarse_points = plan.dy_m.size();
  axis.solved_points = points.size();
  axis.cell_error = final_errors(c, points, cells, nodes);
  const std::size_t n = nodes.size(), loads = c.loads();
  axis.results.resize(plan.sides * n * loads);
  for (std::size_t k = 0; k < n; ++k) {
    Point& p = points[nodes[k]];
    axis.dy_m.push_back(p.dy_m);
    axis.rolls.push_back(p.roll);
    for (std::size_t r = 0; r < c.per_point(); ++r)
      axis.results[(r / loads) * n * loads + k * loads + r % loads] = std::move(p.wheels[r]);
  }
  return axis;
}

}  // namespace ctab::gen::detail
