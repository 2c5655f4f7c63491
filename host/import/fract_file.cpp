#include "import/fract_file.hpp"

#include "io/echo.hpp"
#include "io/printable.hpp"

#include <cstdlib>
#include <fstream>

namespace fr {
namespace {

bool is_key_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

}  // namespace

std::string fract_where(const FractFile& f, int line, const std::string& key) {
  std::string out = printable(f.file.string());
  if (line > 0) out.append(":").append(std::to_string(line));
  out.append(": ");
  if (!key.empty()) out.append(echo(key)).append(": ");
  return out;
}

FractFile parse_fract(const std::string& text, const std::filesystem::path& file) {
  FractFile f;
  f.file = file;
  auto fail = [&](int line, const std::string& key, const std::string& what) {
    throw FractError(fract_where(f, line, key) + what);
  };
  if (text.empty())
    fail(0, "",
         "empty file (a Mandelbulber settings file starts with '# Mandelbulber settings file')");
  if (text.size() > kMaxFractBytes)
    fail(0, "",
         "larger than " + std::to_string(kMaxFractBytes >> 20) + " MiB: not a settings file");

  enum class Section { None, Main, Fractal, Skipped } section = Section::None;
  int slot = 0;
  bool header = false;
  size_t start = 0;
  for (int number = 1; start < text.size(); ++number) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string raw = text.substr(start, end - start);
    start = end + 1;
    if (raw.size() > kMaxFractLineChars)
      fail(number, "",
           "a line of " + std::to_string(raw.size()) + " characters (at most " +
               std::to_string(kMaxFractLineChars) + "): not a settings file");
    for (unsigned char c : raw)
      if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7f)
        fail(number, "",
             "a control byte (0x" + std::string(1, "0123456789abcdef"[c >> 4]) +
                 std::string(1, "0123456789abcdef"[c & 15]) + "): not a text settings file");
    const std::string line = trim(raw);
    if (line.empty()) continue;
    if (!header) {
      if (line != "# Mandelbulber settings file")
        fail(number, "",
             "not a Mandelbulber settings file (its first line should be '# "
             "Mandelbulber settings file', it is '" +
                 echo(line) + "')");
      header = true;
      continue;
    }
    if (line[0] == '#') {
      if (line.rfind("# version ", 0) == 0) {
        const std::string v = trim(line.substr(10));
        char* stop = nullptr;
        const double version = std::strtod(v.c_str(), &stop);
        if (v.empty() || *stop != '\0' || !(version > 0 && version < 100))
          fail(number, "", "version '" + echo(v) + "' is not a number like 2.20");
        f.version = version;
      } else if (line == "# only modified parameters") {
        f.only_modified = true;
      }
      continue;
    }
    if (line[0] == '[') {
      if (line.back() != ']') fail(number, "", "a section header needs its ']'");
      const std::string name = line.substr(1, line.size() - 2);
      if (name == "main_parameters") {
        section = Section::Main;
      } else if (name.rfind("fractal_", 0) == 0 && name.size() == 9 && name[8] >= '1' &&
                 name[8] <= '0' + kFractFormulaSlots) {
        section = Section::Fractal;
        slot = name[8] - '1';
      } else {
        section = Section::Skipped;  // [keyframes], [frames], [description], ...: not geometry
      }
      continue;
    }
    if (section == Section::Skipped) continue;
    if (section == Section::None)
      fail(number, "", "a value before the first section ([main_parameters])");
    size_t k = 0;
    while (k < line.size() && is_key_char(line[k])) ++k;
    const std::string key = line.substr(0, k);
    if (key.empty() || k == line.size() || (line[k] != ' ' && line[k] != '\t'))
      fail(number, "", "expected 'name value;', got '" + echo(line) + "'");
    if (line.back() != ';') fail(number, key, "the value does not end with ';'");
    const std::string value = trim(line.substr(k, line.size() - k - 1));
    auto& table = section == Section::Main ? f.main : f.fractal[slot];
    auto [it, inserted] = table.emplace(key, FractEntry{value, number});
    if (!inserted && it->second.value != value)
      fail(number, key,
           "given twice with different values (line " + std::to_string(it->second.line) + " too)");
  }
  if (!header)
    fail(0, "", "not a Mandelbulber settings file (no '# Mandelbulber settings file' line)");
  return f;
}

FractFile load_fract(const std::filesystem::path& file) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    throw FractError(printable(file.string()) + ": is a folder, not a settings file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw FractError(printable(file.string()) + ": cannot be opened");
  std::string text(kMaxFractBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad()) throw FractError(printable(file.string()) + ": cannot be read");
  text.resize(static_cast<size_t>(in.gcount()));
  return parse_fract(text, file);
}

}  // namespace fr
