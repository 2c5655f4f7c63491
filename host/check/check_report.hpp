// check_report.hpp — the findings of `fractalis check`: one row per check, as a table or JSON.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace fr {

enum class CheckStatus { Pass, Warn, Fail };
const char* check_status_name(CheckStatus status);

struct CheckRow {
  std::string check;  // "descriptor", "de-compiles", "de-lipschitz", ...
  CheckStatus status = CheckStatus::Pass;
  std::string detail;  // the reason, with the numbers and the place ("worst 3.01 at (0.2, ...)")
};

struct CheckReport {
  std::string file;      // the plugin as the user named it
  std::string scene_id;  // empty when it did not load
  std::vector<CheckRow> rows;
  bool failed() const;
};

// The table a person reads: check, PASS/WARN/FAIL, detail; then one summary line.
void write_check_table(const CheckReport& report, std::ostream& out);
// The same as JSON: {"file", "scene", "result", "checks": [{"check", "status", "detail"}]}.
std::string check_report_json(const CheckReport& report);

}  // namespace fr
