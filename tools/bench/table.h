// A small table of text cells rendered as aligned plain text (terminal),
// GitHub Markdown, or CSV (RFC 4180 quoting).
#ifndef LINEMAP_TOOLS_BENCH_TABLE_H_
#define LINEMAP_TOOLS_BENCH_TABLE_H_

#include <optional>
#include <string>
#include <vector>

namespace linemap::bench {

class Table {
 public:
  explicit Table(std::vector<std::string> headers) : headers_(std::move(headers)) {}

  // A row with as many cells as headers (missing cells are left empty).
  void AddRow(std::vector<std::string> cells);

  // Columns of words rather than numbers (the first always is): aligned left
  // in Text() and Markdown().
  void LeftAlign(std::size_t column);

  const std::vector<std::string>& headers() const { return headers_; }
  const std::vector<std::vector<std::string>>& rows() const { return rows_; }

  // Columns padded to their widest cell; the first column and those given to
  // LeftAlign() left-aligned, the others right-aligned (numbers).
  std::string Text() const;
  std::string Markdown() const;
  std::string Csv() const;

 private:
  std::vector<std::string> headers_;
  std::vector<std::vector<std::string>> rows_;
  std::vector<bool> left_;  // per column; empty = only the first

  bool IsLeft(std::size_t column) const {
    return column == 0 || (column < left_.size() && left_[column]);
  }
};

// Number formatting for table cells: "n/a" for a missing value.
std::string FormatFixed(std::optional<double> value, int decimals);
std::string FormatCount(std::optional<double> value);  // 1234567 (no separators)
std::string CsvField(const std::string& text);

}  // namespace linemap::bench

#endif  // LINEMAP_TOOLS_BENCH_TABLE_H_
