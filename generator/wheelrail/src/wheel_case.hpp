// SPDX-License-Identifier: Apache-2.0
#pragma once
//! One wheel-rail case (internal to ctab::wheelrail): its inputs, the workspace it solves in and the result it fills,
//! shared by the steps of solve_wheel_contact. wheelrail_contact.cpp drives the steps: main_patch_strips (the main
//! patch's strip solves and warm starts), gap_passes (the prescribed-load fixed point), centre_following (CONTACT's
//! reference point during the passes), further_patches (patches of further gap minima) and patch_results.
#include <chrono>
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "ctab/contact/bem2d.hpp"
#include "ctab/contact/mim1d.hpp"
#include "ctab/wheelrail/wheelrail_contact.hpp"
#include "patch_problem.hpp"
#include "patch_sampling.hpp"

namespace ctab::gen {

struct WheelContactWorkspace::Impl {
  std::vector<GapMinimum> minima;
  std::vector<PatchProblem> pool;            // patch problems; the first `used` are this case's
  Mim1dWarmStart pass_start;                 // the main patch's previous pass (gap passes), when not warm-started
  Mim1dWarmStart moved_start;                // pass_start moved onto a grid with another origin (start_on_grid)
  Mim1dWarmStart chain_start;                // the chain's last two solves extrapolated (extrapolate_warm_start)
  Bem2dPressureField bem2d_pass_start;       // bem2d: the main patch's previous pass
  Bem2dPressureField bem2d_solved;           // bem2d: the field of the pass being solved
  std::unique_ptr<Mim1dSolver> other_width;  // resolve_at_strip_width's solver
  std::size_t used = 0;
  PatchProblem& acquire() {  // the pool is sized before use
    PatchProblem& p = pool[used++];
    p.origin_y = std::numeric_limits<double>::quiet_NaN();
    return p;
  }
};

//! CONTACT's reference point at one sampling approach, kept for the next query at the same approach
//! (centre_following.hpp).
struct CentreCache {
  double approach_m = std::numeric_limits<double>::quiet_NaN();
  GapMinimum centre;
  bool found = false;
};

struct WheelCase {
  WheelCase(const SideGeometry& side_geometry, double dy, double roll, double E_star, LoadKind load_kind, double value,
            const WheelRailOptions& wheelrail_options, WheelContactWorkspace::Impl& workspace,
            Mim1dWarmStart* warm_start)
      : side(side_geometry), dy_m(dy), roll_rad(roll), E_star_Pa(E_star), load(load_kind), load_value(value),
        options(wheelrail_options), ws(workspace), warm(warm_start),
        builder(side_geometry, dy, roll, 0.0, wheelrail_options.surface, strip_alignment(wheelrail_options)) {}

  const std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  const SideGeometry& side;
  double dy_m, roll_rad, E_star_Pa;
  LoadKind load;
  double load_value;  // [N] or, LoadKind::Approach, [m]
  const WheelRailOptions& options;
  WheelContactWorkspace::Impl& ws;
  Mim1dWarmStart* warm;     // in/out, or null: cold
  bool recentring = false;  // recentre_main_patch's re-solve: the gap passes keep its plane
  CentreCache centre_cache;
  PatchBuilder builder;
  WheelContact result;
  std::string detail;  // why the case failed (empty while it has not)

  [[nodiscard]] bool mim1d() const { return options.method == NormalMethod::Mim1d; }
};

}  // namespace ctab::gen
