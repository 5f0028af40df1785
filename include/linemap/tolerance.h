// Whether a map decoded from a file saved within a tolerance keeps the
// guarantees of that tolerance (EncodeOptions::tolerance_cells), measured
// against the original map: what `linemap eval --tolerance T` prints. The
// encoder checks them on its own decode before it writes a file; a caller
// that receives a map can check them again here.
//
// The guarantees, for a tolerance of T cells, between an original grid O
// and a simplified (decoded) grid S of the same size:
//   1. every occupied cell of O has an occupied cell of S within T, and
//      every occupied cell of S has one of O within T (Hausdorff <= T);
//   2. every free cell of S is within T of a free cell of O and every free
//      cell of O within T of a free cell of S (so unknown never turns free
//      further than T from the original free space);
//   3. no leak: free regions of O (4-connected, kLeakRegionCells+ cells,
//      linemap/codec.h)
//      that are apart stay apart in S; and no free region of O is split;
//   4. plans agree: from 16 sampled start cells to every goal cell free
//      in both maps, a 4-connected path over free cells exists on S exactly
//      when it exists on O, and its length is within kPlanLengthTolerance
//      of O's; and from every cell free in both maps beside a cell free in
//      one only, every plan of up to kLocalPlanSteps steps on either map has
//      the same length on the other (a doorway closed or a wall opened where
//      no sampled start plans through, and the short plans that 3 % cannot
//      tell apart: under 34 steps, 3 % is less than one step).
#ifndef LINEMAP_TOLERANCE_H_
#define LINEMAP_TOLERANCE_H_

#include <cstddef>
#include <cstdint>

#include "linemap/grid.h"

namespace linemap {

// Largest tolerance the encoder accepts, in cells.
inline constexpr int kMaxToleranceCells = 4;
// Plans agree when the decoded path length is within this share of the
// original's (0.03 = 3 %). No slack in steps is added: a wall grown by one
// cell makes a plan round its end 2 steps longer, more than 3 % of any plan
// under 67 steps, and a planner told "within 3 %" must not find those.
inline constexpr double kPlanLengthTolerance = 0.03;
// The local plans of guarantee 4 reach this many steps. Measured on
// ../shared/maps (`build/bench_tolerance --maps ../shared/maps
// --cells-only`, 24 strided starts x ~1000 goals per map that the encoder
// never samples): with 8 steps, 61 of 609,096 plans at T = 1 still
// differed by more than 3 % (7 by more than 2 steps), with 16 steps 1; the
// files are the same size within 1 %.
inline constexpr int kLocalPlanSteps = 16;

// The guarantees' figures of `decoded` against `original` (same size; a
// report of mismatched sizes has same_size false and nothing else set).
struct ToleranceReport {
  bool same_size = false;
  int tolerance_cells = 0;
  // Hausdorff distance (Chebyshev, cells) from the original's occupied cells
  // to the decoded ones, and back; -1 when the other map has no occupied
  // cell but this one has (infinitely far); 0 when this one has none.
  int hausdorff_original_to_decoded = 0;
  int hausdorff_decoded_to_original = 0;
  // Occupied cells of the original with a free 4-neighbour, and how many of
  // them have a decoded occupied cell within T.
  std::size_t wall_surface_cells = 0;
  std::size_t wall_surface_kept = 0;
  // Decoded free cells further than T from every original free cell, and
  // original free cells further than T from every decoded free cell.
  std::size_t free_moved_beyond = 0;
  std::size_t free_lost_beyond = 0;
  // Original unknown cells decoded free further than T from original free.
  std::size_t unknown_turned_free_beyond = 0;
  // Free regions (kLeakRegionCells+ cells) of the original that the decode
  // joins (sum over decoded components of regions touched - 1), and
  // original free regions whose decoded cells fall in several components.
  std::size_t leaks = 0;
  std::size_t splits = 0;
  // Start / goal pairs (sampled starts, every goal) free in both maps, and
  // those whose plans
  // disagree (one exists and not the other, or lengths differ by more than
  // kPlanLengthTolerance).
  std::size_t plan_pairs = 0;
  std::size_t plan_disagreements = 0;
  // The local plans of guarantee 4 (from each cell free in both maps beside
  // a change, on each map, up to kLocalPlanSteps steps), and those not on
  // the other map with the same length.
  std::size_t local_plans = 0;
  std::size_t local_plan_disagreements = 0;

  double WallSurfaceShare() const {
    return wall_surface_cells ? static_cast<double>(wall_surface_kept) / wall_surface_cells : 1.0;
  }
  // True when every guarantee holds.
  bool Holds() const;
};

ToleranceReport CheckTolerance(const Grid& original, const Grid& decoded, int tolerance_cells);

// Calls visit(key, value) for each figure of `t` under the name `linemap
// eval --tolerance T --json` prints it with (and Python's eval() returns),
// in that order; values are std::int64_t, std::uint64_t, double or bool.
template <typename Visit>
void VisitToleranceFigures(const ToleranceReport& t, Visit&& visit) {
  visit("tolerance_cells", std::int64_t{t.tolerance_cells});
  visit("hausdorff_original_to_decoded", std::int64_t{t.hausdorff_original_to_decoded});
  visit("hausdorff_decoded_to_original", std::int64_t{t.hausdorff_decoded_to_original});
  visit("wall_surface_cells", std::uint64_t{t.wall_surface_cells});
  visit("wall_surface_within_t", std::uint64_t{t.wall_surface_kept});
  visit("wall_surface_share_within_t", t.WallSurfaceShare());
  visit("free_moved_beyond_t", std::uint64_t{t.free_moved_beyond});
  visit("free_lost_beyond_t", std::uint64_t{t.free_lost_beyond});
  visit("unknown_turned_free_beyond_t", std::uint64_t{t.unknown_turned_free_beyond});
  visit("tolerance_leaks", std::uint64_t{t.leaks});
  visit("tolerance_splits", std::uint64_t{t.splits});
  visit("plan_pairs", std::uint64_t{t.plan_pairs});
  visit("plan_disagreements", std::uint64_t{t.plan_disagreements});
  visit("local_plans", std::uint64_t{t.local_plans});
  visit("local_plan_disagreements", std::uint64_t{t.local_plan_disagreements});
  visit("tolerance_holds", t.Holds());
}

}  // namespace linemap

#endif  // LINEMAP_TOLERANCE_H_
