#include "tools/bench/opencv_lines.h"

#ifdef LINEMAP_BENCH_OPENCV
#include <opencv2/imgproc.hpp>
#include <opencv2/ximgproc/fast_line_detector.hpp>
#endif

#include <functional>

#include "tools/bench/measure.h"

namespace linemap::bench {

const std::vector<DetectorName>& OpenCvDetectorNames() {
  static const std::vector<DetectorName> names = {
      {"cv_lsd_grey", "LSD grey100"},     {"cv_lsd_bw", "LSD b/w"},
      {"cv_fld_grey", "FLD grey100"},     {"cv_fld_bw", "FLD b/w"},
      {"cv_hough_bw", "HoughLinesP b/w"}, {"cv_contours_bw", "findContours+approxPolyDP b/w"},
  };
  return names;
}

#ifdef LINEMAP_BENCH_OPENCV
namespace {

// Obstacles `obstacle`, everything else 0; image row 0 = top.
cv::Mat DrawMap(const Grid& grid, std::uint8_t obstacle) {
  cv::Mat image(grid.height(), grid.width(), CV_8UC1, cv::Scalar(0));
  for (int row = 0; row < grid.height(); ++row) {
    std::uint8_t* out = image.ptr<std::uint8_t>(grid.height() - 1 - row);
    for (int col = 0; col < grid.width(); ++col) {
      if (grid.at(col, row) == Cell::kOccupied) out[col] = obstacle;
    }
  }
  return image;
}

LineSegment ToCells(const Grid& grid, double x1, double y1, double x2, double y2) {
  const double top = grid.height() - 1;
  return {x1, top - y1, x2, top - y2};
}

std::vector<LineSegment> FromVec4f(const Grid& grid, const std::vector<cv::Vec4f>& lines) {
  std::vector<LineSegment> out;
  for (const cv::Vec4f& l : lines) out.push_back(ToCells(grid, l[0], l[1], l[2], l[3]));
  return out;
}

DetectorRun Timed(const std::string& key, const std::string& label,
                  const std::function<std::vector<LineSegment>()>& detect) {
  DetectorRun run{key, label, {}, 0};
  run.ms = Median(TimeRuns([&] { run.segments = detect(); }, 1));
  return run;
}

std::vector<LineSegment> Lsd(const Grid& grid, const cv::Mat& image) {
  cv::Ptr<cv::LineSegmentDetector> lsd = cv::createLineSegmentDetector(cv::LSD_REFINE_STD);
  std::vector<cv::Vec4f> lines;
  lsd->detect(image, lines);
  return FromVec4f(grid, lines);
}

std::vector<LineSegment> Fld(const Grid& grid, const cv::Mat& image) {
  cv::Ptr<cv::ximgproc::FastLineDetector> fld = cv::ximgproc::createFastLineDetector();
  std::vector<cv::Vec4f> lines;
  fld->detect(image, lines);
  return FromVec4f(grid, lines);
}

std::vector<LineSegment> Hough(const Grid& grid, const cv::Mat& mask) {
  std::vector<cv::Vec4i> lines;
  cv::HoughLinesP(mask, lines, 1.0, CV_PI / 180.0, 10, 5.0, 2.0);
  std::vector<LineSegment> out;
  for (const cv::Vec4i& l : lines) out.push_back(ToCells(grid, l[0], l[1], l[2], l[3]));
  return out;
}

std::vector<LineSegment> Contours(const Grid& grid, const cv::Mat& mask) {
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(mask.clone(), contours, cv::RETR_LIST, cv::CHAIN_APPROX_NONE);
  std::vector<LineSegment> out;
  for (const std::vector<cv::Point>& contour : contours) {
    std::vector<cv::Point> polygon;
    cv::approxPolyDP(contour, polygon, 1.0, true);
    const std::size_t n = polygon.size();
    if (n == 1)
      out.push_back(ToCells(grid, polygon[0].x, polygon[0].y, polygon[0].x, polygon[0].y));
    for (std::size_t i = 0; n > 1 && i < (n == 2 ? 1 : n); ++i) {
      const cv::Point& a = polygon[i];
      const cv::Point& b = polygon[(i + 1) % n];
      out.push_back(ToCells(grid, a.x, a.y, b.x, b.y));
    }
  }
  return out;
}

}  // namespace

bool OpenCvLineDetectorsBuilt() { return true; }

StatusOr<std::vector<DetectorRun>> OpenCvLineDetectors(const Grid& grid) {
  if (grid.empty()) return InvalidArgumentError("OpenCV: the map has no cells");
  try {
    const cv::Mat grey = DrawMap(grid, 100);
    const cv::Mat bw = DrawMap(grid, 255);
    const std::vector<std::function<std::vector<LineSegment>()>> detectors = {
        [&] { return Lsd(grid, grey); }, [&] { return Lsd(grid, bw); },
        [&] { return Fld(grid, grey); }, [&] { return Fld(grid, bw); },
        [&] { return Hough(grid, bw); }, [&] { return Contours(grid, bw); },
    };
    std::vector<DetectorRun> runs;
    for (std::size_t i = 0; i < detectors.size(); ++i) {
      const DetectorName& name = OpenCvDetectorNames()[i];
      runs.push_back(Timed(name.key, name.label, detectors[i]));
    }
    return runs;
  } catch (const cv::Exception& e) {
    return InternalError(std::string("OpenCV: ") + e.what());
  }
}

#else

bool OpenCvLineDetectorsBuilt() { return false; }

StatusOr<std::vector<DetectorRun>> OpenCvLineDetectors(const Grid& /*grid*/) {
  return UnsupportedError(
      "OpenCV line detectors not built (configure with -DLINEMAP_BENCH_OPENCV=ON)");
}

#endif

}  // namespace linemap::bench
