#include "surfaces/expression_syntax.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <string>

namespace offsetgen {
namespace {

// Length of the UTF-8 character starting at s[i], or 0 when the bytes there are not valid UTF-8.
size_t utf8_length(const std::string& s, size_t i) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = byte(i);
  size_t n = 0;
  if (c < 0x80) return 1;
  if (c >= 0xC2 && c <= 0xDF) n = 2;
  else if (c >= 0xE0 && c <= 0xEF) n = 3;
  else if (c >= 0xF0 && c <= 0xF4) n = 4;
  else return 0;
  if (i + n > s.size()) return 0;
  for (size_t k = 1; k < n; ++k)
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
  // overlong forms and surrogates
  if (n == 3 && ((c == 0xE0 && byte(i + 1) < 0xA0) || (c == 0xED && byte(i + 1) >= 0xA0))) return 0;
  if (n == 4 && ((c == 0xF0 && byte(i + 1) < 0x90) || (c == 0xF4 && byte(i + 1) >= 0x90))) return 0;
  return n;
}

// The character at s[i] for a message: 'x', '·' (U+00B7), or byte 0xFF.
std::string describe_character(const std::string& s, size_t i) {
  const size_t n = utf8_length(s, i);
  if (n == 0) return fmt::format("byte 0x{:02X} (not UTF-8)", static_cast<unsigned char>(s[i]));
  if (n == 1) {
    if (std::isprint(static_cast<unsigned char>(s[i]))) return std::string("'") + s[i] + "'";
    return fmt::format("control character 0x{:02X}", static_cast<unsigned char>(s[i]));
  }
  char32_t code = static_cast<unsigned char>(s[i]) & (0xFF >> (n + 1));
  for (size_t k = 1; k < n; ++k) code = (code << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3F);
  return fmt::format("'{}' (U+{:04X})", s.substr(i, n), static_cast<unsigned>(code));
}

class Parser {
 public:
  explicit Parser(const std::string& text) : s_(text) {}

  std::optional<SyntaxProblem> run() {
    skip();
    if (at_end()) return fail("the expression is empty");
    if (!expression()) return problem_;
    skip();
    if (!at_end()) {
      if (s_[i_] == ')') return fail("unbalanced ')'");
      return fail("unexpected " + describe_character(s_, i_) + " after a complete expression");
    }
    return std::nullopt;
  }

