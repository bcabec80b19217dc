#include "offset/offset_reference.h"

#include "offset/field_reference.h"

namespace offsetgen {

OffsetReference::OffsetReference(const Surface& surface, const OffsetConstruction& construction, int digits)
    : surface_(surface), construction_(construction), digits_(digits) {
  DigitsGuard guard(digits_);
  scale_ = numeric_of(surface.scale);
}

std::vector<GiNaC::numeric> OffsetReference::natural(const CellPoint& x) const {
  std::vector<GiNaC::numeric> p;
  for (const auto& c : x) p.push_back(scale_ * c);
  return p;
}

GiNaC::numeric OffsetReference::field(const CellPoint& x) {
  DigitsGuard guard(digits_);
  FieldReference at(surface_, construction_.atoms(), construction_.field(), natural(x));
  return at.field(at.base());
}

std::vector<GiNaC::numeric> OffsetReference::field_gradient(const CellPoint& x) {
  DigitsGuard guard(digits_);
  FieldReference at(surface_, construction_.atoms(), construction_.field(), natural(x));
  auto g = at.gradient(at.base());
  for (auto& c : g) c *= scale_;
  return g;
}

GiNaC::numeric OffsetReference::offset(const CellPoint& x, const GiNaC::numeric& h) {
  DigitsGuard guard(digits_);
  FieldReference at(surface_, construction_.atoms(), construction_.field(), natural(x));
  return construction_.offset(at, scale_ * h);
}

GiNaC::numeric OffsetReference::shell(const CellPoint& x, const GiNaC::numeric& t) {
  return offset(x, t / 2) * offset(x, -t / 2);
}

std::vector<GiNaC::numeric> OffsetReference::normal(const CellPoint& x, const GiNaC::numeric& h) {
  DigitsGuard guard(digits_);
  FieldReference at(surface_, construction_.atoms(), construction_.field(), natural(x));
  return construction_.normal(at, scale_ * h);
}

GiNaC::numeric OffsetReference::graded(const CellPoint& x, const GiNaC::ex& thickness) {
  DigitsGuard guard(digits_);
  FieldReference at(surface_, construction_.atoms(), construction_.field(), natural(x));
  auto half = [&](int sign) {
    return [&, sign](const FieldReference::Point& q) {
      return scale_ * at.cell_expression(thickness, q) * GiNaC::numeric(sign, 2);
    };
  };
  return construction_.graded_offset(at, half(1)) * construction_.graded_offset(at, half(-1));
}

}  // namespace offsetgen
