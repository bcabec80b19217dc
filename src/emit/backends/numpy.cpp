// The NumPy target: a Python module, <prefix>.py, that imports NumPy and nothing else. Its functions
// take floats or arrays, broadcast them against each other and compute in float64 (np.asarray(a,
// np.float64)[()] on entry: float32 arrays become float64 arrays, Python floats NumPy float64
// scalars, so no float32 arithmetic and no ZeroDivisionError). Selects are np.where, which numba's njit also compiles;
// the normal returns a tuple. "Paste-safe" for a module: importing it only defines <prefix>_* functions (no global
// state, no np.seterr), so two modules, or one imported twice, never interfere. Skeletons:
// templates/numpy/.
#include "emit/backend.h"
#include "emit/emitted_api.h"
#include "offset/method.h"

#include <fmt/format.h>

#include <cmath>
#include <set>

namespace offsetgen {
namespace {

// Python 3.11's keyword.kwlist and keyword.softkwlist (plus 3.12's `type`), and the names of
// dir(builtins): a module or function named like one cannot be imported, or shadows it.
const std::set<std::string>& python_keywords() {
  static const std::set<std::string> words = {
      "False",    "None",   "True",  "and",  "as",     "assert",   "async",   "await", "break", "class",
      "continue", "def",    "del",   "elif", "else",   "except",   "finally", "for",   "from",  "global",
      "if",       "import", "in",    "is",   "lambda", "nonlocal", "not",     "or",    "pass",  "raise",
      "return",   "try",    "while", "with", "yield",  "_",        "case",    "match", "type"};
  return words;
}

const std::set<std::string>& python_builtins() {
  static const std::set<std::string> names = {"ArithmeticError",
                                              "AssertionError",
                                              "AttributeError",
                                              "BaseException",
                                              "BaseExceptionGroup",
                                              "BlockingIOError",
                                              "BrokenPipeError",
                                              "BufferError",
                                              "BytesWarning",
                                              "ChildProcessError",
                                              "ConnectionAbortedError",
                                              "ConnectionError",
                                              "ConnectionRefusedError",
                                              "ConnectionResetError",
                                              "DeprecationWarning",
                                              "EOFError",
                                              "Ellipsis",
                                              "EncodingWarning",
                                              "EnvironmentError",
                                              "Exception",
                                              "ExceptionGroup",
                                              "FileExistsError",
                                              "FileNotFoundError",
                                              "FloatingPointError",
                                              "FutureWarning",
                                              "GeneratorExit",
                                              "IOError",
                                              "ImportError",
                                              "ImportWarning",
                                              "IndentationError",
                                              "IndexError",
                                              "InterruptedError",
                                              "IsADirectoryError",
                                              "KeyError",
                                              "KeyboardInterrupt",
                                              "LookupError",
                                              "MemoryError",
                                              "ModuleNotFoundError",
                                              "NameError",
                                              "NotADirectoryError",
                                              "NotImplemented",
                                              "NotImplementedError",
                                              "OSError",
                                              "OverflowError",
                                              "PendingDeprecationWarning",
                                              "PermissionError",
                                              "ProcessLookupError",
                                              "RecursionError",
                                              "ReferenceError",
                                              "ResourceWarning",
                                              "RuntimeError",
                                              "RuntimeWarning",
                                              "StopAsyncIteration",
                                              "StopIteration",
                                              "SyntaxError",
                                              "SyntaxWarning",
                                              "SystemError",
                                              "SystemExit",
                                              "TabError",
                                              "TimeoutError",
                                              "TypeError",
                                              "UnboundLocalError",
                                              "UnicodeDecodeError",
                                              "UnicodeEncodeError",
                                              "UnicodeError",
                                              "UnicodeTranslateError",
                                              "UnicodeWarning",
                                              "UserWarning",
                                              "ValueError",
                                              "Warning",
                                              "ZeroDivisionError",
                                              "abs",
                                              "aiter",
                                              "all",
                                              "anext",
                                              "any",
                                              "ascii",
                                              "bin",
                                              "bool",
                                              "breakpoint",
                                              "bytearray",
                                              "bytes",
                                              "callable",
                                              "chr",
                                              "classmethod",
                                              "compile",
                                              "complex",
                                              "copyright",
                                              "credits",
                                              "delattr",
                                              "dict",
                                              "dir",
                                              "divmod",
                                              "enumerate",
                                              "eval",
                                              "exec",
                                              "exit",
                                              "filter",
                                              "float",
                                              "format",
                                              "frozenset",
                                              "getattr",
                                              "globals",
                                              "hasattr",
                                              "hash",
                                              "help",
                                              "hex",
                                              "id",
                                              "input",
                                              "int",
                                              "isinstance",
                                              "issubclass",
                                              "iter",
                                              "len",
                                              "license",
                                              "list",
                                              "locals",
                                              "map",
                                              "max",
                                              "memoryview",
                                              "min",
                                              "next",
                                              "object",
                                              "oct",
                                              "open",
                                              "ord",
                                              "pow",
                                              "print",
                                              "property",
                                              "quit",
                                              "range",
                                              "repr",
                                              "reversed",
                                              "round",
                                              "set",
                                              "setattr",
                                              "slice",
                                              "sorted",
                                              "staticmethod",
                                              "str",
                                              "sum",
                                              "super",
                                              "tuple",
                                              "type",
                                              "vars",
                                              "zip"};
  return names;
}

// NumPy's spelling of each function (arctan, not atan).
std::string numpy_function(Fn fn) {
  switch (fn) {
    case Fn::Atan:
      return "np.arctan";
    case Fn::Asin:
      return "np.arcsin";
    case Fn::Acos:
      return "np.arccos";
    default:
      return std::string("np.") + function_name(fn);
  }
}

std::string arguments(const FileFacts& facts, const EmittedFunction& f) {
  if (!f.takes_point) return f.extra_parameter;
  std::string args = facts.dims == 3 ? "x, y, z" : "x, y";
  if (!f.extra_parameter.empty()) args += ", " + f.extra_parameter;
  return args;
}

class NumpyBackend final : public Backend {
 public:
  std::string name() const override { return "numpy"; }
  std::string extension() const override { return "py"; }
  std::string title() const override { return "NumPy"; }
  std::string file_template() const override { return "numpy_module.py.in"; }
  std::string function_template() const override { return "numpy_function.in"; }
  std::vector<Precision> precisions(const std::vector<Precision>&) const override { return {Precision::Double}; }

