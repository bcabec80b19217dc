#include "snippet_conventions.h"

#include <algorithm>
#include <cctype>
#include <regex>
#include <sstream>

#include "run/glsl_source.h"

namespace offsetgen::glsl_test {
namespace {

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::string upper(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return s;
}

bool is_ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

struct Directive {
  int line;          // 1-based
  std::string name;  // "ifndef", "define", ...
  std::vector<std::string> args;
};

class Checker {
 public:
  Checker(const std::string& snippet, std::string prefix)
      : original_(split_lines(snippet)), code_(split_lines(glsl::strip_comments(snippet))), prefix_(std::move(prefix)) {
    for (std::size_t i = 0; i < code_.size(); ++i) {
      const std::string t = trim(code_[i]);
      if (t.empty() || t[0] != '#') continue;
      Directive d{static_cast<int>(i) + 1, {}, {}};
      std::istringstream in(t.substr(1));
      in >> d.name;
      for (std::string w; in >> w;) d.args.push_back(w);
      directives_.push_back(d);
      code_[i].clear();  // what remains in code_ is GLSL proper
    }
  }

  std::vector<Violation> run() {
    check_directives();
    for (std::size_t i = 0; i < code_.size(); ++i) check_line(static_cast<int>(i) + 1, code_[i]);
    check_highp();
    check_top_level_names();
    return std::move(found_);
  }

 private:
  void add(const std::string& rule, int line, const std::string& what) {
    std::string msg = "snippet line " + std::to_string(line) + ": " + what;
    if (line >= 1 && line <= static_cast<int>(original_.size())) {
      msg += ": " + trim(original_[static_cast<std::size_t>(line - 1)]);
    }
    found_.push_back({rule, msg});
  }

  void check_directives() {
    const std::string wanted_guard_part = upper(prefix_);
    std::string guard;
    if (directives_.size() < 3 || directives_[0].name != "ifndef" || directives_[0].args.size() != 1 ||
        directives_[1].name != "define" || directives_[1].args != directives_[0].args ||
        directives_.back().name != "endif") {
      add("guard", directives_.empty() ? 1 : directives_[0].line,
          "not wrapped in '#ifndef G' / '#define G' ... '#endif'");
    } else {
      guard = directives_[0].args[0];
      if (guard.find(wanted_guard_part) == std::string::npos) {
        add("guard", directives_[0].line,
            "guard macro " + guard + " does not name the prefix (" + wanted_guard_part +
                "), so two snippets could share it");
      }
      // Nothing but comments and blank lines outside the guard.
      for (std::size_t i = 0; i < code_.size(); ++i) {
        const int line = static_cast<int>(i) + 1;
        if ((line < directives_[0].line || line > directives_.back().line) && !trim(code_[i]).empty()) {
          add("guard", line, "code outside the include guard");
        }
      }
    }
    for (std::size_t i = 0; i < directives_.size(); ++i) {
      const Directive& d = directives_[i];
      const bool is_guard = !guard.empty() && (i == 0 || i == 1 || i + 1 == directives_.size());
      if (is_guard) continue;
      if (d.name == "version") {
        add("version", d.line, "#version belongs to the host shader");
      } else if (d.name == "define") {
        add("define", d.line, "global #define (only the include guard may define a macro)");
      } else {
        add("directive", d.line, "preprocessor directive #" + d.name + " in a paste-safe snippet");
      }
    }
  }

  void check_line(int line, const std::string& text) {
    static const std::regex kPrecision(R"(\bprecision\s+(?:highp|mediump|lowp)\b)");
    static const std::regex kPow(R"(\bpow\s*\()");
    if (std::regex_search(text, kPrecision)) {
      add("precision", line, "precision statement (belongs to the host shader)");
    }
    if (std::regex_search(text, kPow)) {
      add("pow", line, "pow() call (undefined for a negative base; write products)");
    }
    // Numbers: an identifier swallows its digits (vec3, _t12), so what is left is a literal.
    for (std::size_t i = 0; i < text.size();) {
      const char c = text[i];
      if (is_ident_start(c)) {
        while (i < text.size() && is_ident_char(text[i])) ++i;
      } else if (is_digit(c) || (c == '.' && i + 1 < text.size() && is_digit(text[i + 1]))) {
        const std::size_t b = i;
        bool point = false;
        while (i < text.size() && (is_digit(text[i]) || text[i] == '.')) point |= text[i++] == '.';
        if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
          ++i;
          if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
          while (i < text.size() && is_digit(text[i])) ++i;
        }
        while (i < text.size() && is_ident_char(text[i])) ++i;  // suffixes: f, u, ...
        if (!point) {
          add("literal", line, "number '" + text.substr(b, i - b) + "' without a decimal point (write N.0)");
        }
      } else {
        ++i;
      }
    }
  }

