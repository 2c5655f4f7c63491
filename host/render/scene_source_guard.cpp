#include "render/scene_source_guard.hpp"

#include "render/cl_runtime.hpp"

#include <cctype>

namespace fr {
namespace {

// What one pass over a source file finds: OpenCL C's comments, strings, character literals,
// preprocessor lines (with their continuations) and nesting, without a real parser. Enough to
// name what a file defines at file scope and what it leaves open.
struct SourceScan {
  struct Named {
    int line;
    std::string word;  // the directive ("define", "undef"), or "function", "type"
    std::string name;
  };
  std::vector<Named> names;
  int open_comment_line = 0;  // 0: none
  std::vector<int> open_if_lines;
  int stray_endif_line = 0;
  int open_brace_line = 0, open_paren_line = 0;
};

bool ident_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool ident_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

SourceScan scan_source(std::string_view s) {
  SourceScan out;
  const size_t n = s.size();
  size_t i = 0;
  int line = 1;
  bool line_start = true;
  int brace = 0, paren = 0;
  int brace_line = 0, paren_line = 0;
  std::string last_ident, candidate;  // candidate: the name before a file-scope '('
  bool after_params = false;          // a file-scope ')' just closed the candidate's parameters
  bool in_typedef = false;
  std::string statement_last;  // last identifier of the file-scope statement (typedef's name)
  bool after_struct = false;

  auto skip_block_comment = [&](size_t& k) {  // k at "/*"; returns false if never closed
    const int start = line;
    k += 2;
    while (k + 1 < n && !(s[k] == '*' && s[k + 1] == '/')) line += s[k++] == '\n';
    if (k + 1 >= n) {
      out.open_comment_line = start;
      k = n;
      return false;
    }
    k += 2;
    return true;
  };
  auto skip_quoted = [&](size_t& k) {  // k at the opening quote; stops at its end or the line's
    const char q = s[k++];
    while (k < n && s[k] != q && s[k] != '\n') k += (s[k] == '\\' && k + 1 < n) ? 2 : 1;
    if (k < n && s[k] == q) ++k;
  };

  while (i < n) {
    const char c = s[i];
    if (c == '\n') {
      ++line;
      line_start = true;
      ++i;
      continue;
    }
    if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
      ++i;
      continue;
    }
    if (c == '\\' && i + 1 < n && s[i + 1] == '\n') {  // a continuation outside a directive
      i += 2;
      ++line;
      continue;
    }
    if (c == '/' && i + 1 < n && s[i + 1] == '*') {
      if (!skip_block_comment(i)) break;
      continue;
    }
    if (c == '/' && i + 1 < n && s[i + 1] == '/') {
      while (i < n && s[i] != '\n') ++i;
      continue;
    }
    if (line_start && c == '#') {
      // A directive: its word and first name, then the rest of its logical line.
      const int directive_line = line;
      ++i;
      while (i < n && (s[i] == ' ' || s[i] == '\t')) ++i;
      std::string word, name;
      while (i < n && ident_char(s[i])) word += s[i++];
      while (i < n && (s[i] == ' ' || s[i] == '\t')) ++i;
      while (i < n && ident_char(s[i])) name += s[i++];
      while (i < n && s[i] != '\n') {
        if (s[i] == '\\' && i + 1 < n && s[i + 1] == '\n') {
          i += 2;
          ++line;
        } else if (s[i] == '/' && i + 1 < n && s[i + 1] == '*') {
          if (!skip_block_comment(i)) break;
        } else if (s[i] == '/' && i + 1 < n && s[i + 1] == '/') {
          while (i < n && s[i] != '\n') ++i;
        } else if (s[i] == '"' || s[i] == '\'') {
          skip_quoted(i);
        } else {
          ++i;
        }
      }
      if (word == "if" || word == "ifdef" || word == "ifndef") {
        out.open_if_lines.push_back(directive_line);
      } else if (word == "endif") {
        if (out.open_if_lines.empty()) {
          if (!out.stray_endif_line) out.stray_endif_line = directive_line;
        } else {
          out.open_if_lines.pop_back();
        }
      } else if ((word == "define" || word == "undef") && !name.empty()) {
        out.names.push_back({directive_line, word, name});
      }
      continue;
    }
    line_start = false;
    if (c == '"' || c == '\'') {
      skip_quoted(i);
      after_params = false;
      continue;
    }
    if (ident_start(c)) {
      std::string word;
      while (i < n && ident_char(s[i])) word += s[i++];
      if (brace == 0 && paren == 0) {
        if (word == "typedef") in_typedef = true;
        if (after_struct) out.names.push_back({line, "type", word});
        after_struct = word == "struct" || word == "union" || word == "enum";
        statement_last = word;
      }
      last_ident = word;
      after_params = false;
      continue;
    }
    ++i;
    switch (c) {
      case '(':
        if (brace == 0 && paren == 0) {
          candidate = last_ident;
          paren_line = line;
        }
        ++paren;
        break;
      case ')':
        if (paren > 0 && --paren == 0 && brace == 0) {
          after_params = true;
          continue;  // keep after_params for the next token
        }
        break;
      case '{':
        if (brace == 0) {
          if (after_params && paren == 0 && !candidate.empty())
            out.names.push_back({line, "function", candidate});
          brace_line = line;
        }
        ++brace;
        break;
      case '}':
        if (brace > 0) --brace;
        break;
      case ';':
        if (brace == 0 && paren == 0) {
          if (in_typedef && !statement_last.empty())
            out.names.push_back({line, "type", statement_last});
          in_typedef = false;
          statement_last.clear();
        }
        break;
      default:
        break;
    }
    after_params = false;
    after_struct = false;
    last_ident.clear();
  }
  if (brace > 0) out.open_brace_line = brace_line;
  if (paren > 0) out.open_paren_line = paren_line;
  return out;
}

bool reserved(const std::string& name) {
  return name.rfind("FR_", 0) == 0 || name.rfind("fr_", 0) == 0;
}

}  // namespace