  std::string real_type(Precision) const override { return "float64"; }
  std::string local_decl(Precision) const override { return ""; }  // Python declares nothing
  std::string bool_decl() const override { return ""; }
  std::string literal(double value, Precision) const override {
    if (std::isnan(value)) return "np.nan";  // the density relations
    const std::string text = floating_form(fmt::format("{:.17g}", value));
    return value < 0 ? "(" + text + ")" : text;
  }
  std::string function(Fn fn, Precision) const override { return numpy_function(fn); }
  std::string sqrt_name(Precision) const override { return "np.sqrt"; }
  std::string abs_name(Precision) const override { return "np.abs"; }
  std::string pow_name(Precision) const override { return "np.power"; }
  std::string atan2_name(Precision) const override { return "np.arctan2"; }
  // Both branches are evaluated (a NumPy warning from the discarded one is harmless). [()] turns
  // np.where's 0-d result for scalars back into a scalar (an array is returned as it is): numba's
  // njit cannot mix 0-d arrays and scalars in a later np.where, NumPy then returns scalars for
  // scalar arguments. numba compiles np.where for scalars and for arrays of one shape.
  std::string select(const std::string& condition, const std::string& if_true,
                     const std::string& if_false) const override {
    return "np.where(" + condition + ", " + if_true + ", " + if_false + ")[()]";
  }
  std::string vector_type(int dims) const override { return dims == 3 ? "(nx, ny, nz)" : "(nx, ny)"; }
  std::optional<std::string> reserved(const std::string& identifier) const override {
    if (python_keywords().count(identifier)) return "'" + identifier + "' is a Python keyword";
    if (python_builtins().count(identifier))
      return "'" + identifier + "' is a Python builtin, which the module would shadow";
    if (identifier == "numpy" || identifier == "np" || identifier == "numba")
      return "a module named '" + identifier + "' would hide the package it needs";
    if (identifier.size() > 4 && identifier.rfind("__", 0) == 0 && identifier.substr(identifier.size() - 2) == "__")
      return "names of the form __name__ are Python's special names";
    return std::nullopt;
  }
  // The module's own name (import <prefix>) and its functions.
  std::vector<std::string> declared_identifiers(const std::string& prefix) const override {
    std::vector<std::string> names = {prefix};
    for (const auto& suffix : function_suffixes()) names.push_back(prefix + "_" + suffix);
    return names;
  }

