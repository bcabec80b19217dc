#include "emit/c_names.h"

#include <cctype>
#include <set>

namespace offsetgen::c_names {
namespace {

// C99 through C23 and C++17/C++20 keywords (alternative tokens included).
const std::set<std::string>& keywords() {
  static const std::set<std::string> words = {"alignas",
                                              "alignof",
                                              "and",
                                              "and_eq",
                                              "asm",
                                              "auto",
                                              "bitand",
                                              "bitor",
                                              "bool",
                                              "break",
                                              "case",
                                              "catch",
                                              "char",
                                              "char8_t",
                                              "char16_t",
                                              "char32_t",
                                              "class",
                                              "co_await",
                                              "co_return",
                                              "co_yield",
                                              "compl",
                                              "concept",
                                              "const",
                                              "consteval",
                                              "constexpr",
                                              "constinit",
                                              "const_cast",
                                              "continue",
                                              "decltype",
                                              "default",
                                              "delete",
                                              "do",
                                              "double",
                                              "dynamic_cast",
                                              "else",
                                              "enum",
                                              "explicit",
                                              "export",
                                              "extern",
                                              "false",
                                              "float",
                                              "for",
                                              "friend",
                                              "goto",
                                              "if",
                                              "inline",
                                              "int",
                                              "long",
                                              "mutable",
                                              "namespace",
                                              "new",
                                              "noexcept",
                                              "not",
                                              "not_eq",
                                              "nullptr",
                                              "operator",
                                              "or",
                                              "or_eq",
                                              "private",
                                              "protected",
                                              "public",
                                              "register",
                                              "reinterpret_cast",
                                              "requires",
                                              "restrict",
                                              "return",
                                              "short",
                                              "signed",
                                              "sizeof",
                                              "static",
                                              "static_assert",
                                              "static_cast",
                                              "struct",
                                              "switch",
                                              "template",
                                              "this",
                                              "thread_local",
                                              "throw",
                                              "true",
                                              "try",
                                              "typedef",
                                              "typeid",
                                              "typename",
                                              "typeof",
                                              "typeof_unqual",
                                              "union",
                                              "unsigned",
                                              "using",
                                              "virtual",
                                              "void",
                                              "volatile",
                                              "wchar_t",
                                              "while",
                                              "xor",
                                              "xor_eq"};
  return words;
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

}  // namespace

std::optional<std::string> reserved(const std::string& identifier) {
  if (keywords().count(identifier)) return "'" + identifier + "' is a C or C++ keyword";
  if (starts_with(identifier, "__") ||
      (identifier.size() > 1 && identifier[0] == '_' && std::isupper(static_cast<unsigned char>(identifier[1]))))
    return "names beginning with __ or _ and a capital letter are reserved to the C implementation";
  if (starts_with(identifier, "_")) return "names beginning with _ are reserved at file scope in C";
  if (identifier.find("__") != std::string::npos) return "names containing __ are reserved in C++";
  if (starts_with(identifier, "offsetgen_"))
    return "names beginning with offsetgen_ belong to the header's own helpers (and offsetgen check's wrappers)";
  return std::nullopt;
}

}  // namespace offsetgen::c_names
