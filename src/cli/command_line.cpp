#include "cli/command_line.h"

#include "offset/method.h"
#include "surfaces/surface.h"

#include <fmt/format.h>

#include <csignal>
#include <cstdio>
#include <exception>
#include <filesystem>

namespace offsetgen {

// The handler of support/interrupt_cleanup.cpp exits with 128 + the signal.
static_assert(kExitInterrupted == 128 + SIGINT && kExitTerminated == 128 + SIGTERM);
namespace {

std::string quote(const std::string& arg) {
  if (!arg.empty() && arg.find_first_of(" \t\"'\\$`*?()<>|&;") == std::string::npos) return arg;
  std::string out = "'";
  for (char c : arg) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

std::string banner_command(const std::vector<std::string>& args) {
  std::string command = "offsetgen";
  for (size_t i = 1; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if ((arg == "--out-dir") && i + 1 < args.size()) {
      ++i;  // where the files land does not change what they say
      continue;
    }
    if (arg.rfind("--out-dir=", 0) == 0) continue;
    if (arg == "-q" || arg == "--quiet") continue;  // says nothing about the content
    command += " " + quote(arg);
    if ((arg == "-o" || arg == "--output") && i + 1 < args.size()) {
      command += " " + quote(std::filesystem::path(args[++i]).filename().string());
    }
  }
  return command;
}

int run_reporting_errors(const std::function<int()>& command) {
  try {
    return command();
  } catch (const InputError& e) {
    fmt::print(stderr, "offsetgen: error: {}\n", e.what());
    return kExitUsage;
  } catch (const ResourceError& e) {
    fmt::print(stderr, "offsetgen: error: {}\n", e.what());
    return kExitInternal;
  } catch (const UnsoundPartError& e) {
    fmt::print(stderr, "offsetgen: error: {}\n", e.what());
    return kExitInternal;
  } catch (const std::exception& e) {
    fmt::print(stderr, "offsetgen: internal error: {}\n", e.what());
    return kExitInternal;
  }
}

std::string method_help_lines() {
  std::string lines;
  for (const OffsetMethod* m : offset_methods()) lines += fmt::format("\n  {}: {}", m->name(), m->description());
  return lines;
}

}  // namespace offsetgen
