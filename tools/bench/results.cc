#include "tools/bench/results.h"

#include "tools/bench/measure.h"

namespace linemap::bench {

std::optional<double> MapResult::Get(const std::string& figure) const {
  auto it = figures.find(figure);
  if (it == figures.end()) return std::nullopt;
  return it->second;
}

std::optional<double> MapResult::RatioToPng9(const std::string& figure) const {
  const std::optional<double> value = Get(figure);
  const std::optional<double> base = Get(key::kPng9Bytes);
  if (!value || !base || *base <= 0) return std::nullopt;
  return *value / *base;
}

std::optional<double> ColumnValue(const MapResult& result, const Column& column) {
  return column.ratio ? result.RatioToPng9(column.figure) : result.Get(column.figure);
}

std::optional<double> ColumnMedian(const std::vector<MapResult>& results, const Column& column) {
  std::vector<double> values;
  for (const MapResult& result : results) {
    if (std::optional<double> v = ColumnValue(result, column)) values.push_back(*v);
  }
  if (values.empty()) return std::nullopt;
  return Median(values);
}

}  // namespace linemap::bench
