// A target language is one Backend: its name, file extension, printer hooks and file layout. Its
// file skeletons live in templates/<name>/. The registry (backend_registry.cpp)
// lists every backend; nothing else in the pipeline names a language. What runs a target's files
// (`offsetgen check`) is its Runner, found by the backend's name (run/runner.h). Modelled on SymForce's
// backends/<lang>/: one config object per output language, holding its printer and its templates.
#pragma once

#include "lowering/program.h"

#include <optional>
#include <string>
#include <vector>

namespace offsetgen {

enum class Precision { Double, Float };

struct EmittedFunction;
struct FileFacts;
struct MethodFacts;

class Backend {
 public:
  virtual ~Backend() = default;

  // --- Identity -----------------------------------------------------------------------------
  virtual std::string name() const = 0;       // "c", "glsl": --lang, LANG, the metadata's "language"
  virtual std::string extension() const = 0;  // "h", "glsl": <prefix>.<extension>
  virtual std::string title() const = 0;      // "C", "GLSL": in messages
  // Its skeletons, in templates/<name>/: the file, and one function.
  virtual std::string file_template() const = 0;
  virtual std::string function_template() const = 0;
  // The precisions this target emits: C follows --precision, shaders are float only.
  virtual std::vector<Precision> precisions(const std::vector<Precision>& requested) const { return requested; }

  // --- Printer hooks (emit/printer.cpp) -----------------------------------------------------
  virtual std::string real_type(Precision p) const = 0;   // "double", "highp float", "float"
  virtual std::string local_decl(Precision p) const = 0;  // the declaration of a temporary
  virtual std::string bool_decl() const = 0;              // "const int", "bool"
  virtual std::string literal(double value, Precision p) const = 0;
  virtual std::string suffix(Precision) const { return ""; }  // appended to function names: "" or "f"
  virtual std::string function(Fn fn, Precision p) const { return offsetgen::function_name(fn) + suffix(p); }
  // Whether the target has sinpi and cospi (Fn::SinPi, Fn::CosPi): it is then given its programs in
  // half-turns (lowering/program.h, in_half_turns), so the trig of 2 pi x never rounds 2 pi x.
  virtual bool half_turn_trig() const { return false; }
  virtual std::string sqrt_name(Precision p) const { return "sqrt" + suffix(p); }
  virtual std::string abs_name(Precision p) const { return "abs" + suffix(p); }
  virtual std::string pow_name(Precision p) const { return "pow" + suffix(p); }
  // atan2(y, x): the angle of (x, y); GLSL spells it atan(y, x).
  virtual std::string atan2_name(Precision p) const { return "atan2" + suffix(p); }
  virtual std::string select(const std::string& condition, const std::string& if_true,
                             const std::string& if_false) const {
    return "(" + condition + ") ? " + if_true + " : " + if_false;
  }
  virtual std::string vector_type(int dims) const = 0;  // "vec3", "float3"
  // Why a file of this target must not declare `identifier`, or nullopt when it may.
  virtual std::optional<std::string> reserved(const std::string& identifier) const = 0;
  // Every identifier a file with this prefix declares (functions, macros, guard).
  virtual std::vector<std::string> declared_identifiers(const std::string& prefix) const;

  // --- Function layout (emit/render.cpp) ------------------------------------------------------
  // How the body reads each program input: "x" (C) or "p.x" (shaders).
  virtual std::vector<std::string> input_names(const FileFacts& facts, const EmittedFunction& f) const;
  virtual std::string parameters(const FileFacts& facts, const EmittedFunction& f, Precision p) const = 0;
  virtual std::string return_type(const FileFacts& facts, const EmittedFunction& f, Precision p) const;
  virtual std::string emitted_name(const FileFacts& facts, const EmittedFunction& f, Precision p) const;
  // A statement that marks an unread parameter as used ("(void)x;"), or "" where none is needed.
  virtual std::string unused_parameter(const std::string&) const { return ""; }
  // Lines that open the body, given its inputs (NumPy: each input converted to float64).
  virtual std::string prologue(const std::vector<std::string>&) const { return ""; }
  // The body's last lines for a vector result (C: n[i] = ...; shaders: return vec3(...)).
  virtual std::string vector_return(const FileFacts& facts, const std::vector<std::string>& components) const;
  // A last rewrite of a printed body (calls of the file's own sin/cos helpers).
  virtual std::string finish_body(const FileFacts&, const std::string& body, Precision) const { return body; }

  // --- File layout (file_template()) -----------------------------------------------------------
  // One line of the file comment's function list, and of its op-count list.
  virtual std::string list_entry(const FileFacts& facts, const EmittedFunction& f, Precision p) const = 0;
  virtual std::string ops_entry(const EmittedFunction& f) const = 0;
  // A labelled paragraph of the file comment ("accuracy", text), and the method's paragraph.
  virtual std::string paragraph(const std::string& label, const std::string& text) const = 0;
  virtual std::string method_paragraph(const MethodFacts& m) const = 0;
  // An unlabelled paragraph of the file comment (the density notes).
  virtual std::string comment_paragraph(const std::string& text) const = 0;
  // What the density notes add on how this target returns NaN ("" for none).
  virtual std::string nan_note() const { return ""; }
  // The functions of one precision, with whatever support code they need ahead of them.
  virtual std::string precision_section(const FileFacts&, const std::string& functions, Precision) const {
    return functions;
  }
  // Sections after every precision's functions (C: the batch API).
  virtual std::string trailing_sections(const FileFacts&, const std::vector<EmittedFunction>&,
                                        const std::vector<Precision>&) const {
    return "";
  }
};

// Every backend, in --lang all order.
const std::vector<const Backend*>& backends();

// The backend named `name`; throws InputError listing the known names.
const Backend& backend(const std::string& name);

// "c,glsl" or "all" -> the backends, in registry order, without duplicates. Throws InputError for an
// empty list or an unknown name.
std::vector<const Backend*> parse_languages(const std::string& list);

// The suffixes of every function a file may declare: <prefix>_<suffix>.
const std::vector<std::string>& function_suffixes();

// "c, glsl, hlsl"
std::string backend_names(const char* separator = ", ");

// A literal that reads as a floating literal in C, GLSL ES, HLSL and WGSL: "2" -> "2.0",
// "1e-05" -> "1.0e-05".
std::string floating_form(std::string text);

// The float literal most backends print: 9 significant digits (they round-trip every float).
std::string float_literal(double value);

}  // namespace offsetgen