  std::vector<std::string> input_names(const FileFacts& facts, const EmittedFunction& f) const override {
    std::vector<std::string> inputs;
    if (f.takes_point) inputs = {"x", "y"};
    if (f.takes_point && facts.dims == 3) inputs.push_back("z");
    if (!f.extra_parameter.empty()) inputs.push_back(f.extra_parameter);
    return inputs;
  }
  std::string parameters(const FileFacts& facts, const EmittedFunction& f, Precision) const override {
    return arguments(facts, f);
  }
  std::string prologue(const std::vector<std::string>& inputs) const override {
    std::string lines;
    for (const auto& input : inputs) lines += fmt::format("    {0} = np.asarray({0}, np.float64)[()]\n", input);
    return lines;
  }
  std::string vector_return(const FileFacts&, const std::vector<std::string>& components) const override {
    std::string list;
    for (const auto& c : components) list += (list.empty() ? "" : ", ") + c;
    return "    return (" + list + ")\n";
  }
  // The printer ends statements with ';', which Python allows but does not use.
  std::string finish_body(const FileFacts&, const std::string& body, Precision) const override {
    std::string out;
    for (size_t i = 0; i < body.size(); ++i)
      if (!(body[i] == ';' && i + 1 < body.size() && body[i + 1] == '\n')) out += body[i];
    return out;
  }

  std::string list_entry(const FileFacts& facts, const EmittedFunction& f, Precision) const override {
    const std::string call = fmt::format("{}_{}({}){}", facts.prefix, f.suffix, arguments(facts, f),
                                         f.vector_result ? " -> " + vector_type(facts.dims) : "");
    return fmt::format("    {:<42} {}\n", call, f.doc);
  }
  std::string ops_entry(const EmittedFunction& f) const override {
    return fmt::format("    {:<8} {}\n", f.suffix, count_ops(*f.program));
  }
  std::string paragraph(const std::string& label, const std::string& text) const override {
    std::string capitalised = label;
    capitalised[0] = static_cast<char>(capitalised[0] - 'a' + 'A');
    return wrap_paragraph(capitalised + ": " + text, "", "    ");
  }
  std::string method_paragraph(const MethodFacts& m) const override {
    return wrap_paragraph(m.summary, "Method:  ", "         ") + "\n" +
           wrap_paragraph(m.citation, "         ", "         ");
  }
  std::string comment_paragraph(const std::string& text) const override { return wrap_paragraph(text, "", "    "); }
  std::string nan_note() const override { return "NumPy returns np.nan."; }
  // __all__: `from <prefix> import *` brings the functions and not `np`.
  std::string trailing_sections(const FileFacts& facts, const std::vector<EmittedFunction>& functions,
                                const std::vector<Precision>&) const override {
    std::string names;
    for (const auto& f : functions) names += fmt::format("    \"{}_{}\",\n", facts.prefix, f.suffix);
    return "\n\n__all__ = [\n" + names + "]\n";
  }
};

}  // namespace

const Backend& numpy_backend() {
  static const NumpyBackend instance;
  return instance;
}

}  // namespace offsetgen
