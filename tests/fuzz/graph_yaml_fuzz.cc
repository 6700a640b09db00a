// Process graph files from untrusted text (procs/launch/graph_spec.h ParseGraph, LoadGraph's
// text form), then what topay-launch does with a graph (SelectGroups, ExcludeGroups,
// ExpandVariables) with fuzzed group and variable names. Bad input must be a GraphError naming
// the file; a loaded graph must hold what ParseGraph promises (unique names, dependencies
// first, values in range), a selection must keep every dependency, an exclusion fails exactly
// when a kept process needs a dropped one, and an expansion leaves no ${...} behind.
// Input: [flags][names][0x00][graph YAML] (without a 0x00 byte: no names, all YAML). Names are
// '\n'-separated: "NAME=value" defines a variable (besides BIN_DIR, GRAPH_DIR and RUN_DIR),
// "-group" excludes a group, any other line selects a group. Flags: bit 0 SelectGroups,
// bit 1 ExcludeGroups, bit 2 ExpandVariables (run in that order, as topay-launch does).
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "procs/launch/graph_spec.h"
#include "tests/fuzz/fuzz_reader.h"
#include "tests/fuzz/loader_checks.h"

namespace topay::fuzz {
namespace {

using launch::GraphError;
using launch::GraphSpec;
using launch::ProcessSpec;

constexpr const char* kPath = "config/graphs/fuzz_graph.yaml";

struct Names {
  std::vector<std::string> selected;
  std::vector<std::string> excluded;
  launch::GraphVariables variables{{{"BIN_DIR", "/opt/topay/bin"}, {"GRAPH_DIR", "/opt/topay/config/graphs"},
                                    {"RUN_DIR", "/tmp/run"}}};
};

// Variable values never hold '$', '{' or '}', so that an expansion's result holds no "${".
Names ParseNames(const std::string& text) {
  Names names;
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t end = std::min(text.find('\n', begin), text.size());
    const std::string line = text.substr(begin, end - begin);
    begin = end + 1;
    if (const std::size_t eq = line.find('='); eq != std::string::npos) {
      std::string value = line.substr(eq + 1);
      std::erase_if(value, [](char c) { return c == '$' || c == '{' || c == '}'; });
      names.variables.values[line.substr(0, eq)] = value;
    } else if (!line.empty() && line[0] == '-') {
      names.excluded.push_back(line.substr(1));
    } else if (!line.empty()) {
      names.selected.push_back(line);
    }
  }
  return names;
}

const ProcessSpec* Find(const GraphSpec& graph, const std::string& name) {
  for (const ProcessSpec& p : graph.processes) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

bool Contains(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

// Every process's dependencies are in the graph, before it.
void CheckDependenciesFirst(const GraphSpec& graph) {
  std::set<std::string> placed;
  for (const ProcessSpec& p : graph.processes) {
    for (const std::string& dep : p.depends_on) {
      FuzzCheck(placed.contains(dep), "a process's dependencies come before it");
    }
    placed.insert(p.name);
  }
}

// `after` keeps some of `before`'s processes, in the same order.
void CheckOrderedSubset(const GraphSpec& before, const GraphSpec& after) {
  std::size_t at = 0;
  for (const ProcessSpec& p : after.processes) {
    while (at < before.processes.size() && before.processes[at].name != p.name) ++at;
    FuzzCheck(at < before.processes.size(), "a selection keeps processes in their order");
    ++at;
  }
}

void CheckLoaded(const GraphSpec& graph) {
  FuzzCheck(graph.file == kPath, "the graph names its file");
  FuzzCheck(graph.grace_period_s >= 0.0 && graph.heartbeat_period_s >= 0.01, "graph periods are in range");
  FuzzCheck(!graph.processes.empty(), "a loaded graph has processes");
  std::set<std::string> names;
  for (const ProcessSpec& p : graph.processes) {
    FuzzCheck(!p.name.empty() && !p.command.empty(), "a process has a name and a command");
    FuzzCheck(names.insert(p.name).second, "process names are unique");
    FuzzCheck(p.restart_delay_s >= 0.0 && p.restart_delay_max_s >= p.restart_delay_s, "restart delays are in range");
    FuzzCheck(p.max_restarts >= -1, "max_restarts is in range");
    FuzzCheck(p.heartbeat_timeout_s >= 0.1 && p.startup_timeout_s >= 0.1 && p.ready_delay_s >= 0.0,
              "supervision times are in range");
    const launch::RealtimeSettings& rt = p.realtime;
    FuzzCheck(!rt.nice || (*rt.nice >= -20 && *rt.nice <= 19), "nice is in range");
    FuzzCheck(!rt.fifo_priority || (*rt.fifo_priority >= 1 && *rt.fifo_priority <= 99), "the priority is in range");
    for (const int cpu : rt.cpus) FuzzCheck(cpu >= 0 && cpu < 1024, "CPU numbers are in range");
  }
  CheckDependenciesFirst(graph);
}

void Select(const std::vector<std::string>& groups, GraphSpec* graph) {
  const GraphSpec before = *graph;
  launch::SelectGroups(groups, graph);
  CheckOrderedSubset(before, *graph);
  CheckDependenciesFirst(*graph);
  for (const ProcessSpec& p : before.processes) {
    const bool selected = groups.empty() ? p.autostart : Contains(groups, p.group);
    if (selected) FuzzCheck(Find(*graph, p.name) != nullptr, "a selected process is kept");
  }
}

void Exclude(const std::vector<std::string>& groups, GraphSpec* graph) {
  const GraphSpec before = *graph;
  bool needed = false;  // a kept process depends on a dropped one
  for (const ProcessSpec& p : before.processes) {
    if (Contains(groups, p.group)) continue;
    for (const std::string& dep : p.depends_on) {
      const ProcessSpec* d = Find(before, dep);
      needed = needed || (d != nullptr && Contains(groups, d->group));
    }
  }
  try {
    launch::ExcludeGroups(groups, graph);
  } catch (const GraphError& e) {
    CheckErrorNamesSource(e, kPath);
    FuzzCheck(needed, "an exclusion fails only when a kept process needs a dropped one");
    return;
  }
  FuzzCheck(!needed, "an exclusion that drops a needed process fails");
  CheckOrderedSubset(before, *graph);
  CheckDependenciesFirst(*graph);
  for (const ProcessSpec& p : before.processes) {
    FuzzCheck((Find(*graph, p.name) != nullptr) != Contains(groups, p.group), "exactly the excluded groups go");
  }
}

bool HasVariable(const std::string& text) { return text.find("${") != std::string::npos; }

void Expand(const launch::GraphVariables& variables, GraphSpec* graph) {
  try {
    launch::ExpandVariables(variables, graph);
  } catch (const GraphError& e) {
    CheckErrorNamesSource(e, kPath);
    return;
  }
  for (const ProcessSpec& p : graph->processes) {
    FuzzCheck(!HasVariable(p.command) && !HasVariable(p.working_dir), "an expanded command has no ${...}");
    for (const std::string& arg : p.args) FuzzCheck(!HasVariable(arg), "an expanded argument has no ${...}");
    for (const auto& [key, value] : p.env) FuzzCheck(!HasVariable(value), "an expanded value has no ${...}");
  }
}

}  // namespace
}  // namespace topay::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay::fuzz;
  FuzzReader in(data, size);
  const std::uint8_t flags = in.Byte();
  const std::string rest = in.RestAsString();
  const std::size_t split = rest.find('\0');
  const Names names = ParseNames(split == std::string::npos ? std::string() : rest.substr(0, split));
  const std::string yaml = split == std::string::npos ? rest : rest.substr(split + 1);

  topay::launch::GraphSpec graph;
  try {
    graph = topay::launch::ParseGraph(yaml, kPath);
  } catch (const topay::launch::GraphError& e) {
    CheckErrorNamesSource(e, kPath);
    return 0;
  }
  CheckLoaded(graph);
  if (flags & 1) Select(names.selected, &graph);
  if (flags & 2) Exclude(names.excluded, &graph);
  if (flags & 4) Expand(names.variables, &graph);
  return 0;
}
