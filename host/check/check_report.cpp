#include "check/check_report.hpp"

#include "io/check.hpp"
#include "io/json_text.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <ostream>

namespace fr {
const char* check_status_name(CheckStatus status) {
  switch (status) {
    case CheckStatus::Pass:
      return "pass";
    case CheckStatus::Warn:
      return "warn";
    case CheckStatus::Fail:
      return "fail";
  }
  FR_CHECK(false, "a CheckStatus without a name");
  return "fail";  // not reached
}

bool CheckReport::failed() const {
  for (const CheckRow& r : rows)
    if (r.status == CheckStatus::Fail) return true;
  return false;
}

void write_check_table(const CheckReport& report, std::ostream& out) {
  out << "fractalis check " << report.file
      << (report.scene_id.empty() ? "" : " (scene '" + report.scene_id + "')") << "\n\n";
  size_t width = 5;
  for (const CheckRow& r : report.rows) width = std::max(width, r.check.size());
  int counts[3] = {0, 0, 0};
  for (const CheckRow& r : report.rows) {
    ++counts[static_cast<int>(r.status)];
    const char* tag = r.status == CheckStatus::Pass   ? "PASS"
                      : r.status == CheckStatus::Warn ? "WARN"
                                                      : "FAIL";
    out << "  " << r.check << std::string(width - r.check.size() + 2, ' ') << tag << "  "
        << r.detail << "\n";
  }
  out << "\n"
      << counts[0] << " passed, " << counts[1] << " warned, " << counts[2]
      << " failed: " << (report.failed() ? "FAIL" : "PASS") << "\n";
}

std::string check_report_json(const CheckReport& report) {
  nlohmann::ordered_json checks = nlohmann::ordered_json::array();
  for (const CheckRow& r : report.rows)
    checks.push_back(
        {{"check", r.check}, {"status", check_status_name(r.status)}, {"detail", r.detail}});
  const nlohmann::ordered_json j = {
      {"file", report.file},
      {"scene", report.scene_id},
      {"result", report.failed() ? "fail" : "pass"},
      {"checks", checks},
  };
  return json_text(j);
}

}  // namespace fr
