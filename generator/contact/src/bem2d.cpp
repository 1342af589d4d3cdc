// SPDX-License-Identifier: Apache-2.0
// bem2d driver: input checks, the potential-area grid (rebuilt larger when a prescribed load needs more), the
// constrained CG and the result. Method and statuses: ctab/contact/bem2d.hpp.
#include "ctab/contact/bem2d.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <new>

#include "bem2d_internal.hpp"
#include "ctab/contact/hertz.hpp"

namespace ctab::gen {

namespace {

using bem2d::Prescribed;

// Prescribed load: the grid first covers twice the Hertz approach at the deepest point; when the solved approach
// exceeds the covered one it is rebuilt for 1.5 times the solved approach (each rebuild at least 1.5 x larger).
constexpr double kInitialCoverFactor = 2.0;
// ... or, started from a nearby solved field, 1.25 times that field's depth below its deepest separation.
constexpr double kStartCoverFactor = 1.25;
// Cold solves on grids of at least this many elements (and rows) start from the solve on elements twice as large,
// solved to this tolerance (it only starts the fine solve). Chosen: below ~4000 elements the coarse solve saves
// less than it costs.
constexpr std::size_t kCoarseStartElements = 4096;
constexpr std::size_t kCoarseStartMinRows = 8;
constexpr double kCoarseStartTolerance = 1e-5;
constexpr double kRebuildCoverFactor = 1.5;
constexpr int kMaxGridRebuilds = 8;
// Growth of the covered approach when a tiny load leaves no element centre below it (centres lie dx/2 off x = 0).
constexpr double kTinyLoadCoverGrowth = 4.0;

bool valid_setup(const GapProfile& gap, double E_star_Pa, const Bem2dGrid& grid) {
  try {
    validate(gap);
  } catch (const std::exception&) {
    return false;
  }
  const auto positive = [](double v) { return v > 0.0 && std::isfinite(v); };
  return positive(E_star_Pa) && positive(grid.dx_m) && positive(grid.dy_m) && positive(grid.tolerance) &&
         grid.max_iterations >= 1;
}

// Approach of Hertz at the deepest gap sample beyond that sample's separation [m] (lateral curvature raised to
// A/20, as hertz_strip.hpp), or 0 when Hertz has no answer.
double hertz_approach_estimate(const GapProfile& gap, double E_star_Pa, double normal_force_N) {
  const auto k = static_cast<std::size_t>(std::min_element(gap.h_m.begin(), gap.h_m.end()) - gap.h_m.begin());
  const double A = gap.A_per_m[k], B = std::max(gap.B_per_m[k], A / 20.0);
  const HertzContact h = hertz_from_load(A, B, E_star_Pa, normal_force_N);
  return h.status == SolveStatus::Converged ? h.approach_m : 0.0;
}

class Bem2dRun {
 public:
  Bem2dRun(const GapProfile& gap, double E_star_Pa, const Bem2dGrid& options, Bem2dPressureField* field,
           const Bem2dPressureField* start = nullptr)
      : gap_(gap), E_star_(E_star_Pa), options_(options), field_(field),
        start_(start != nullptr && !start->empty() && start->depth_m > 0.0 ? start : nullptr) {
    solution_.method = "bem2d";
    if (field_) *field_ = Bem2dPressureField{};
  }

  NormalSolution solve(Prescribed prescribed, double target) {
    const auto start = std::chrono::steady_clock::now();
    try {
      run(prescribed, target);
    } catch (const std::bad_alloc&) {
      solution_.status = SolveStatus::NumericalFailure;
    } catch (const std::exception&) {
      solution_.status = SolveStatus::InvalidInput;
    }
    solution_.solve_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return solution_;
  }

