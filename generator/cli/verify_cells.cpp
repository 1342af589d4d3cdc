// SPDX-License-Identifier: Apache-2.0
#include "verify_cells.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace ctab::cli {

const char* cell_class_name(CellClass c) noexcept {
  switch (c) {
    case CellClass::Tread: return "tread";
    case CellClass::TwoPatch: return "two-patch";
    case CellClass::Flange: return "flange";
    case CellClass::Knee: return "knee";
    case CellClass::Jump: return "jump";
    case CellClass::Load: return "load";
  }
  return "unknown";
}

namespace {

// A cell's nodes: (i_dy, i_second) at its corners, and what the classes ask of them.
struct CellNodes {
  const tables::Table& t;
  std::size_t i_dy, i_second, wheel;
  bool second_axis;  // the cell spans two second-axis values

  template <class Use>
  void each(Use&& use) const {
    for (std::size_t di = 0; di < 2; ++di)
      for (std::size_t dj = 0; dj < (second_axis ? 2u : 1u); ++dj) use(i_dy + di, i_second + dj);
  }
  [[nodiscard]] bool usable() const {
    bool ok = true;
    each([&](std::size_t i, std::size_t j) { ok = ok && tables::is_success(t.status[t.wheel_index(i, j, wheel)]); });
    return ok;
  }
  [[nodiscard]] bool present(std::size_t i, std::size_t j, std::size_t slot) const {
    return t.patch.present[t.patch_index(i, j, wheel, slot)] != 0;
  }
  [[nodiscard]] std::size_t patches(std::size_t i, std::size_t j) const {
    std::size_t n = 0;
    for (std::size_t slot = 0; slot < t.n_slots; ++slot) n += present(i, j, slot);
    return n;
  }
  // The slots present differ between the nodes.
  [[nodiscard]] bool presence_changes() const {
    bool changes = false;
    for (std::size_t slot = 0; slot < t.n_slots; ++slot)
      each([&](std::size_t i, std::size_t j) {
        changes = changes || present(i, j, slot) != present(i_dy, i_second, slot);
      });
    return changes;
  }
  [[nodiscard]] std::size_t fewest_patches() const {
    std::size_t fewest = t.n_slots;
    each([&](std::size_t i, std::size_t j) { fewest = std::min(fewest, patches(i, j)); });
    return fewest;
  }
  [[nodiscard]] bool steep() const {
    bool found = false;
    each([&](std::size_t i, std::size_t j) {
      for (std::size_t slot = 0; slot < t.n_slots; ++slot)
        found = found || (present(i, j, slot) &&
                          std::abs(t.patch.contact_angle_rad[t.patch_index(i, j, wheel, slot)]) > kFlangeAngle_rad);
    });
    return found;
  }
  // Fastest change of a slot's normal force along dy, over the wheel's normal force [1/m].
  [[nodiscard]] double force_gradient() const {
    const double width = t.lateral_displacement_m[i_dy + 1] - t.lateral_displacement_m[i_dy];
    double fastest = 0.0;
    for (std::size_t dj = 0; dj < (second_axis ? 2u : 1u); ++dj) {
      double total = 0.0;
      for (std::size_t slot = 0; slot < t.n_slots; ++slot)
        total += t.patch.normal_force_N[t.patch_index(i_dy, i_second + dj, wheel, slot)];
      for (std::size_t slot = 0; slot < t.n_slots && total > 0.0; ++slot) {
        const double low = t.patch.normal_force_N[t.patch_index(i_dy, i_second + dj, wheel, slot)];
        const double high = t.patch.normal_force_N[t.patch_index(i_dy + 1, i_second + dj, wheel, slot)];
        fastest = std::max(fastest, std::abs(high - low) / width / total);
      }
    }
    return fastest;
  }
};

// Whether the table lists a jump of `wheel` in dy cell i_dy at a second-axis index the cell touches.
bool listed_jump(const tables::Table& t, const CellNodes& cell) {
  for (const tables::Jump& j : t.jumps)
    if (j.wheel == cell.wheel && j.i_dy == cell.i_dy &&
        (j.i_second == cell.i_second || (cell.second_axis && j.i_second == cell.i_second + 1)))
      return true;
  return false;
}

double cell_width(const tables::Table& t, std::size_t i_dy) {
  return t.lateral_displacement_m[i_dy + 1] - t.lateral_displacement_m[i_dy];
}

bool located(const tables::Table& t, std::size_t i_dy) {
  return i_dy + 1 < t.n_dy() && cell_width(t, i_dy) <= kLocatedJumpWidth_m * (1.0 + 1e-9);
}

// A cell not in the jump class, with its force gradient for the knee.
struct Candidate {
  SampleCell cell;
  double gradient = 0.0;
  CellClass fallback = CellClass::Tread;
};

void add_load_cells(const tables::Table& t, CellClasses& classes) {
  if (t.n_second() < 2) return;
  for (std::size_t i = 0; i < t.n_dy(); ++i)
    for (std::size_t j = 0; j + 1 < t.n_second(); ++j)
      for (std::size_t wheel = 0; wheel < tables::kWheels; ++wheel) {
        const double dy = t.lateral_displacement_m[i];
        CellNodes nodes{t, i, j, wheel, false};
        const bool ok = tables::is_success(t.status[t.wheel_index(i, j, wheel)]) &&
                        tables::is_success(t.status[t.wheel_index(i, j + 1, wheel)]);
        if (ok && nodes.patches(i, j) + nodes.patches(i, j + 1) > 0)
          classes[static_cast<std::size_t>(CellClass::Load)].push_back(
              {wheel, dy, dy, t.second_axis[j], t.second_axis[j + 1]});
      }
}

void take_knee(std::vector<Candidate>& candidates, CellClasses& classes) {
  std::vector<double> gradients;
  for (const Candidate& c : candidates) gradients.push_back(c.gradient);
  double threshold = std::numeric_limits<double>::infinity();
  if (gradients.size() >= 10) {
    const std::size_t k =
        static_cast<std::size_t>(std::floor((1.0 - kKneeShare) * static_cast<double>(gradients.size())));
    std::nth_element(gradients.begin(), gradients.begin() + static_cast<std::ptrdiff_t>(k), gradients.end());
    threshold = gradients[k];
  }
  for (const Candidate& c : candidates) {
    const bool knee = c.gradient >= threshold && c.gradient > kKneeMinGradient_per_m;
    classes[static_cast<std::size_t>(knee ? CellClass::Knee : c.fallback)].push_back(c.cell);
  }
}

}  // namespace

