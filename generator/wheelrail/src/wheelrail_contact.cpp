#include "ctab/wheelrail/wheelrail_contact.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numbers>

#include "ctab/contact/hertz.hpp"
#include "ctab/contact/hertz_strip.hpp"
#include "ctab/contact/root_finding.hpp"

namespace ctab::gen {

namespace {

constexpr double kFlangeRootS_m = -0.026;  // S1002 sections C-H (flange) start here
constexpr double kMinimumWindowDepth_m = 50e-6;
constexpr double kWindowFactor = 2.0;  // window depth over the expected approach

// One patch's strip problem: the plane tangent to the rail at the reference point.
struct PatchProblem {
  GapMinimum reference;
  double angle = 0, c = 1, sn = 0;
  double y0 = 0, z0 = 0;            // reference point on the rail (rail y, track z)
  GapProfile gap;                   // y_m holds s
  std::vector<double> rail_y;       // rail y below each sample
  std::unique_ptr<Mim1dSolver> solver;
  NormalSolution solution;
};

// Creates the patch's solver, or re-targets the one it already has.
bool prepare_solver(PatchProblem& p, double E_star, const Mim1dOptions& options) {
  try {
    if (p.solver && p.solver->matches(E_star, options))
      p.solver->reset(p.gap);
    else
      p.solver = std::make_unique<Mim1dSolver>(p.gap, E_star, options);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

class PatchBuilder {
 public:
  PatchBuilder(const SideGeometry& side, double dy, double roll, double z_first)
      : side_(side), dy_(dy), roll_(roll), z_first_(z_first) {}

  // Wheel surface (touching position) at rail coordinate y: Newton on S.
  WheelSurfacePoint wheel_at(double y, double& s_guess) const {
    WheelSurfacePoint w = side_.wheel_point(s_guess, dy_, roll_);
    for (int i = 0; i < 20 && std::abs(w.rail_y_m - y) > 1e-13; ++i) {
      const double dyds = std::cos(roll_) - side_.wheel().at(s_guess).dz * std::sin(roll_);
      s_guess -= (w.rail_y_m - y) / dyds;
      w = side_.wheel_point(s_guess, dy_, roll_);
    }
    w.z_m += z_first_;
    return w;
  }

  // Separation along the plane normal at plane coordinate s; false outside the profiles.
  bool sample(PatchProblem& p, double s, double& n_rail, double& n_wheel, double& s_guess, double& y_rail, double& B,
              double& A) const {
    const ProfileTable& rail = side_.rail();
    for (int i = 0; i < 30; ++i) {  // rail: z_r(y0 + s c - n sn) = z0 + s sn + n c
      const double y = p.y0 + s * p.c - n_rail * p.sn;
      if (!rail.contains(y)) return false;
      const ProfilePoint r = rail.at(y);
      const double f = r.z - (p.z0 + s * p.sn + n_rail * p.c), df = -r.dz * p.sn - p.c;
      n_rail -= f / df;
      if (std::abs(f) < 1e-14) break;
    }
    y_rail = p.y0 + s * p.c - n_rail * p.sn;
    const ProfilePoint r = rail.at(y_rail);
    WheelSurfacePoint w{};
    for (int i = 0; i < 30; ++i) {
      const double y = p.y0 + s * p.c - n_wheel * p.sn;
      if (!rail.contains(y) || !side_.wheel().contains(s_guess)) return false;
      w = wheel_at(y, s_guess);
      const double f = w.z_m - (p.z0 + s * p.sn + n_wheel * p.c), df = -w.slope * p.sn - p.c;
      n_wheel -= f / df;
      if (std::abs(f) < 1e-14) break;
    }
    if (!side_.wheel().contains(s_guess)) return false;
    // h'' = kappa (1 + n'^2)^(3/2) for each surface, n' its slope relative to the plane.
    const double tr = std::tan(std::atan(r.dz) - p.angle), tw = std::tan(std::atan(w.slope) - p.angle);
    const double gr = 1 + tr * tr, gw = 1 + tw * tw;
    B = 0.5 * (r.curvature() * gr * std::sqrt(gr) - w.curvature * gw * std::sqrt(gw));
    A = p.c / (2.0 * w.radius_m);  // rolling radius seen in the contact plane: r / cos(delta)
    return true;
  }

  // Samples h(s) outward from the reference point while h < depth.
  bool build(PatchProblem& p, double depth, double step) const {
    p.angle = p.reference.contact_angle_rad;
    p.c = std::cos(p.angle);
    p.sn = std::sin(p.angle);
    p.y0 = p.reference.rail_y_m;
    p.z0 = side_.rail().at(p.y0).z;
    p.gap.source = "wheel-rail patch";
    for (std::vector<double>* v : {&p.gap.y_m, &p.gap.h_m, &p.gap.A_per_m, &p.gap.B_per_m, &p.rail_y}) v->clear();
    // Towards -s first (then reversed), then from s = 0 towards +s: the samples come out in increasing s.
    for (int direction = -1; direction <= 1; direction += 2) {
      double n_rail = 0, n_wheel = 0, s_guess = p.reference.wheel_s_m;
      for (int k = (direction < 0 ? 1 : 0);; ++k) {
        const double s = direction * step * k;
        double y = 0, B = 0, A = 0;
        if (!sample(p, s, n_rail, n_wheel, s_guess, y, B, A)) break;
        const double h = n_rail - n_wheel;
        p.gap.y_m.push_back(s);
        p.gap.h_m.push_back(h);
        p.gap.A_per_m.push_back(A);
        p.gap.B_per_m.push_back(B);
        p.rail_y.push_back(y);
        if (h > depth || k > 4000) break;
      }
      if (direction < 0)
        for (std::vector<double>* v : {&p.gap.y_m, &p.gap.h_m, &p.gap.A_per_m, &p.gap.B_per_m, &p.rail_y})
          std::reverse(v->begin(), v->end());
    }
    return p.gap.size() >= 8;
  }

 private:
  const SideGeometry& side_;
  double dy_, roll_, z_first_;
};

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  const auto upper = std::upper_bound(x.begin(), x.end(), at);
  const std::size_t i = std::clamp<std::size_t>(static_cast<std::size_t>(upper - x.begin()), 1, x.size() - 1);
  const double t = (at - x[i - 1]) / (x[i] - x[i - 1]);
  return (1 - t) * y[i - 1] + t * y[i];
}

// Expected normal approach from Hertz with the curvatures at the gap minimum (window sizing only).
double expected_approach(const SideGeometry& side, const GapMinimum& m, double dy, double roll, double E_star,
                         LoadKind load, double value) {
  const double c = std::cos(m.contact_angle_rad);
  if (load == LoadKind::Approach) return value * c;
  const WheelSurfacePoint w = side.wheel_point(m.wheel_s_m, dy, roll);
  const double A = c / (2.0 * w.radius_m);
  const double B = std::max(0.5 * (side.rail().at(m.rail_y_m).curvature() - w.curvature), A / 20.0);
  const HertzContact h = hertz_from_load(A, B, E_star, load == LoadKind::VerticalForce ? value / std::max(c, 0.05) : value);
  return h.status == SolveStatus::Converged ? h.approach_m : 1e-4;
}

}  // namespace

struct WheelContactWorkspace::Impl {
  std::vector<GapMinimum> minima;
  std::vector<PatchProblem> pool;  // patch problems; the first `used` are this case's
  std::size_t used = 0;
  PatchProblem& acquire() { return pool[used++]; }  // the pool is sized before use
};

WheelContactWorkspace::WheelContactWorkspace() : impl_(std::make_unique<Impl>()) {}
WheelContactWorkspace::~WheelContactWorkspace() = default;
WheelContactWorkspace::WheelContactWorkspace(WheelContactWorkspace&&) noexcept = default;
WheelContactWorkspace& WheelContactWorkspace::operator=(WheelContactWorkspace&&) noexcept = default;

WheelContact solve_wheel_contact(const SideGeometry& side, double dy_m, double roll_rad, double E_star_Pa, LoadKind load,
                                 double load_value, const WheelRailOptions& options) {
  WheelContactWorkspace workspace;
  return solve_wheel_contact(side, dy_m, roll_rad, E_star_Pa, load, load_value, options, workspace);
}

WheelContact solve_wheel_contact(const SideGeometry& side, double dy_m, double roll_rad, double E_star_Pa, LoadKind load,
                                 double load_value, const WheelRailOptions& options, WheelContactWorkspace& workspace) {
  const auto start = std::chrono::steady_clock::now();
  WheelContactWorkspace::Impl& ws = workspace.impl();
  ws.used = 0;
  WheelContact result;
  result.dy_m = dy_m;
  result.roll_rad = roll_rad;
  auto finish = [&](SolveStatus status) {
    result.status = status;
    if (!is_success(status)) result.patches.clear();
    result.solve_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  };
  if (!(std::isfinite(dy_m) && std::isfinite(roll_rad) && std::isfinite(load_value) && load_value >= 0.0))
    return finish(SolveStatus::InvalidInput);
  std::vector<GapMinimum>& minima = ws.minima;
  double z_first = 0.0;
  side.gap_minima(dy_m, roll_rad, minima, z_first);
  if (minima.empty() || !std::isfinite(z_first)) return finish(SolveStatus::InvalidInput);
  result.first_contact_z_m = z_first + side.track().nominal_radius_m;
  result.rigid_contact = minima[0];
  if (load_value == 0.0) {
    result.near_misses = minima;
    return finish(SolveStatus::NoContact);
  }
  const PatchBuilder builder(side, dy_m, roll_rad, z_first);
  // At most one patch per gap minimum: size the pool now so that references into it stay valid.
  if (ws.pool.size() < minima.size()) ws.pool.resize(minima.size());
  // Window depth: twice the expected approach; doubled when a contact reaches the window's end.
  double depth = std::max(kWindowFactor * expected_approach(side, minima[0], dy_m, roll_rad, E_star_Pa, load, load_value),
                          kMinimumWindowDepth_m);
  auto inside_window = [&](const GapMinimum& m) {
    for (std::size_t k = 0; k < ws.used; ++k) {
      const PatchProblem& p = ws.pool[k];
      if (!p.rail_y.empty() && m.rail_y_m >= p.rail_y.front() && m.rail_y_m <= p.rail_y.back()) return true;
    }
    return false;
  };
  auto solve_patch = [&](PatchProblem& p, double vertical_approach) {
    const double approach = vertical_approach * p.c;
    if (options.method == NormalMethod::Hertz)
      p.solution = solve_hertz_for_approach(p.gap, E_star_Pa, options.mim1d.strip_width_m, approach);
    else
      p.solution = p.solver->solve_for_approach(approach);
    result.iterations += p.solution.iterations;
  };
  for (int attempt = 0; attempt < 4; ++attempt) {
    ws.used = 0;
    PatchProblem& main = ws.acquire();
    main.reference = minima[0];
    if (!builder.build(main, depth, options.sample_step_m)) return finish(SolveStatus::InvalidInput);
    if (!prepare_solver(main, E_star_Pa, options.mim1d)) return finish(SolveStatus::InvalidInput);
    // Single patch first: the loading condition maps directly onto the strip problem.
    if (load == LoadKind::Approach) {
      result.vertical_approach_m = load_value;
      solve_patch(main, load_value);
    } else {
      const double force = load == LoadKind::VerticalForce ? load_value / main.c : load_value;
      main.solution = options.method == NormalMethod::Hertz
                          ? solve_hertz_for_load(main.gap, E_star_Pa, options.mim1d.strip_width_m, force)
                          : main.solver->solve_for_load(force);
      result.iterations += main.solution.iterations;
      result.vertical_approach_m = main.solution.approach_m / main.c;
    }
    if (main.solution.status == SolveStatus::ZoneTruncated) {
      depth *= 2.0;
      continue;
    }
    if (!is_success(main.solution.status)) return finish(main.solution.status);
    // Further patches whose gap the approach closes.
    for (std::size_t k = 1; k < minima.size(); ++k) {
      if (minima[k].gap_m >= result.vertical_approach_m || inside_window(minima[k])) continue;
      PatchProblem& extra = ws.acquire();
      extra.reference = minima[k];
      if (!builder.build(extra, minima[k].gap_m + depth, options.sample_step_m) ||
          !prepare_solver(extra, E_star_Pa, options.mim1d))
        --ws.used;  // give the slot back
    }
    if (ws.used > 1 && load != LoadKind::Approach) {
      auto total = [&](double dz) {
        double sum = 0.0;
        for (std::size_t k = 0; k < ws.used; ++k) {
          PatchProblem& p = ws.pool[k];
          solve_patch(p, dz);
          const double n = is_success(p.solution.status) ? p.solution.normal_load_N : 0.0;
          sum += load == LoadKind::VerticalForce ? n * p.c : n;
        }
        return sum - load_value;
      };
      const double hi = result.vertical_approach_m;
      const RootResult root = find_root_bracketed(total, 0.0, -load_value, hi, total(hi), 1e-15,
                                                  options.mim1d.tolerance * load_value * 10.0, 100);
      if (!root.converged) return finish(SolveStatus::MaxIterations);
      result.vertical_approach_m = root.x;
      (void)total(root.x);
    } else if (ws.used > 1) {
      for (std::size_t k = 1; k < ws.used; ++k) solve_patch(ws.pool[k], load_value);
    }
    break;
  }
  // Collect the patches.
  SolveStatus status = SolveStatus::Converged;
  for (std::size_t slot = 0; slot < ws.used; ++slot) {
    PatchProblem& p = ws.pool[slot];
    if (p.solution.status == SolveStatus::NoContact) continue;
    if (!is_success(p.solution.status)) status = p.solution.status;
    for (const PatchSolution& ps : p.solution.patches) {
      ContactPatch out;
      // Contact point of this run: its deepest rigid point (the reference minimum for the run that holds it).
      std::size_t deepest = p.gap.size();
      for (std::size_t i = 0; i < p.gap.size(); ++i)
        if (p.gap.y_m[i] >= ps.y_min_m && p.gap.y_m[i] <= ps.y_max_m && (deepest == p.gap.size() || p.gap.h_m[i] < p.gap.h_m[deepest]))
          deepest = i;
      const bool holds_reference = ps.y_min_m <= 0.0 && ps.y_max_m >= 0.0;
      GapMinimum point = p.reference;
      if (!holds_reference && deepest < p.gap.size()) {
        double s_guess = p.reference.wheel_s_m;
        point.rail_y_m = p.rail_y[deepest];
        (void)builder.wheel_at(point.rail_y_m, s_guess);
        point.wheel_s_m = s_guess;
        point.rolling_radius_m = side.track().nominal_radius_m + side.wheel().at(s_guess).z;
      }
      out.zone = point.wheel_s_m > kFlangeRootS_m ? "tread" : "flange";
      out.normal_force_N = ps.normal_force_N;
      out.area_m2 = ps.area_m2;
      out.max_pressure_Pa = ps.max_pressure_Pa;
      out.approach_m = p.solution.approach_m;
      out.plane_angle_rad = p.angle;
      out.y_rail_m = point.rail_y_m;
      out.y_wheel_m = point.wheel_s_m;
      out.rolling_radius_m = point.rolling_radius_m;
      out.y_cop_rail_m = interpolate(p.gap.y_m, p.rail_y, ps.centre_of_pressure_y_m);
      out.s_min_m = ps.y_min_m;
      out.s_max_m = ps.y_max_m;
      // Contact angle: direction of the resultant normal force, the load-weighted mean of the rail normals.
      double weighted_angle = 0.0;
      for (const StripSolution& st : ps.strips) {
        const double y = interpolate(p.gap.y_m, p.rail_y, st.y_m);
        out.strips.push_back({st.y_m, y, st.half_length_m, st.p0_Pa});
        weighted_angle += st.load_N * std::atan(side.rail().at(y).dz);
      }
      out.contact_angle_rad = weighted_angle / ps.normal_force_N;
      result.normal_force_N += out.normal_force_N;
      result.vertical_force_N += out.normal_force_N * std::cos(out.plane_angle_rad);
      result.patches.push_back(std::move(out));
    }
  }
  for (std::size_t k = 1; k < minima.size(); ++k)
    if (minima[k].gap_m >= result.vertical_approach_m && !inside_window(minima[k])) result.near_misses.push_back(minima[k]);
  if (result.patches.empty() && status == SolveStatus::Converged) status = SolveStatus::NumericalFailure;
  return finish(status);
}

}  // namespace ctab::gen
