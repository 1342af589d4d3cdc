// SPDX-License-Identifier: Apache-2.0
// `ctab paper-cases`: the main job for now — the paper's theoretical cases against Hertz and CONTACT.
#include <cstdio>

#include "commands.hpp"
#include "ctab/contact/hertz.hpp"
#include "ctab/contact/hertz_strip.hpp"
#include "ctab/contact/material.hpp"
#include "ctab/contact/mim1d.hpp"
#include "ctab/fixtures/paper_cases.hpp"

namespace ctab::cli {

namespace {

void print_row(const char* label, const gen::NormalSolution& s, double force_ref, double area_ref, double pmax_ref) {
  const double area = s.patches.empty() ? 0.0 : s.patches.front().area_m2;
  const double pmax = s.patches.empty() ? 0.0 : s.patches.front().max_pressure_Pa;
  std::printf("  %-26s %-10s %10.2f %+7.2f%% %9.2f %+7.2f%% %9.1f %+7.2f%% %8.3f\n", label, gen::status_name(s.status),
              s.normal_load_N * 1e-3, 100.0 * (s.normal_load_N / force_ref - 1.0), area * 1e6,
              100.0 * (area / area_ref - 1.0), pmax * 1e-6, 100.0 * (pmax / pmax_ref - 1.0), s.solve_time_s * 1e3);
}

int run_paper_cases() {
  const double E_star = gen::effective_modulus(gen::kSteel, gen::kSteel);
  const double width = 0.2e-3;
  std::printf(
      "MIM-1D on the theoretical cases of Qazi et al. (2022), section 3.1: steel, approach 1 mm, strips 0.2 mm\n");
  std::printf("  %-26s %-10s %10s %8s %9s %8s %9s %8s %8s\n", "method", "status", "N [kN]", "err", "A [mm2]", "err",
              "pmax[MPa]", "err", "time[ms]");

  const gen::GapProfile sphere = gen::paper::hertz_sphere_gap();
  const double curvature = 1.0 / (2.0 * gen::paper::kSphereRadius_m);
  const gen::HertzContact exact = gen::hertz_from_approach(curvature, curvature, E_star, gen::paper::kApproach_m);
  std::printf("Sphere R = 40 mm on a flat; reference: Hertz (N %.2f kN, area %.2f mm2, p0 %.1f MPa)\n",
              exact.normal_force_N * 1e-3, exact.area_m2 * 1e6, exact.max_pressure_Pa * 1e-6);
  gen::Mim1dOptions options;
  options.strip_width_m = width;
  gen::Mim1dSolver sphere_solver(sphere, E_star, options);
  print_row("MIM-1D", sphere_solver.solve_for_approach(gen::paper::kApproach_m), exact.normal_force_N, exact.area_m2,
            exact.max_pressure_Pa);

  const gen::GapProfile body = gen::paper::nonhertz_gap();
  std::printf("Two-radius body (R 40 mm | 500 mm, rolling radius 400 mm) on a flat; reference: CONTACT (N %.1f kN, "
              "area %.1f mm2, pmax %.0f MPa)\n",
              gen::paper::kNonHertzContactForce_N * 1e-3, gen::paper::kNonHertzContactArea_m2 * 1e6,
              gen::paper::kNonHertzContactMaxPressure_Pa * 1e-6);
  const auto ref_force = gen::paper::kNonHertzContactForce_N, ref_area = gen::paper::kNonHertzContactArea_m2,
             ref_pmax = gen::paper::kNonHertzContactMaxPressure_Pa;
  gen::Mim1dSolver smoothed(body, E_star, options);
  print_row("MIM-1D (smoothed curvature)", smoothed.solve_for_approach(gen::paper::kApproach_m), ref_force, ref_area,
            ref_pmax);
  gen::Mim1dOptions pointwise_options = options;
  pointwise_options.curvature.treatment = gen::CurvatureTreatment::Pointwise;
  gen::Mim1dSolver pointwise(body, E_star, pointwise_options);
  print_row("MIM-1D (pointwise, paper)", pointwise.solve_for_approach(gen::paper::kApproach_m), ref_force, ref_area,
            ref_pmax);
  print_row("Hertz at first contact", gen::solve_hertz_for_approach(body, E_star, width, gen::paper::kApproach_m),
            ref_force, ref_area, ref_pmax);
  return 0;
}

}  // namespace

Command add_paper_cases_command(CLI::App& parent) {
  CLI::App* app = parent.add_subcommand(
      "paper-cases", "Solve the paper's Hertzian and non-Hertzian cases (embedded) and compare with the references");
  return {app, [] { return run_paper_cases(); }};
}

}  // namespace ctab::cli
