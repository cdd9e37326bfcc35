#include "pathspace/study/table.h"

#include <fmt/format.h>

#include "pathspace/io/atomic_file.h"

namespace pathspace::study {

namespace {

std::string csv_escape(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string s = "\"";
  for (char c : text) {
    if (c == '"') s += '"';
    s += c;
  }
  return s + "\"";
}

}  // namespace

Table& Table::column(std::string name, std::string format, std::string field) {
  columns.push_back({std::move(name), std::move(field), std::move(format)});
  return *this;
}

std::vector<Column> Table::effective_columns() const {
  if (!columns.empty()) return columns;
  std::vector<Column> out;
  for (const Record& r : rows)
    for (const Field& f : r.fields()) {
      bool seen = false;
      for (const Column& c : out) seen = seen || c.name == f.name;
      if (!seen) out.push_back({f.name, {}, {}});
    }
  return out;
}

std::string cell_text(const Value& value, const std::string& format) {
  if (const int64_t* i = std::get_if<int64_t>(&value))
    return format.empty() ? std::to_string(*i) : fmt::format(fmt::runtime(format), *i);
  if (const double* d = std::get_if<double>(&value)) return fmt::format(fmt::runtime(format.empty() ? "{:.6g}" : format), *d);
  if (const bool* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
  if (const std::string* s = std::get_if<std::string>(&value)) return *s;
  return {};
}

std::string to_csv(const Table& table) {
  std::string out;
  for (const std::string& c : table.comments) out += "# " + c + "\n";
  const std::vector<Column> columns = table.effective_columns();
  // Appended piecewise: `"," + std::string` trips GCC 12's false -Wrestrict (PR 105329).
  for (size_t i = 0; i < columns.size(); ++i) {
    if (i) out += ',';
    out += csv_escape(columns[i].name);
  }
  out += '\n';
  for (const Record& r : table.rows) {
    for (size_t i = 0; i < columns.size(); ++i) {
      const Value* v = r.find(columns[i].source());
      if (i) out += ',';
      out += csv_escape(v ? cell_text(*v, columns[i].format) : std::string());
    }
    out += '\n';
  }
  return out;
}

nlohmann::ordered_json to_json(const Table& table) {
  const std::vector<Column> columns = table.effective_columns();
  nlohmann::ordered_json j;
  j["comments"] = table.comments;
  j["columns"] = nlohmann::ordered_json::array();
  for (const Column& c : columns) j["columns"].push_back(c.name);
  j["rows"] = nlohmann::ordered_json::array();
  for (const Record& r : table.rows) {
    nlohmann::ordered_json row = nlohmann::ordered_json::object();
    for (const Column& c : columns)
      if (const Value* v = r.find(c.source())) row[c.name] = to_json(*v);
    j["rows"].push_back(std::move(row));
  }
  return j;
}

void write_csv(const std::string& path, const Table& table) { write_text_file(path, to_csv(table)); }

void write_json(const std::string& path, const Table& table) { write_text_file(path, to_json(table).dump(2) + "\n"); }

}  // namespace pathspace::study