HostKernelNames collect_host_names(const std::vector<std::string_view>& before,
                                   const std::vector<std::string_view>& after) {
  HostKernelNames host;
  // The assembler's own generated names (kernel_assembly.cpp) that do not begin with FR_.
  host.defined = {"PARAM", "scene_params_t"};
  for (const auto* files : {&before, &after})
    for (std::string_view text : *files)
      for (const auto& named : scan_source(text).names) {
        if (named.word == "undef") continue;
        host.defined.insert(named.name);
        if (files == &after && named.word == "function") host.functions_after.insert(named.name);
      }
  return host;
}

std::vector<std::string> guard_scene_source(const std::string& scene_id, std::string_view file_name,
                                            std::string_view text, const HostKernelNames& host) {
  const SourceScan scan = scan_source(text);
  auto refuse = [&](int line, const std::string& why) {
    throw KernelBuildError("scene '" + scene_id + "': " + std::string(file_name) + ":" +
                           std::to_string(line) + ": " + why);
  };
  std::vector<std::string> macros;
  for (const auto& named : scan.names) {
    if (named.word == "define" || named.word == "undef") {
      const std::string what = "`#" + named.word + " " + named.name + "`";
      if (reserved(named.name))
        refuse(named.line, what +
                               ": names beginning FR_ or fr_ are the host's (its switches "
                               "and hooks); choose another name");
      if (host.defined.count(named.name))
        refuse(named.line, what + " would change the host's own " + named.name +
                               " for all of its code after the scene's; choose another name");
      bool known = false;
      for (const auto& m : macros) known |= m == named.name;
      if (!known) macros.push_back(named.name);
    } else if (named.word == "function" && host.functions_after.count(named.name)) {
      refuse(named.line, "function " + named.name +
                             "() has the name of one of the host's render stages; choose "
                             "another name");
    }
  }
  if (scan.open_comment_line)
    refuse(scan.open_comment_line,
           "a comment opened here is never closed (it would hide the host's code after it)");
  if (!scan.open_if_lines.empty())
    refuse(scan.open_if_lines.back(), "this #if has no #endif in the file");
  if (scan.stray_endif_line) refuse(scan.stray_endif_line, "#endif without #if");
  if (scan.open_paren_line) refuse(scan.open_paren_line, "a '(' opened here is never closed");
  if (scan.open_brace_line) refuse(scan.open_brace_line, "a '{' opened here is never closed");
  return macros;
}

}  // namespace fr
