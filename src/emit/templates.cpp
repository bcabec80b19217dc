#include "emit/templates.h"

#include "emit/embedded_templates.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace offsetgen {

std::string load_template(const std::string& name) {
  const auto& table = embedded_templates();
  auto it = std::lower_bound(table.begin(), table.end(), name,
                             [](const EmbeddedTemplate& entry, const std::string& key) { return entry.name < key; });
  if (it == table.end() || it->name != name)
    throw std::runtime_error("no template " + name + " was compiled into offsetgen (templates/" + name + ")");
  return std::string(it->text);
}

std::map<std::string, std::string> load_template_sections(const std::string& name,
                                                          const std::vector<std::string>& required) {
  std::map<std::string, std::string> sections;
  std::istringstream in(load_template(name));
  std::string line, current;
  while (std::getline(in, line)) {
    if (line.rfind("@@ ", 0) == 0) {
      current = line.substr(3);
      sections[current];
      continue;
    }
    if (current.empty()) continue;
    sections[current] += line + "\n";
  }
  for (const auto& section : required)
    if (!sections.count(section)) throw std::runtime_error("template " + name + " lacks section @@ " + section);
  return sections;
}

}  // namespace offsetgen
