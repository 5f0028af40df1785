#include "tools/bench/anchors.h"

#include <algorithm>

#include "tools/bench/measure.h"

namespace linemap::bench {
namespace {

double Ratio(const MapResult& result, const std::string& subject, const std::string& anchor) {
  return *result.Get(subject) / *result.Get(anchor);
}

NamedTable SummaryTable(const std::vector<AnchorOutcome>& outcomes, const Anchor& subject,
                        bool goal) {
  Table table({"anchor", "maps", subject.name + " smaller", "lost", "median size ratio",
               "worst size ratio"});
  for (const AnchorOutcome& outcome : outcomes) {
    std::vector<double> ratios;
    for (const auto* list : {&outcome.won, &outcome.lost}) {
      for (const MapResult* r : *list) {
        ratios.push_back(Ratio(*r, subject.figure, outcome.anchor.figure));
      }
    }
    const std::size_t maps = ratios.size();
    const bool any = maps > 0;
    table.AddRow({outcome.anchor.name, std::to_string(maps),
                  any ? std::to_string(outcome.won.size()) + "/" + std::to_string(maps) : "n/a",
                  std::to_string(outcome.lost.size()), any ? FormatFixed(Median(ratios), 3) : "n/a",
                  any ? FormatFixed(*std::max_element(ratios.begin(), ratios.end()), 3) : "n/a"});
  }
  return {
      "Anchors: " + subject.name + " against each codec",
      "Maps of at least " + FormatCount(kAnchorMinCells) + " cells; " +
          (goal ? "goal: " + subject.name + " strictly smaller than every anchor on every such map."
                : "for comparison (not a goal), " + subject.name +
                      " coded for size, as the anchors are at their highest efforts.") +
          " size ratio = " + subject.name +
          " bytes / anchor bytes; maps = those where both were measured "
          "(an anchor missing here was skipped or not installed: see the notes).",
      table};
}

NamedTable LossesTable(const std::vector<AnchorOutcome>& outcomes, const Anchor& subject) {
  Table table({"anchor", "map", "cells", subject.name + " bytes", "anchor bytes", "size ratio"});
  for (const AnchorOutcome& outcome : outcomes) {
    for (const MapResult* r : outcome.lost) {
      table.AddRow({outcome.anchor.name, r->name, FormatCount(r->Get(key::kCells)),
                    FormatCount(r->Get(subject.figure)), FormatCount(r->Get(outcome.anchor.figure)),
                    FormatFixed(Ratio(*r, subject.figure, outcome.anchor.figure), 3)});
    }
  }
  return {"Anchors: maps " + subject.name + " loses", "", table};
}

}  // namespace

std::vector<Anchor> SizeAnchors() {
  return {{"PNG-9", key::kPng9Bytes}, {"WebP lossless", key::kWebpBytes},
          {"JBIG1", key::kJbigBytes}, {"zstd -19", key::kZstdBytes},
          {"xz -9e", key::kXzBytes},  {"JPEG XL lossless", key::kJxlBytes}};
}

Anchor AnchorSubject() { return {".lmap 2.0", key::kLmapBytes}; }

std::vector<Anchor> ComparedSubjects() {
  return {{".lmap 2.3 --compact", key::kLmapCompactBytes},
          {".lmap 2.3 --compact --raster-only", key::kLmapRasterCompactBytes}};
}

std::vector<AnchorOutcome> CheckAnchors(const std::vector<MapResult>& results,
                                        const Anchor& subject) {
  std::vector<AnchorOutcome> outcomes;
  for (const Anchor& anchor : SizeAnchors()) {
    AnchorOutcome outcome{anchor, {}, {}};
    for (const MapResult& result : results) {
      const std::optional<double> cells = result.Get(key::kCells);
      const std::optional<double> mine = result.Get(subject.figure);
      const std::optional<double> theirs = result.Get(anchor.figure);
      if (!cells || *cells < kAnchorMinCells || !mine || !theirs || *theirs <= 0) continue;
      (*mine < *theirs ? outcome.won : outcome.lost).push_back(&result);
    }
    outcomes.push_back(std::move(outcome));
  }
  return outcomes;
}

std::vector<NamedTable> AnchorTables(const std::vector<MapResult>& results, const Anchor& subject,
                                     bool goal) {
  const std::vector<AnchorOutcome> outcomes = CheckAnchors(results, subject);
  std::vector<NamedTable> tables = {SummaryTable(outcomes, subject, goal)};
  const bool any_lost = std::any_of(outcomes.begin(), outcomes.end(),
                                    [](const AnchorOutcome& o) { return !o.lost.empty(); });
  if (any_lost) tables.push_back(LossesTable(outcomes, subject));
  return tables;
}

}  // namespace linemap::bench
