// Table: rows of Records with chosen columns, written as CSV or JSON. The experiment runner's
// results become one (results_table in experiment_output.h); a study that measures without the
// runner (studies/psf2021/hash_table_csv.cpp) builds its own and uses the same writers.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pathspace/study/record.h"

namespace pathspace::study {

struct Column {
  std::string name;    // header
  std::string field;   // the record field it shows; empty: `name`
  std::string format;  // fmt format of a number ("{:.5g}", "{:.3f}"); empty: integers exact, numbers {:.6g}
  const std::string& source() const { return field.empty() ? name : field; }
};

struct Table {
  std::vector<std::string> comments;  // CSV: "# " lines before the header; JSON: "comments"
  std::vector<Column> columns;        // empty: every field of the rows, in order of first appearance
  std::vector<Record> rows;

  Table& column(std::string name, std::string format = {}, std::string field = {});
  // The columns written: `columns`, or those derived from the rows.
  std::vector<Column> effective_columns() const;
};

// One cell as text: a field missing in the row (or std::monostate) is empty.
std::string cell_text(const Value& value, const std::string& format);

// Header line, then one line per row; text with commas, quotes or line breaks is quoted.
std::string to_csv(const Table& table);
// {"comments": [...], "columns": [...], "rows": [{column: value}, ...]}; numbers keep their type
// (formats apply to CSV only).
nlohmann::ordered_json to_json(const Table& table);

// Atomic writes (io/atomic_file.h).
void write_csv(const std::string& path, const Table& table);
void write_json(const std::string& path, const Table& table);

}  // namespace pathspace::study
