// `ctab solve`: one normal-contact problem on a gap profile, readable summary or JSON.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "commands.hpp"
#include "ctab/gen/error.hpp"
#include "ctab/gen/gap_csv.hpp"
#include "ctab/gen/hertz_strip.hpp"
#include "ctab/gen/material.hpp"
#include "ctab/gen/mim1d.hpp"
#include "ctab/gen/solution_json.hpp"

namespace ctab::cli {

namespace {

struct SolveOptions {
  std::string gap_path;
  std::optional<double> approach_m;
  std::optional<double> load_N;
  std::string method = "mim1d";
  std::string curvature = "smoothed";
  std::string update = "newton";
  double strip_width_m = 0.2e-3;
  double youngs_modulus_Pa = gen::kSteel.youngs_modulus_Pa;
  double poisson_ratio = gen::kSteel.poisson_ratio;
  bool json = false;
};

void print_summary(const gen::NormalSolution& s) {
  std::printf("method %s: %s after %d iterations (%d outer), residual %.2e, %.3f ms\n", s.method.c_str(),
              gen::status_name(s.status), s.iterations, s.outer_iterations, s.residual, s.solve_time_s * 1e3);
  std::printf("approach %.6f mm, normal load %.4f kN, %zu patch(es)\n", s.approach_m * 1e3, s.normal_load_N * 1e-3,
              s.patches.size());
  for (std::size_t k = 0; k < s.patches.size(); ++k) {
    const auto& p = s.patches[k];
    std::printf("  patch %zu: y %.3f..%.3f mm, force %.4f kN, area %.4f mm^2, max pressure %.2f MPa, %zu strips\n", k + 1,
                p.y_min_m * 1e3, p.y_max_m * 1e3, p.normal_force_N * 1e-3, p.area_m2 * 1e6, p.max_pressure_Pa * 1e-6,
                p.strips.size());
  }
}

int run_solve(const SolveOptions& o) {
  if (!(o.strip_width_m > 0.0 && std::isfinite(o.strip_width_m)))
    throw gen::InputError("--strip-width", 0, "expected a positive width in metres");
  if (!(o.youngs_modulus_Pa > 0.0 && std::isfinite(o.youngs_modulus_Pa)))
    throw gen::InputError("--E", 0, "expected a positive Young's modulus in Pa");
  if (!(o.poisson_ratio > -1.0 && o.poisson_ratio < 0.5))
    throw gen::InputError("--nu", 0, "expected a Poisson's ratio in (-1, 0.5)");
  if (o.approach_m && !std::isfinite(*o.approach_m)) throw gen::InputError("--approach", 0, "expected a finite number");
  if (o.load_N && !(std::isfinite(*o.load_N) && *o.load_N >= 0.0))
    throw gen::InputError("--load", 0, "expected a finite, non-negative force in N");
  const gen::GapProfile gap = gen::read_gap_csv(o.gap_path);
  const gen::ElasticMaterial material{o.youngs_modulus_Pa, o.poisson_ratio};
  const double E_star = gen::effective_modulus(material, material);
  gen::NormalSolution solution;
  if (o.method == "hertz") {
    solution = o.approach_m ? gen::solve_hertz_for_approach(gap, E_star, o.strip_width_m, *o.approach_m)
                            : gen::solve_hertz_for_load(gap, E_star, o.strip_width_m, *o.load_N);
  } else {
    gen::Mim1dOptions options;
    options.strip_width_m = o.strip_width_m;
    options.curvature.treatment =
        o.curvature == "pointwise" ? gen::CurvatureTreatment::Pointwise : gen::CurvatureTreatment::ContactSmoothed;
    options.update = o.update == "fixed-point" ? gen::Mim1dUpdate::FixedPoint : gen::Mim1dUpdate::Newton;
    gen::Mim1dSolver solver(gap, E_star, options);
    solution = o.approach_m ? solver.solve_for_approach(*o.approach_m) : solver.solve_for_load(*o.load_N);
  }
  if (o.json)
    std::cout << gen::to_json(solution).dump(1) << '\n';
  else
    print_summary(solution);
  return gen::is_success(solution.status) ? 0 : 4;
}

}  // namespace

Command add_solve_command(CLI::App& parent) {
  auto options = std::make_shared<SolveOptions>();
  CLI::App* app = parent.add_subcommand("solve", "Solve one normal-contact problem on a gap profile (SI units)");
  app->add_option("--gap", options->gap_path, "CSV with columns y_m,h_m,A_per_m,B_per_m")->required();
  auto* approach = app->add_option("--approach", options->approach_m, "prescribed rigid approach [m]");
  auto* load = app->add_option("--load", options->load_N, "prescribed normal load [N]");
  approach->excludes(load);
  load->excludes(approach);
  app->add_option("--method", options->method, "normal-contact method")->check(CLI::IsMember({"mim1d", "hertz"}));
  app->add_option("--strip-width", options->strip_width_m, "strip width 2b [m] (default 0.2e-3)");
  app->add_option("--E", options->youngs_modulus_Pa, "Young's modulus of both bodies [Pa] (default 208e9)");
  app->add_option("--nu", options->poisson_ratio, "Poisson's ratio of both bodies [-] (default 0.3)");
  app->add_option("--curvature", options->curvature, "lateral curvature in Eq. 26: smoothed (default) or pointwise")
      ->check(CLI::IsMember({"smoothed", "pointwise"}));
  app->add_option("--update", options->update, "MIM-1D update: newton (default) or fixed-point (paper Figure 3)")
      ->check(CLI::IsMember({"newton", "fixed-point"}));
  app->add_flag("--json", options->json, "print one JSON object");
  app->callback([app, approach, load] {
    if (approach->count() + load->count() != 1)
      throw CLI::ValidationError("solve", "give exactly one of --approach METRES or --load NEWTONS");
    (void)app;
  });
  return {app, [options] { return run_solve(*options); }};
}

}  // namespace ctab::cli
