#include "procs/launch/graph_spec.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>

namespace topay::launch {
namespace {

// Error context: the file and the path of the current node, e.g. "processes[1] (planner)".
struct Where {
  const std::string& file;
  std::string path;

  [[noreturn]] void Fail(const YAML::Node& node, const std::string& field,
                         const std::string& what) const {
    const int line = node.IsDefined() ? node.Mark().line + 1 : 0;
    std::string at = file + (line > 0 ? ":" + std::to_string(line) : "") + ": ";
    const std::string name = path.empty() ? field : (field.empty() ? path : path + "." + field);
    throw GraphError(at + (name.empty() ? "" : name + ": ") + what);
  }
};

void CheckKeys(const YAML::Node& map, const std::set<std::string>& known, const Where& where) {
  if (!map.IsMap()) where.Fail(map, "", "expected a mapping");
  for (const auto& entry : map) {
    // A key that is a list, a map or null (e.g. `[a]: 1`) has no name (and no string value).
    if (!entry.first.IsScalar()) where.Fail(entry.first, "", "a key must be a name, not a list, a map or null");
    const std::string key = entry.first.Scalar();
    if (!known.contains(key)) where.Fail(entry.first, key, "unknown key '" + key + "'");
  }
}

template <class T>
void Read(const YAML::Node& map, const std::string& key, const Where& where, T* value) {
  const YAML::Node node = map[key];
  if (!node.IsDefined() || node.IsNull()) return;
  try {
    *value = node.as<T>();
  } catch (const YAML::Exception&) {
    where.Fail(node, key, "wrong type");
  }
}

void ReadRange(const YAML::Node& map, const std::string& key, const Where& where, double low,
               double* value) {
  Read(map, key, where, value);
  if (!(*value >= low)) where.Fail(map[key], key, "must be >= " + std::to_string(low));
}

RestartPolicy ParsePolicy(const YAML::Node& map, const Where& where) {
  std::string text = "on-failure";
  Read(map, "restart", where, &text);
  if (text == "never") return RestartPolicy::kNever;
  if (text == "on-failure") return RestartPolicy::kOnFailure;
  if (text == "always") return RestartPolicy::kAlways;
  where.Fail(map["restart"], "restart", "must be never, on-failure or always, not '" + text + "'");
}

RealtimeSettings ParseRealtime(const YAML::Node& node, const Where& parent) {
  RealtimeSettings rt;
  if (!node.IsDefined()) return rt;
  const Where where{parent.file, parent.path + ".realtime"};
  CheckKeys(node, {"nice", "fifo_priority", "cpus", "mlockall"}, where);
  if (node["nice"]) {
    int nice = 0;
    Read(node, "nice", where, &nice);
    if (nice < -20 || nice > 19) where.Fail(node["nice"], "nice", "must be in -20..19");
    rt.nice = nice;
  }
  if (node["fifo_priority"]) {
    int priority = 0;
    Read(node, "fifo_priority", where, &priority);
    if (priority < 1 || priority > 99) where.Fail(node["fifo_priority"], "fifo_priority", "must be in 1..99");
    rt.fifo_priority = priority;
  }
  Read(node, "cpus", where, &rt.cpus);
  for (const int cpu : rt.cpus) {
    if (cpu < 0 || cpu >= 1024) where.Fail(node["cpus"], "cpus", "CPU numbers must be in 0..1023");
  }
  Read(node, "mlockall", where, &rt.mlockall);
  return rt;
}

ProcessSpec ParseProcess(const YAML::Node& node, int index, const std::string& file) {
  Where where{file, "processes[" + std::to_string(index) + "]"};
  ProcessSpec p;
  if (node.IsMap()) Read(node, "name", where, &p.name);
  if (!p.name.empty()) where.path += " (" + p.name + ")";
  CheckKeys(node, {"name", "command", "args", "env", "working_dir", "depends_on", "restart",
                   "restart_delay_s", "restart_delay_max_s", "max_restarts", "heartbeat",
                   "heartbeat_timeout_s", "startup_timeout_s", "ready_delay_s", "group", "autostart", "publishes", "ends_graph", "realtime"},
            where);
  if (p.name.empty()) where.Fail(node, "name", "missing");
  Read(node, "command", where, &p.command);
  if (p.command.empty()) where.Fail(node, "command", "missing");
  Read(node, "args", where, &p.args);
  Read(node, "env", where, &p.env);
  Read(node, "working_dir", where, &p.working_dir);
  Read(node, "depends_on", where, &p.depends_on);
  p.restart = ParsePolicy(node, where);
  ReadRange(node, "restart_delay_s", where, 0.0, &p.restart_delay_s);
  ReadRange(node, "restart_delay_max_s", where, p.restart_delay_s, &p.restart_delay_max_s);
  Read(node, "max_restarts", where, &p.max_restarts);
  if (p.max_restarts < -1) where.Fail(node["max_restarts"], "max_restarts", "must be >= -1");
  Read(node, "heartbeat", where, &p.heartbeat);
  ReadRange(node, "heartbeat_timeout_s", where, 0.1, &p.heartbeat_timeout_s);
  ReadRange(node, "startup_timeout_s", where, 0.1, &p.startup_timeout_s);
  ReadRange(node, "ready_delay_s", where, 0.0, &p.ready_delay_s);
  Read(node, "group", where, &p.group);
  Read(node, "autostart", where, &p.autostart);
  Read(node, "publishes", where, &p.publishes);
  Read(node, "ends_graph", where, &p.ends_graph);
  p.realtime = ParseRealtime(node["realtime"], where);
  return p;
}

// Kahn's algorithm, taking the earliest ready process in file order each step. Throws on a
// cycle, naming its members.
std::vector<ProcessSpec> StartOrder(std::vector<ProcessSpec> processes, const std::string& file) {
  std::vector<ProcessSpec> order;
  std::set<std::string> placed;
  while (!processes.empty()) {
    auto ready = std::find_if(processes.begin(), processes.end(), [&](const ProcessSpec& p) {
      return std::all_of(p.depends_on.begin(), p.depends_on.end(),
                         [&](const std::string& d) { return placed.contains(d); });
    });
    if (ready == processes.end()) {
      std::string members;
      for (const ProcessSpec& p : processes) members += (members.empty() ? "" : ", ") + p.name;
      throw GraphError(file + ": processes: dependency cycle among " + members);
    }
    placed.insert(ready->name);
    order.push_back(std::move(*ready));
    processes.erase(ready);
  }
  return order;
}

}  // namespace

const char* ToString(RestartPolicy policy) {
  switch (policy) {
    case RestartPolicy::kNever: return "never";
    case RestartPolicy::kOnFailure: return "on-failure";
    case RestartPolicy::kAlways: return "always";
  }
  return "?";
}

GraphSpec LoadGraph(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw GraphError(path + ": cannot read the file");
  std::ostringstream text;
  text << file.rdbuf();
  return ParseGraph(text.str(), path);
}

GraphSpec ParseGraph(const std::string& yaml_text, const std::string& path) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw GraphError(path + ":" + std::to_string(e.mark.line + 1) + ": YAML: " + e.msg);
  }
  const Where where{path, ""};
  CheckKeys(root, {"name", "isolated", "lcm_url", "grace_period_s", "heartbeat_period_s", "run_root",
                   "processes"},
            where);
  GraphSpec graph;
  graph.file = path;
  graph.name = std::filesystem::path(path).stem().string();
  Read(root, "name", where, &graph.name);
  Read(root, "isolated", where, &graph.isolated);
  Read(root, "lcm_url", where, &graph.lcm_url);
  ReadRange(root, "grace_period_s", where, 0.0, &graph.grace_period_s);
  ReadRange(root, "heartbeat_period_s", where, 0.01, &graph.heartbeat_period_s);
  Read(root, "run_root", where, &graph.run_root);
  const YAML::Node list = root["processes"];
  if (!list.IsSequence() || list.size() == 0) {
    where.Fail(list.IsDefined() ? list : root, "processes", "a non-empty list is required");
  }
  std::vector<ProcessSpec> processes;
  std::set<std::string> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    processes.push_back(ParseProcess(list[i], static_cast<int>(i), path));
    if (!names.insert(processes.back().name).second) {
      where.Fail(list[i]["name"], "processes[" + std::to_string(i) + "].name",
                 "duplicate process name '" + processes.back().name + "'");
    }
  }
  for (std::size_t i = 0; i < processes.size(); ++i) {
    for (const std::string& dep : processes[i].depends_on) {
      if (!names.contains(dep)) {
        where.Fail(list[i]["depends_on"],
                   "processes[" + std::to_string(i) + "] (" + processes[i].name + ").depends_on",
                   "unknown process '" + dep + "'");
      }
    }
  }
  graph.processes = StartOrder(std::move(processes), path);
  return graph;
}

