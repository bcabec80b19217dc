#include "surfaces/expression_syntax.h"

#include <cctype>

namespace offsetgen {
namespace {

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
      return fail(std::string("unexpected '") + s_[i_] + "' after a complete expression");
    }
    return std::nullopt;
  }

 private:
  bool at_end() const { return i_ >= s_.size(); }
  void skip() {
    while (!at_end() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  std::optional<SyntaxProblem> fail(const std::string& message) {
    problem_ = SyntaxProblem{static_cast<int>(i_) + 1, message};
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
      return unary();
    }
    return power();
  }
  bool power() {
    if (!primary()) return false;
    skip();
    if (!at_end() && (s_[i_] == '^' || s_.compare(i_, 2, "**") == 0)) {  // Python's ** too
      i_ += s_[i_] == '^' ? 1 : 2;
      return unary();
    }
    return true;
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
          if (!expression()) return false;
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
      if (!expression()) return false;
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
    return error(std::string("unexpected '") + c + "' where a number, name or '(' is expected");
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
  std::optional<SyntaxProblem> problem_;
};

}  // namespace

std::optional<SyntaxProblem> find_syntax_problem(const std::string& text) { return Parser(text).run(); }

std::string caret_line(const std::string& text, int column, int indent) {
  std::string pad(static_cast<size_t>(indent), ' ');
  return pad + text + "\n" + pad + std::string(static_cast<size_t>(column > 0 ? column - 1 : 0), ' ') + "^";
}

}  // namespace offsetgen
