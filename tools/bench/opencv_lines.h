// Optional comparator: the line detectors an engineer would reach for in
// OpenCV 4.6, run on the map drawn as RM-Line's paper did (obstacles grey
// 100, everything else 0) and as plain black / white (obstacles 255).
// Built only with -DLINEMAP_BENCH_OPENCV=ON (libopencv-dev); otherwise
// OpenCvLineDetectors() reports kUnsupported.
//
// Detectors and parameters (OpenCV defaults unless said):
//   LSD   cv::createLineSegmentDetector(LSD_REFINE_STD)
//   FLD   cv::ximgproc::createFastLineDetector() (length >= 10 px, distance
//         1.414 px, Canny 50 / 50, aperture 3, no merge)
//   Hough cv::HoughLinesP on the obstacle mask: rho 1 px, theta 1 deg,
//         threshold 10 votes, min length 5 px, max gap 2 px
//   Contours cv::findContours(RETR_LIST, CHAIN_APPROX_NONE) on the obstacle
//         mask, then cv::approxPolyDP(epsilon 1 px, closed): polygon edges
// Pixel (x, y) is cell (x, height - 1 - y); detector coordinates are taken
// as pixel-centre coordinates.
#ifndef LINEMAP_TOOLS_BENCH_OPENCV_LINES_H_
#define LINEMAP_TOOLS_BENCH_OPENCV_LINES_H_

#include <string>
#include <vector>

#include "linemap/grid.h"
#include "linemap/lines.h"
#include "linemap/status.h"

namespace linemap::bench {

struct DetectorRun {
  std::string key;                    // figure-key stem, e.g. "cv_lsd_grey"
  std::string label;                  // table header, e.g. "LSD grey100"
  std::vector<LineSegment> segments;  // cell units
  double ms = 0;                      // CPU time of the detector alone
};

bool OpenCvLineDetectorsBuilt();

struct DetectorName {
  const char* key;
  const char* label;
};
// The detectors OpenCvLineDetectors() runs, in its order.
const std::vector<DetectorName>& OpenCvDetectorNames();

StatusOr<std::vector<DetectorRun>> OpenCvLineDetectors(const Grid& grid);

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_OPENCV_LINES_H_