CellClasses classify_cells(const tables::Table& t) {
  CellClasses classes;
  std::vector<Candidate> candidates;
  const bool second_axis = t.n_second() > 1;
  const std::size_t second_cells = second_axis ? t.n_second() - 1 : 1;
  const auto& dy = t.lateral_displacement_m;
  for (std::size_t i = 0; i + 1 < t.n_dy(); ++i)
    for (std::size_t j = 0; j < second_cells; ++j)
      for (std::size_t wheel = 0; wheel < tables::kWheels; ++wheel) {
        const CellNodes nodes{t, i, j, wheel, second_axis};
        if (located(t, i) || !nodes.usable()) continue;
        SampleCell cell{wheel, dy[i], dy[i + 1], t.second_axis[j], t.second_axis[second_axis ? j + 1 : j]};
        bool jump = listed_jump(t, nodes) || nodes.presence_changes();
        if (i > 0 && located(t, i - 1) && listed_jump(t, CellNodes{t, i - 1, j, wheel, second_axis})) {
          cell.dy_low_m += kLocatedJumpWidth_m;
          jump = true;
        }
        if (i + 2 < t.n_dy() && located(t, i + 1) && listed_jump(t, CellNodes{t, i + 1, j, wheel, second_axis})) {
          cell.dy_high_m -= kLocatedJumpWidth_m;
          jump = true;
        }
        if (!(cell.dy_high_m > cell.dy_low_m)) continue;
        if (jump) {
          classes[static_cast<std::size_t>(CellClass::Jump)].push_back(cell);
          continue;
        }
        const std::size_t fewest = nodes.fewest_patches();
        if (fewest == 0) continue;  // no contact at a node and none changes: nothing to compare
        if (fewest >= 2) classes[static_cast<std::size_t>(CellClass::TwoPatch)].push_back(cell);
        else candidates.push_back({cell, nodes.force_gradient(), nodes.steep() ? CellClass::Flange : CellClass::Tread});
      }
  take_knee(candidates, classes);
  add_load_cells(t, classes);
  return classes;
}

namespace {

// Uniform in (0, 1) from 53 random bits (0 itself is replaced by 1/2).
double unit(std::mt19937_64& random) {
  const double u = static_cast<double>(random() >> 11) * 0x1.0p-53;
  return u > 0.0 ? u : 0.5;
}

}  // namespace

std::vector<SamplePoint> draw_samples(const CellClasses& classes, std::size_t samples, std::uint64_t seed) {
  std::vector<std::size_t> drawn;
  for (std::size_t c = 0; c < kCellClasses; ++c)
    if (!classes[c].empty()) drawn.push_back(c);
  std::vector<SamplePoint> points;
  if (drawn.empty()) return points;
  std::mt19937_64 random(seed);
  for (std::size_t k = 0; k < drawn.size(); ++k) {
    const std::vector<SampleCell>& cells = classes[drawn[k]];
    const std::size_t count = samples / drawn.size() + (k < samples % drawn.size() ? 1 : 0);
    for (std::size_t n = 0; n < count; ++n) {
      const SampleCell& cell = cells[static_cast<std::size_t>(random() % cells.size())];
      SamplePoint p;
      p.cell_class = static_cast<CellClass>(drawn[k]);
      p.index = points.size();
      p.wheel = cell.wheel;
      p.dy_m = cell.dy_low_m + unit(random) * (cell.dy_high_m - cell.dy_low_m);
      p.second = cell.second_low + unit(random) * (cell.second_high - cell.second_low);
      points.push_back(p);
    }
  }
  return points;
}

}  // namespace ctab::cli
