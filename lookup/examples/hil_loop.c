// SPDX-License-Identifier: Apache-2.0
/* A fixed-step hardware-in-the-loop style loop over the C API: 4 wheelsets (8 wheels) at 1 kHz, each wheelset
 * oscillating laterally through the flange jump, for a given simulated time. One prelookup per wheelset, reused
 * for both wheels; per wheel the normal contact and the creep forces (FASTSIM on the strips, mu 0.3) from simple
 * kinematics at 30 m/s: xi from the rolling radius difference, eta from the lateral velocity, phi from the contact
 * angle. Reports the worst and mean step time against the 1 ms step.
 *
 *   ctab_hil_loop TABLE.blob [--seconds S] [--amplitude M] [--frequency HZ] [--require-budget]
 * Exit code 1 if a query failed, or with --require-budget if a step took longer than 1 ms (on a real-time
 * machine; a shared workstation may preempt the loop). */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "ctab/lookup/ctab_lookup.h"

#define WHEELSETS 4
#define STEP_S 1e-3
#define SPEED_M_S 30.0
#define RADIUS_M 0.46
#define PI 3.14159265358979323846

/* Creepages of one wheel (CONTACT's signs, illustrative kinematics: no yaw, rigid wheelset). */
static ctab_creep_input creepages(const ctab_result* normal, int wheel, double lateral_velocity) {
  ctab_creep_input in;
  memset(&in, 0, sizeof in);
  const double side = wheel == CTAB_WHEEL_RIGHT ? 1.0 : -1.0;
  in.xi = -side * normal->rolling_radius_difference_m / (2.0 * RADIUS_M);
  in.eta = side * lateral_velocity / SPEED_M_S;
  in.phi_per_m = normal->patch[0].present ? -sin(normal->patch[0].q[CTAB_PLANE_ANGLE_RAD]) / RADIUS_M : 0.0;
  in.friction = 0.3;
  in.method = CTAB_CREEP_STRIPS_CARTER;
  return in;
}

static double now_s(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int main(int argc, char** argv) {
  double seconds = 10.0, amplitude_m = 8e-3, frequency_hz = 1.0;
  int require_budget = 0;
  const char* path = NULL;
  for (int i = 1; i < argc; ++i) {
    if (i + 1 < argc && strcmp(argv[i], "--seconds") == 0) seconds = atof(argv[++i]);
    else if (i + 1 < argc && strcmp(argv[i], "--amplitude") == 0) amplitude_m = atof(argv[++i]);
    else if (i + 1 < argc && strcmp(argv[i], "--frequency") == 0) frequency_hz = atof(argv[++i]);
    else if (strcmp(argv[i], "--require-budget") == 0) require_budget = 1;
    else path = argv[i];
  }
  if (path == NULL || !(seconds > 0.0)) {
    fprintf(stderr,
            "usage: ctab_hil_loop TABLE.blob [--seconds S] [--amplitude M] [--frequency HZ] [--require-budget]\n");
    return 2;
  }
  ctab_table* table = NULL;
  const ctab_status opened = ctab_table_open(path, NULL, &table);
  if (opened != CTAB_OK) {
    fprintf(stderr, "ctab_hil_loop: %s: %s\n", path, ctab_status_message(opened));
    return 2;
  }
  const double second = ctab_table_second_value(table, 0);
  static ctab_result results[2 * WHEELSETS]; /* all memory set up before the loop */
  static ctab_creep_result creep[2 * WHEELSETS];
  const long steps = (long)(seconds / STEP_S + 0.5);
  double worst = 0.0, total = 0.0, force_sum = 0.0, creep_sum = 0.0, creep_max = 0.0;
  long failed = 0, patch_changes = 0;
  int last_present = -1;
  for (long step = 0; step < steps; ++step) {
    const double t = (double)step * STEP_S;
    const double start = now_s();
    for (int k = 0; k < WHEELSETS; ++k) {
      const double phase = 2.0 * PI * frequency_hz * t + 0.5 * k;
      const double dy = amplitude_m * sin(phase), velocity = amplitude_m * 2.0 * PI * frequency_hz * cos(phase);
      ctab_location where;
      ctab_prelookup(table, dy, second, &where);
      for (int wheel = 0; wheel < 2; ++wheel) {
        if (ctab_query_prelooked(table, &where, wheel, &results[2 * k + wheel]) < 0) ++failed;
        const ctab_creep_input in = creepages(&results[2 * k + wheel], wheel, velocity);
        if (ctab_creep_prelooked(table, &where, wheel, &in, &creep[2 * k + wheel]) < 0) ++failed;
      }
    }
    const double elapsed = now_s() - start;
    total += elapsed;
    if (elapsed > worst) worst = elapsed;
    /* Use the results (the flange slot of wheelset 0's right wheel switching on and off). */
    const int present = results[0].n_slots > 1 ? results[0].patch[1].present : 0;
    if (last_present >= 0 && present != last_present) ++patch_changes;
    last_present = present;
    for (int s = 0; s < results[0].n_slots; ++s) force_sum += results[0].patch[s].q[CTAB_NORMAL_FORCE_N];
    const double creep_force = hypot(creep[0].fx_N, creep[0].force_lateral_N);
    creep_sum += creep_force;
    if (creep_force > creep_max) creep_max = creep_force;
  }
  printf("ctab_hil_loop: %ld steps of %d wheels (%.1f simulated s at 1 kHz), amplitude %.1f mm at %.2f Hz\n", steps,
         2 * WHEELSETS, seconds, amplitude_m * 1e3, frequency_hz);
  printf("  worst step %.2f us, mean step %.3f us (normal + creep; budget 1000 us), failed calls %ld\n", worst * 1e6,
         total / (double)steps * 1e6, failed);
  printf("  flange slot of wheel 0 switched %ld times; mean normal force of wheel 0 %.1f N\n", patch_changes,
         force_sum / (double)steps);
  printf("  creep force of wheel 0 (|Fx, lateral|): mean %.1f N, largest %.1f N\n", creep_sum / (double)steps,
         creep_max);
  ctab_table_close(table);
  return failed == 0 && (!require_budget || worst < STEP_S) ? 0 : 1;
}