 private:
  void run(Prescribed prescribed, double target) {
    const bool load = prescribed == Prescribed::Load;
    if (!valid_setup(gap_, E_star_, options_) || !std::isfinite(target) || (load && target < 0.0)) {
      solution_.status = SolveStatus::InvalidInput;
      return;
    }
    const double h_min = bem2d::deepest_separation(gap_, options_.dy_m, options_.alignment);
    if (!std::isfinite(h_min)) {
      solution_.status = SolveStatus::InvalidInput;
      return;
    }
    solution_.approach_m = load ? h_min : target;
    if ((load && target == 0.0) || (!load && target <= h_min)) {
      solution_.status = SolveStatus::NoContact;
      return;
    }
    double estimate = target, covered = target;
    first_cover(prescribed, target, h_min, estimate, covered);
    if (start_ == nullptr && coarse_start(prescribed, target, covered)) first_cover(prescribed, target, h_min, estimate, covered);
    bem2d::CgResult cg;
    for (int rebuild = 0;; ++rebuild) {
      std::string why;
      const SolveStatus grid_status =
          bem2d::make_element_grid(gap_, options_.dx_m, options_.dy_m, options_.alignment, covered, grid_, why);
      if (load && grid_status == SolveStatus::NoContact && rebuild < kMaxGridRebuilds) {
        // A load so small that no element centre lies below the covered approach: cover more.
        covered = h_min + kTinyLoadCoverGrowth * (covered - h_min);
        continue;
      }
      if (grid_status != SolveStatus::Converged) {
        solution_.status = load && grid_status == SolveStatus::NoContact ? SolveStatus::NumericalFailure : grid_status;
        solution_.detail = why;
        return;
      }
      InfluenceConvolution influence(grid_.nx, grid_.ny, grid_.dx, grid_.dy, E_star_);
      bem2d::initial_pressure(influence, grid_, prescribed, target, estimate, pressure_, rebuild == 0 ? start_ : nullptr);
      cg = bem2d::solve_constrained_cg(influence, grid_, prescribed, target, options_, pressure_);
      solution_.iterations += cg.iterations;
      solution_.outer_iterations = load ? rebuild + 1 : 0;
      if (!load || cg.status != SolveStatus::Converged || cg.approach < covered || rebuild == kMaxGridRebuilds) break;
      estimate = cg.approach;
      covered = h_min + kRebuildCoverFactor * (cg.approach - h_min);
    }
    solution_.status = cg.status;
    solution_.residual = cg.residual;
    solution_.approach_m = cg.approach;
    if (load && cg.status == SolveStatus::Converged && cg.approach >= covered)
      solution_.status = SolveStatus::ZoneTruncated;
    if (cg.status == SolveStatus::Converged || cg.status == SolveStatus::MaxIterations) {
      bem2d::assemble_solution(grid_, pressure_, solution_);
      if (cg.status == SolveStatus::Converged && bem2d::loaded_at_border(grid_, pressure_))
        solution_.status = SolveStatus::ZoneTruncated;
      if (field_) {
        bem2d::export_field(grid_, pressure_, *field_);
        field_->depth_m = cg.approach - h_min;
      }
    }
    if (cg.status == SolveStatus::NoContact) solution_.normal_load_N = 0.0;
  }

  // The approach the start estimates and the one the first grid covers (prescribed load; an approach is its own).
  void first_cover(Prescribed prescribed, double target, double h_min, double& estimate, double& covered) const {
    if (prescribed != Prescribed::Load) return;
    if (start_ != nullptr) {
      estimate = h_min + start_->depth_m;
      covered = h_min + kStartCoverFactor * start_->depth_m;
      return;
    }
    const double hertz = hertz_approach_estimate(gap_, E_star_, target);
    const double first_guess = hertz > 0.0 ? hertz : 1e-6;
    estimate = h_min + first_guess;
    covered = h_min + kInitialCoverFactor * first_guess;
  }

  // A cold solve on a grid of at least kCoarseStartElements starts from the same problem solved on elements twice
  // as large (itself started so when large): true when that solve gave the start.
  bool coarse_start(Prescribed prescribed, double target, double covered) {
    std::string why;
    if (bem2d::make_element_grid(gap_, options_.dx_m, options_.dy_m, options_.alignment, covered, grid_, why) !=
            SolveStatus::Converged ||
        grid_.nx * grid_.ny < kCoarseStartElements || grid_.ny < kCoarseStartMinRows)
      return false;
    Bem2dGrid coarse = options_;
    coarse.dx_m *= 2.0;
    coarse.dy_m *= 2.0;
    coarse.tolerance = std::max(options_.tolerance, kCoarseStartTolerance);
    const NormalSolution solved = Bem2dRun(gap_, E_star_, coarse, &coarse_field_).solve(prescribed, target);
    if (solved.status != SolveStatus::Converged || coarse_field_.empty() || !(coarse_field_.depth_m > 0.0)) return false;
    start_ = &coarse_field_;
    return true;
  }

  const GapProfile& gap_;
  double E_star_;
  Bem2dGrid options_;
  Bem2dPressureField* field_;
  const Bem2dPressureField* start_;  // null: cold start
  Bem2dPressureField coarse_field_;  // the coarse solve's field when it starts this one
  NormalSolution solution_;
  bem2d::ElementGrid grid_;
  std::vector<double> pressure_;
};

}  // namespace

NormalSolution solve_bem2d_for_approach(const GapProfile& gap, double E_star_Pa, const Bem2dGrid& grid,
                                        double approach_m, Bem2dPressureField* field) {
  return Bem2dRun(gap, E_star_Pa, grid, field).solve(Prescribed::Approach, approach_m);
}

NormalSolution solve_bem2d_for_load(const GapProfile& gap, double E_star_Pa, const Bem2dGrid& grid,
                                    double normal_force_N, Bem2dPressureField* field,
                                    const Bem2dPressureField* start) {
  return Bem2dRun(gap, E_star_Pa, grid, field, start).solve(Prescribed::Load, normal_force_N);
}

}  // namespace ctab::gen
