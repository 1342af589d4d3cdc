#pragma once
//! The parallel contact-table generator: every case (lateral shift x load or approach, each wheel) solved with
//! the wheel-rail contact solver, in OpenMP over the flattened case list.
//!
//! Set-up (serial, may throw InputError): profiles, track, the process-wide kernel and Hertz tables. The
//! parallel region has one task per case with a dynamic schedule (the cost varies tenfold between tread and
//! flange cases) and one WheelContactWorkspace per thread (indexed by omp_get_thread_num(); results do not
//! depend on it); every task writes only its own preallocated result slot, nothing is reduced across cases,
//! no I/O happens and no exception leaves the region (a failure becomes the case's status). The table is
//! therefore bit-identical for any number of threads. When the two sides are mirror images (one wheel and one
//! rail profile for both) and the lateral axis is symmetric, only the right wheel is solved: the left wheel at
//! dy is the right wheel at -dy (the file says so in its `mirrored` attribute).
#include <atomic>
#include <functional>
#include <string>

#include "ctab/sweep/table_config.hpp"
#include "ctab/tables/table.hpp"

namespace ctab::gen {

struct GeneratorInfo {
  std::string version = "unknown";  //!< generator version (provenance)
  std::string git_commit = "unknown";
  int threads = 1;                  //!< OpenMP threads for the sweep
};

//! Progress observer, called from the calling thread only (about every 0.1 s) with cases done and total.
using ProgressCallback = std::function<void(std::size_t done, std::size_t total)>;

//! Generates the table. Throws InputError at set-up (e.g. a profile file that cannot be read).
[[nodiscard]] tables::Table generate_table(const TableConfig& config, const GeneratorInfo& info,
                                           const ProgressCallback& progress = {});

//! Equivalent ellipse of a patch (Kik-Piotrowski recipe: area and length/width ratio kept):
//! a = sqrt(area/pi) sqrt(L/W), b = sqrt(area/pi) sqrt(W/L) [m].
void equivalent_ellipse(double area_m2, double length_m, double width_m, double& a_m, double& b_m) noexcept;

}  // namespace ctab::gen
