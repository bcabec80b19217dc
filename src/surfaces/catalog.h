// The built-in catalog of triply periodic minimal surfaces (nodal approximations).
#pragma once

#include "surfaces/surface.h"

#include <string>
#include <vector>

namespace offsetgen {

struct CatalogEntry {
  const char* name;
  const char* title;
  const char* formula;   // in X = 2*pi*x etc.; parsed by GiNaC with exact rationals
  const char* citation;
};

const std::vector<CatalogEntry>& catalog();

// Throws InputError listing the known names when `name` is not in the catalog.
Surface catalog_surface(const std::string& name);

}  // namespace offsetgen