 private:
  bool at_end() const { return i_ >= s_.size(); }
  void skip() {
    while (!at_end() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  std::optional<SyntaxProblem> fail(const std::string& message) {
    problem_ = SyntaxProblem{column_of(s_, i_), message};
    return problem_;
  }
  bool error(const std::string& message) {
    fail(message);
    return false;
  }

  bool expression() {
    if (!term()) return false;
    for (skip(); !at_end() && (s_[i_] == '+' || s_[i_] == '-'); skip()) {
      ++i_;
      if (!term()) return false;
    }
    return true;
  }
  bool term() {
    if (!unary()) return false;
    for (skip(); !at_end() && (s_[i_] == '*' || s_[i_] == '/'); skip()) {
      ++i_;
      if (!unary()) return false;
    }
    return true;
  }
  bool unary() {
    skip();
    if (!at_end() && (s_[i_] == '+' || s_[i_] == '-')) {
      ++i_;
      if (!deeper()) return false;
      const bool ok = unary();
      --depth_;
      return ok;
    }
    return power();
  }
  // Nesting (parentheses, calls, signs) is bounded, so no input can exhaust the stack here or in GiNaC.
  bool deeper() {
    if (++depth_ <= kMaxNesting) return true;
    --depth_;
    return error("the expression is nested too deeply (more than " + std::to_string(kMaxNesting) +
                 " levels of parentheses, calls or signs)");
  }
  bool at_power() const { return !at_end() && (s_[i_] == '^' || s_.compare(i_, 2, "**") == 0); }  // Python's ** too
  bool power() {
    if (!primary()) return false;
    skip();
    if (!at_power()) return true;
    if (in_exponent_)
      return error("a chained power like x^y^z is ambiguous (and GiNaC cannot read it): write x^(y^z) or (x^y)^z");
    i_ += s_[i_] == '^' ? 1 : 2;
    in_exponent_ = true;
    const bool ok = unary();
    in_exponent_ = false;
    return ok;
  }
  // Parentheses and call arguments start a fresh context: x^(y^z) is fine.
  bool nested_expression() {
    if (!deeper()) return false;
    const bool saved = in_exponent_;
    in_exponent_ = false;
    const bool ok = expression();
    in_exponent_ = saved;
    --depth_;
    return ok;
  }
  bool primary() {
    skip();
    if (at_end()) return error("the expression ends where a number, name or '(' is expected");
    const char c = s_[i_];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      while (!at_end() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_')) ++i_;
      skip();
      if (!at_end() && s_[i_] == '(') {
        ++i_;
        skip();
        if (!at_end() && s_[i_] == ')') return error("a function call needs an argument");
        for (;;) {
          if (!nested_expression()) return false;
          skip();
          if (!at_end() && s_[i_] == ',') {
            ++i_;
            continue;
          }
          if (!at_end() && s_[i_] == ')') {
            ++i_;
            return true;
          }
          return error("expected ',' or ')' to close the function call");
        }
      }
      return true;
    }
    if (c == '(') {
      const size_t open = i_;
      ++i_;
      if (!nested_expression()) return false;
      skip();
      if (at_end() || s_[i_] != ')') {
        if (at_end()) {
          i_ = open;
          return error("this '(' is never closed");
        }
        return error("expected ')'");
      }
      ++i_;
      return true;
    }
    return error("unexpected " + describe_character(s_, i_) + " where a number, name or '(' is expected");
  }
  bool number() {
    bool digits = false;
    while (!at_end() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_, digits = true;
    if (!at_end() && s_[i_] == '.') {
      ++i_;
      while (!at_end() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_, digits = true;
    }
    if (!digits) return error("malformed number");
    if (!at_end() && (s_[i_] == 'e' || s_[i_] == 'E')) {
      size_t save = i_++;
      if (!at_end() && (s_[i_] == '+' || s_[i_] == '-')) ++i_;
      if (at_end() || !std::isdigit(static_cast<unsigned char>(s_[i_]))) {
        i_ = save;
        return error("malformed exponent in a number");
      }
      while (!at_end() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
    }
    return true;
  }

  const std::string& s_;
  size_t i_ = 0;
  bool in_exponent_ = false;
  int depth_ = 0;
  static constexpr int kMaxNesting = 200;
  std::optional<SyntaxProblem> problem_;
};

}  // namespace

std::optional<SyntaxProblem> find_syntax_problem(const std::string& text) { return Parser(text).run(); }

int column_of(const std::string& text, size_t byte_index) {
  int column = 1;
  for (size_t i = 0; i < byte_index && i < text.size();) {
    const size_t n = utf8_length(text, i);
    i += n == 0 ? 1 : n;
    ++column;
  }
  return column;
}

std::string printable(const std::string& text) {
  std::string out;
  for (size_t i = 0; i < text.size();) {
    const size_t n = utf8_length(text, i);
    const auto c = static_cast<unsigned char>(text[i]);
    if (n == 0 || (n == 1 && c < 0x20 && c != '\t') || c == 0x7F) {
      out += fmt::format("\\x{:02X}", c);
      ++i;
    } else {
      out.append(text, i, n);
      i += n;
    }
  }
  return out;
}

std::string caret_line(const std::string& text, int column, int indent) {
  std::string pad(static_cast<size_t>(indent), ' ');
  // Escapes widen the printed text: the caret counts printed characters up to the column.
  std::string before;
  size_t i = 0;
  for (int c = 1; c < column && i < text.size(); ++c) {
    const size_t n = utf8_length(text, i);
    before += text.substr(i, n == 0 ? 1 : n);
    i += n == 0 ? 1 : n;
  }
  const std::string shown = printable(before);
  int width = 0;
  for (size_t k = 0; k < shown.size(); k += std::max<size_t>(1, utf8_length(shown, k))) ++width;
  return pad + printable(text) + "\n" + pad + std::string(static_cast<size_t>(width), ' ') + "^";
}

}  // namespace offsetgen
