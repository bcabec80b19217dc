#include "run/glsl_source.h"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace offsetgen::glsl {
namespace {

int count_lines(const std::string& s) {
  if (s.empty()) return 0;
  auto n = static_cast<int>(std::count(s.begin(), s.end(), '\n'));
  return s.back() == '\n' ? n : n + 1;
}

// Line `line` (1-based) of `text`, without its newline; empty when out of range.
std::string nth_line(const std::string& text, int line) {
  std::istringstream in(text);
  std::string l;
  for (int i = 1; std::getline(in, l); ++i) {
    if (i == line) return l;
  }
  return {};
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

// Keeps only what sits at brace depth 0, so function bodies cannot produce false matches.
std::string top_level_only(const std::string& src) {
  std::string out;
  out.reserve(src.size());
  int depth = 0;
  for (char ch : src) {
    if (ch == '{') {
      if (depth == 0) out += '{';
      ++depth;
    } else if (ch == '}') {
      depth = std::max(0, depth - 1);
      if (depth == 0) out += '}';
    } else if (depth == 0) {
      out += ch;
    }
  }
  return out;
}

// Drops preprocessor lines (#ifndef, #define ...): they are never function definitions.
std::string drop_preprocessor(const std::string& src) {
  std::istringstream in(src);
  std::string line, out;
  while (std::getline(in, line)) {
    if (trim(line).rfind('#', 0) == 0) line.clear();
    out += line;
    out += '\n';
  }
  return out;
}

GlslParam parse_param(const std::string& decl) {
  static const std::vector<std::string> kPrecision{"highp", "mediump", "lowp"};
  std::istringstream in(decl);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  GlslParam p;
  std::vector<std::string> rest;
  for (const auto& w : words) {
    if (w == "in" || w == "out" || w == "inout") {
      p.qualifier = w;
    } else if (w == "const" || std::find(kPrecision.begin(), kPrecision.end(), w) != kPrecision.end()) {
      continue;
    } else {
      rest.push_back(w);
    }
  }
  if (!rest.empty()) p.type = rest[0];
  if (rest.size() > 1) p.name = rest[1];
  return p;
}

}  // namespace

std::string HostedSource::describe_line(int host_line) const {
  const int snippet_line = host_line - snippet_first_line + 1;
  std::ostringstream os;
  if (snippet_line >= 1 && snippet_line <= snippet_line_count) {
    os << "snippet line " << snippet_line << ": " << nth_line(snippet, snippet_line);
  } else {
    os << "host line " << host_line << ": " << nth_line(text, host_line);
  }
  return os.str();
}

HostedSource assemble(const std::string& prologue, const std::string& snippet, const std::string& epilogue) {
  HostedSource s;
  s.snippet = snippet;
  s.text = prologue;
  if (!s.text.empty() && s.text.back() != '\n') s.text += '\n';
  s.snippet_first_line = count_lines(s.text) + 1;
  s.snippet_line_count = count_lines(snippet);
  s.text += snippet;
  if (!snippet.empty() && snippet.back() != '\n') s.text += '\n';
  s.text += epilogue;
  return s;
}

std::vector<int> referenced_lines(const std::string& log) {
  // glslang: "ERROR: /tmp/x.frag:12: ..." or "ERROR: 0:12: ..."; Mesa: "0:12(5): error: ...".
  static const std::regex kLoc(R"((?:^|[\s])[^\s:]*:(\d+)(?:\(\d+\))?:)");
  // Lines named by errors; warnings' lines only when there is no error at all, so a harmless
  // warning (e.g. glslang's Vulkan default-precision note) does not point at an innocent line.
  std::vector<int> errors, others;
  std::istringstream in(log);
  for (std::string l; std::getline(in, l);) {
    std::smatch m;
    if (!std::regex_search(l, m, kLoc)) continue;
    const int n = std::stoi(m[1].str());
    auto& bucket = (l.find("ERROR") != std::string::npos || l.find("error") != std::string::npos) ? errors : others;
    if (std::find(bucket.begin(), bucket.end(), n) == bucket.end()) bucket.push_back(n);
  }
  return errors.empty() ? others : errors;
}

std::string annotate_log(const std::string& log, const HostedSource& source) {
  std::string out = trim(log);
  const auto lines = referenced_lines(log);
  if (!lines.empty()) out += "\nat:";
  for (int n : lines) out += "\n  " + source.describe_line(n);
  return out;
}

std::string strip_comments(const std::string& src) {
  // Reads from `src`, blanks in `out`: the end-of-comment test must see the original bytes.
  std::string out = src;
  const std::size_t n = src.size();
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (src[i] == '/' && src[i + 1] == '/') {
      for (; i < n && src[i] != '\n'; ++i) out[i] = ' ';
    } else if (src[i] == '/' && src[i + 1] == '*') {
      const std::size_t close = src.find("*/", i + 2);
      const std::size_t end = close == std::string::npos ? n : close + 2;
      for (std::size_t j = i; j < end; ++j) {
        if (src[j] != '\n') out[j] = ' ';
      }
      i = end - 1;
    }
  }
  return out;
}

std::vector<GlslFunction> scan_functions(const std::string& snippet) {
  const std::string top = top_level_only(drop_preprocessor(strip_comments(snippet)));
  // [precision] type name ( params ) {   -- the '{' tells a definition from a prototype.
  static const std::regex kDef(
      R"((?:\b(?:highp|mediump|lowp)\s+)?\b([A-Za-z_]\w*)\s+([A-Za-z_]\w*)\s*\(([^()]*)\)\s*\{)");
  std::vector<GlslFunction> found;
  for (auto it = std::sregex_iterator(top.begin(), top.end(), kDef); it != std::sregex_iterator(); ++it) {
    GlslFunction f;
    f.return_type = (*it)[1].str();
    f.name = (*it)[2].str();
    const std::string params = trim((*it)[3].str());
    if (!params.empty() && params != "void") {
      std::istringstream in(params);
      for (std::string decl; std::getline(in, decl, ',');) f.params.push_back(parse_param(decl));
    }
    const bool seen = std::any_of(found.begin(), found.end(), [&](const GlslFunction& g) { return g.name == f.name; });
    if (!seen) found.push_back(std::move(f));
  }
  return found;
}

std::vector<std::string> declarations_without_highp(const std::string& snippet) {
  // "type name" is a declaration; "type(" is a constructor and needs no qualifier.
  static const std::regex kDecl(
      R"((\b(?:highp|mediump|lowp)\s+)?\b(?:float|vec[234]|mat[234](?:x[234])?)\s+[A-Za-z_]\w*)");
  std::vector<std::string> found;
  std::istringstream in(strip_comments(snippet));
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    ++n;
    if (trim(line).rfind('#', 0) == 0) continue;
    for (auto it = std::sregex_iterator(line.begin(), line.end(), kDecl); it != std::sregex_iterator(); ++it) {
      const std::string qualifier = trim((*it)[1].str());
      if (qualifier == "highp") continue;
      found.push_back("snippet line " + std::to_string(n) + ": " + nth_line(snippet, n));
      break;
    }
  }
  return found;
}

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

}  // namespace offsetgen::glsl