namespace {

std::string Expand(const GraphVariables& variables, const std::string& text,
                   const std::string& where) {
  std::string out;
  std::size_t pos = 0;
  while (true) {
    const std::size_t open = text.find("${", pos);
    if (open == std::string::npos) break;
    const std::size_t close = text.find('}', open);
    if (close == std::string::npos) throw GraphError(where + ": unterminated ${ in '" + text + "'");
    const std::string name = text.substr(open + 2, close - open - 2);
    const auto value = variables.values.find(name);
    if (value == variables.values.end()) {
      throw GraphError(where + ": unknown variable ${" + name + "}");
    }
    out += text.substr(pos, open - pos) + value->second;
    pos = close + 1;
  }
  return out + text.substr(pos);
}

}  // namespace

void ExpandVariables(const GraphVariables& variables, GraphSpec* graph) {
  for (ProcessSpec& p : graph->processes) {
    const std::string where = graph->file + ": process " + p.name;
    p.command = Expand(variables, p.command, where + ".command");
    for (std::string& arg : p.args) arg = Expand(variables, arg, where + ".args");
    for (auto& [key, value] : p.env) value = Expand(variables, value, where + ".env." + key);
    p.working_dir = Expand(variables, p.working_dir, where + ".working_dir");
  }
}

void SelectGroups(const std::vector<std::string>& groups, GraphSpec* graph) {
  std::set<std::string> keep;
  std::function<void(const std::string&)> add = [&](const std::string& name) {
    if (!keep.insert(name).second) return;
    for (const ProcessSpec& p : graph->processes) {
      if (p.name == name) for (const std::string& dep : p.depends_on) add(dep);
    }
  };
  for (const ProcessSpec& p : graph->processes) {
    const bool selected = groups.empty() ? p.autostart
                                         : std::find(groups.begin(), groups.end(), p.group) != groups.end();
    if (selected) add(p.name);
  }
  std::erase_if(graph->processes, [&](const ProcessSpec& p) { return !keep.contains(p.name); });
}

void ExcludeGroups(const std::vector<std::string>& groups, GraphSpec* graph) {
  const auto excluded = [&](const ProcessSpec& p) {
    return std::find(groups.begin(), groups.end(), p.group) != groups.end();
  };
  std::set<std::string> dropped;
  for (const ProcessSpec& p : graph->processes) {
    if (excluded(p)) dropped.insert(p.name);
  }
  for (const ProcessSpec& p : graph->processes) {
    if (excluded(p)) continue;
    for (const std::string& dep : p.depends_on) {
      if (dropped.contains(dep)) {
        throw GraphError(graph->file + ": process " + p.name + " depends on " + dep + ", which --without drops");
      }
    }
  }
  std::erase_if(graph->processes, excluded);
}

}  // namespace topay::launch
