// CSV text as the project's files hold it: a field in double quotes may hold
// commas, and "" inside it is one quote. The reader's messages name the file,
// the row and the column.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace walkers {

// Reads CSV text row by row; empty lines are skipped.
class CsvReader {
 public:
  // Reads the header line; `path` names the file in messages. Throws
  // InputError (files/errors.h) for text without a header.
  CsvReader(std::string text, std::string path);

  const std::vector<std::string>& header() const { return header_; }
  // The index of a column; throws InputError naming the file if there is none.
  int Column(const std::string& name) const;
  // Moves to the next row; false at the end. Throws InputError if the row's
  // number of fields differs from the header's.
  bool Next();
  int row() const { return row_; }  // the line number (the header is row 1)
  const std::vector<std::string>& fields() const { return fields_; }
  // A field as a finite number, or an integer in [lo, hi]; throws InputError
  // "PATH: row N, column 'name': 'text' is not a finite number".
  double Number(int column) const;
  std::int64_t Integer(int column, std::int64_t lo, std::int64_t hi) const;

 private:
  [[noreturn]] void Fail(int column, const std::string& problem) const;

  std::string text_, path_;
  std::size_t at_ = 0;
  int row_ = 1;
  std::vector<std::string> header_, fields_;
};

// The fields of one CSV line.
std::vector<std::string> SplitCsvLine(const std::string& line);

// `text` as one CSV field in double quotes, a quote in it doubled.
std::string CsvQuoted(const std::string& text);

}  // namespace walkers
