#include "files/csv.h"

#include <gtest/gtest.h>

#include "tests/input_error_message.h"

namespace walkers {
namespace {

// the message of the InputError `f` throws, or "" if it throws none
template <typename F>
std::string Error(const F& f) {
  return testing::InputErrorMessage(f);
}

TEST(CsvTest, QuotedFieldsHoldCommasAndQuotesAndComeBackAsWritten) {
  const std::string failure = "CVODE: \"error test\" failed, at t = 1";
  const std::vector<std::string> fields = SplitCsvLine("1," + CsvQuoted(failure) + ",,x");
  ASSERT_EQ(fields.size(), 4u);
  EXPECT_EQ(fields[1], failure);
  EXPECT_EQ(fields[2], "");
  EXPECT_EQ(CsvQuoted("a\"b"), "\"a\"\"b\"");
}

TEST(CsvTest, TheReaderSkipsEmptyLinesAndCountsRowsAsLines) {
  CsvReader rows("n,x\n1,0.5\n\n2,-3e2\n", "f.csv");
  EXPECT_EQ(rows.Column("x"), 1);
  ASSERT_TRUE(rows.Next());
  EXPECT_EQ(rows.row(), 2);
  EXPECT_EQ(rows.Integer(0, 0, 9), 1);
  EXPECT_EQ(rows.Number(1), 0.5);
  ASSERT_TRUE(rows.Next());
  EXPECT_EQ(rows.row(), 4);
  EXPECT_EQ(rows.Number(1), -300.0);
  EXPECT_FALSE(rows.Next());
}

TEST(CsvTest, MessagesNameTheFileTheRowAndTheColumn) {
  EXPECT_EQ(Error([] { CsvReader("", "f.csv"); }), "f.csv: no header line");
  EXPECT_EQ(Error([] { CsvReader("n\n1\n", "f.csv").Column("x"); }), "f.csv: no column 'x'");
  EXPECT_EQ(Error([] {
              CsvReader rows("n,x\n1\n", "f.csv");
              rows.Next();
            }),
            "f.csv: row 2 has 1 fields, the header 2");
  CsvReader rows("n,x\n12,nan\n", "f.csv");
  ASSERT_TRUE(rows.Next());
  EXPECT_EQ(Error([&] { rows.Number(1); }), "f.csv: row 2, column 'x': 'nan' is not a finite number");
  EXPECT_EQ(Error([&] { rows.Integer(1, 0, 9); }), "f.csv: row 2, column 'x': 'nan' is not an integer");
  EXPECT_EQ(Error([&] { rows.Integer(0, 0, 9); }),
            "f.csv: row 2, column 'n': '12' is outside its allowed range [0, 9]");
}

}  // namespace
}  // namespace walkers
