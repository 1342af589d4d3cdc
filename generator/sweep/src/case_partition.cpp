// SPDX-License-Identifier: Apache-2.0
#include "ctab/sweep/case_partition.hpp"

#include <algorithm>
#include <charconv>

namespace ctab::gen {

std::size_t rows_per_unit(std::size_t n_dy, bool mirrored) {
  const std::size_t span = mirrored ? (n_dy + 1) / 2 : n_dy;
  return std::clamp((span + kTargetUnits - 1) / kTargetUnits, kRowsPerUnit, kMaxRowsPerUnit);
}

std::vector<std::vector<std::size_t>> sweep_units(std::size_t n_dy, bool mirrored) {
  return sweep_units(n_dy, mirrored, rows_per_unit(n_dy, mirrored));
}

std::vector<std::vector<std::size_t>> sweep_units(std::size_t n_dy, bool mirrored, std::size_t rows_per_unit) {
  rows_per_unit = std::max<std::size_t>(rows_per_unit, 1);
  const std::size_t span = mirrored ? (n_dy + 1) / 2 : n_dy;  // rows counted from row 0
  std::vector<std::vector<std::size_t>> units;
  for (std::size_t begin = 0; begin < span; begin += rows_per_unit) {
    std::vector<std::size_t> unit;
    const std::size_t end = std::min(span, begin + rows_per_unit);
    for (std::size_t i = begin; i < end; ++i) {
      unit.push_back(i);
      if (mirrored && n_dy - 1 - i != i) unit.push_back(n_dy - 1 - i);
    }
    std::sort(unit.begin(), unit.end());
    units.push_back(std::move(unit));
  }
  return units;
}

std::vector<std::size_t> shard_rows(const std::vector<std::vector<std::size_t>>& units, std::size_t index,
                                    std::size_t count) {
  std::vector<std::size_t> rows;
  if (count == 0 || index == 0 || index > count) return rows;
  const std::size_t first = (index - 1) * units.size() / count, last = index * units.size() / count;
  for (std::size_t u = first; u < last; ++u) rows.insert(rows.end(), units[u].begin(), units[u].end());
  std::sort(rows.begin(), rows.end());
  return rows;
}

std::string format_rows(const std::vector<std::size_t>& rows) {
  std::string text;
  for (std::size_t i = 0; i < rows.size();) {
    std::size_t j = i;
    while (j + 1 < rows.size() && rows[j + 1] == rows[j] + 1) ++j;
    if (!text.empty()) text += ',';
    text += std::to_string(rows[i]);
    if (j > i) {
      text += '-';
      text += std::to_string(rows[j]);
    }
    i = j + 1;
  }
  return text;
}

std::optional<std::vector<std::size_t>> parse_rows(const std::string& text, std::size_t n_dy) {
  std::vector<std::size_t> rows;
  const char* at = text.data();
  const char* const end = at + text.size();
  auto number = [&](std::size_t& value) {
    const auto [next, error] = std::from_chars(at, end, value);
    if (error != std::errc() || next == at) return false;
    at = next;
    return true;
  };
  while (at < end) {
    std::size_t first = 0, last = 0;
    if (!number(first)) return std::nullopt;
    last = first;
    if (at < end && *at == '-' && (++at, !number(last))) return std::nullopt;
    if (last < first || last >= n_dy || (!rows.empty() && first <= rows.back())) return std::nullopt;
    for (std::size_t i = first; i <= last; ++i) rows.push_back(i);
    if (at < end && (*at != ',' || ++at == end)) return std::nullopt;
  }
  return rows;
}

}  // namespace ctab::gen
