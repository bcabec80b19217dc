#include "density/periodicity.h"

#include <fmt/format.h>

#include <sstream>
#include <vector>

namespace offsetgen::density {
namespace {

// The behaviour of a sub-expression under var -> var + 1.
enum class Shift { Same, Flipped, Unknown };  // e, -e, or not provable

Shift times(Shift a, Shift b) {
  if (a == Shift::Unknown || b == Shift::Unknown) return Shift::Unknown;
  return a == b ? Shift::Same : Shift::Flipped;
}

std::string text(const GiNaC::ex& e) {
  std::ostringstream out;
  out << e;
  return out.str();
}

class Prover {
 public:
  explicit Prover(const GiNaC::symbol& var) : var_(var) {}

  Shift classify(const GiNaC::ex& e) {
    if (!e.has(var_)) return Shift::Same;
    if (GiNaC::is_a<GiNaC::symbol>(e)) return fail(e, "it occurs outside a periodic function");
    if (GiNaC::is_a<GiNaC::add>(e)) {
      std::vector<Shift> shifts;
      for (size_t i = 0; i < e.nops(); ++i) {
        shifts.push_back(classify(e.op(i)));
        if (shifts.back() == Shift::Unknown) return Shift::Unknown;
      }
      for (size_t i = 0; i < e.nops(); ++i)
        if (shifts[i] != shifts[0]) {  // name a term that flips while others keep
          const size_t flipping = shifts[i] == Shift::Flipped ? i : 0;
          return fail(e.op(flipping), fmt::format("it changes sign under {0} -> {0} + 1 and the other terms do not "
                                                  "(period 2, not 1)",
                                                  text(var_)));
        }
      return shifts[0];
    }
    if (GiNaC::is_a<GiNaC::mul>(e)) {
      Shift s = Shift::Same;
      for (size_t i = 0; i < e.nops(); ++i) s = times(s, classify(e.op(i)));
      return s;
    }
    if (GiNaC::is_a<GiNaC::power>(e)) {
      const GiNaC::ex base = e.op(0), exponent = e.op(1);
      if (GiNaC::is_a<GiNaC::numeric>(exponent) && GiNaC::ex_to<GiNaC::numeric>(exponent).is_integer()) {
        const Shift s = classify(base);
        if (s == Shift::Unknown) return s;
        return GiNaC::ex_to<GiNaC::numeric>(exponent).is_even() ? Shift::Same : s;
      }
      if (classify(base) == Shift::Same && classify(exponent) == Shift::Same) return Shift::Same;
      return fail(e, "a power of a part that changes sign");
    }
    if (GiNaC::is_a<GiNaC::function>(e)) return function(e);
    return fail(e, "it is not built from periodic parts");
  }

  const std::string& reason() const { return reason_; }

 private:
  Shift function(const GiNaC::ex& e) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    if (e.nops() != 1) {  // atan2(y, x): periodic when both arguments are
      for (size_t i = 0; i < e.nops(); ++i)
        if (classify(e.op(i)) != Shift::Same) return fail(e, "an argument of it is not periodic");
      return Shift::Same;
    }
    const GiNaC::ex argument = e.op(0);
    if (name == "sin" || name == "cos" || name == "tan") {
      // The argument moves by a constant d: sin, cos keep (d = 2 pi n) or flip (d = pi (2n + 1)); tan
      // keeps for any whole multiple of pi.
      const GiNaC::ex d = (argument.subs(var_ == var_ + 1) - argument).expand();
      if (!d.has(var_) && d.info(GiNaC::info_flags::real)) {
        const GiNaC::ex ratio = (d / GiNaC::Pi).expand();
        if (GiNaC::is_a<GiNaC::numeric>(ratio) && GiNaC::ex_to<GiNaC::numeric>(ratio).is_integer()) {
          const bool odd = GiNaC::ex_to<GiNaC::numeric>(ratio).is_odd();
          return name == "tan" || !odd ? Shift::Same : Shift::Flipped;
        }
        if (d.is_zero()) return Shift::Same;
        if (Prover(var_).classify(argument) == Shift::Same) return Shift::Same;  // e.g. sin(cos(2 pi x) + 1)
        return fail(e, fmt::format("its argument moves by {} under {} -> {} + 1, not a whole multiple of {}", text(d),
                                   text(var_), text(var_), name == "tan" ? "pi" : "2 pi"));
      }
    }
    const Shift inner = classify(argument);
    if (inner == Shift::Unknown || inner == Shift::Same) return inner;
    // A flipped argument: even functions keep, odd ones flip, others are unknown.
    if (name == "cos" || name == "cosh") return Shift::Same;
    if (name == "sin" || name == "tan" || name == "sinh" || name == "tanh" || name == "atan" || name == "asin")
      return Shift::Flipped;
    return fail(e, "a function of a part that changes sign");
  }

  Shift fail(const GiNaC::ex& e, const std::string& why) {
    if (reason_.empty()) reason_ = fmt::format("'{}': {}", text(e), why);
    return Shift::Unknown;
  }

  const GiNaC::symbol& var_;
  std::string reason_;
};

}  // namespace

std::optional<std::string> periodicity_problem(const GiNaC::ex& e, const GiNaC::symbol& var) {
  Prover prover(var);
  switch (prover.classify(e)) {
    case Shift::Same:
      return std::nullopt;
    case Shift::Flipped:
      return fmt::format("it changes sign under {0} -> {0} + 1 (period 2, not 1)", text(var));
    case Shift::Unknown:
      break;
  }
  return prover.reason();
}

}  // namespace offsetgen::density