  void check_highp() {
    std::string snippet;
    for (const auto& l : original_) snippet += l + "\n";
    for (const std::string& s : glsl::declarations_without_highp(snippet)) {
      found_.push_back({"highp", s + "  (float declaration without highp)"});
    }
  }

  // Top-level statements: everything at brace depth 0 up to ';' or '{', parenthesised parts
  // (parameter lists) dropped. The declared name is the last identifier before '=' or the end.
  void check_top_level_names() {
    int depth = 0, parens = 0;
    std::string statement;
    int statement_line = 0;
    auto finish = [&](int line) {
      std::string s = statement;
      statement.clear();
      if (const auto eq = s.find('='); eq != std::string::npos) s.resize(eq);
      std::string name;
      for (std::size_t i = 0; i < s.size();) {
        if (is_ident_start(s[i])) {
          const std::size_t b = i;
          while (i < s.size() && is_ident_char(s[i])) ++i;
          name = s.substr(b, i - b);
        } else {
          ++i;
        }
      }
      if (name.empty()) return;
      if (name.rfind(prefix_ + "_", 0) != 0) {
        add("prefix", statement_line ? statement_line : line,
            "top-level name '" + name + "' does not start with '" + prefix_ + "_'");
      }
    };
    for (std::size_t li = 0; li < code_.size(); ++li) {
      const int line = static_cast<int>(li) + 1;
      for (char c : code_[li]) {
        if (depth > 0) {
          if (c == '{') ++depth;
          if (c == '}' && --depth == 0) statement_line = 0;
          continue;
        }
        if (c == '(') {
          ++parens;
        } else if (c == ')') {
          parens = std::max(0, parens - 1);
        } else if (parens > 0) {
          continue;
        } else if (c == '{') {
          finish(line);
          depth = 1;
        } else if (c == ';') {
          finish(line);
          statement_line = 0;
        } else {
          if (statement_line == 0 && !std::isspace(static_cast<unsigned char>(c))) {
            statement_line = line;
          }
          statement += c;
        }
      }
      statement += ' ';
    }
  }

  std::vector<std::string> original_;
  std::vector<std::string> code_;  // comments blanked, directive lines emptied
  std::string prefix_;
  std::vector<Directive> directives_;
  std::vector<Violation> found_;
};

}  // namespace

std::vector<Violation> convention_violations(const std::string& snippet, const std::string& prefix) {
  return Checker(snippet, prefix).run();
}

std::vector<Violation> header_comment_violations(const std::string& snippet, const std::string& prefix) {
  std::vector<Violation> found;
  // The comments before the guard, as the user sees them at the top of the file.
  const auto guard = snippet.find("#ifndef");
  const std::string head = snippet.substr(0, guard);
  const std::vector<std::pair<std::string, std::string>> required = {
      {"generated, do not edit", "the 'generated, do not edit' notice"},
      {"description:", "a description: field"},
      {"use:", "a use: field with the signatures"},
      {"inputs and outputs:", "inputs and outputs (with units)"},
      {"sign convention:", "the sign convention"},
      {"accuracy:", "the order and expected accuracy"},
      {"targets:", "the target GLSL versions"},
      {"Command: offsetgen generate", "the generating command"},
  };
  for (const auto& [needle, what] : required) {
    if (head.find(needle) == std::string::npos) {
      found.push_back({"header", "header comment lacks " + what + " ('" + needle + "')"});
    }
  }
  const auto use = head.find("use:");
  const std::string use_block = use == std::string::npos ? "" : head.substr(use);
  for (const auto& f : glsl::scan_functions(snippet)) {
    // <prefix>_sin and <prefix>_cos are the snippet's own trig, called by its functions, not API.
    if (f.name == prefix + "_sin" || f.name == prefix + "_cos") continue;
    if (use_block.find(f.name + "(") == std::string::npos) {
      found.push_back({"header", "use: does not list " + f.name});
    }
  }
  if (head.find(prefix + "_") == std::string::npos) {
    found.push_back({"header", "header comment never names the prefix " + prefix});
  }
  return found;
}

std::string describe(const std::vector<Violation>& violations) {
  std::string out;
  for (const auto& v : violations) out += v.rule + ": " + v.message + "\n";
  return out;
}

}  // namespace offsetgen::glsl_test
