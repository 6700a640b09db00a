#include "fault_results_file.h"

#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include <fmt/format.h>

namespace topay::tools {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The field `key` of `j` as a T; throws naming the field if it is missing or of another type.
template <typename T>
T Field(const json& j, const char* key) {
  const auto it = j.find(key);
  if (it == j.end()) throw std::runtime_error(fmt::format("no \"{}\"", key));
  try {
    if constexpr (std::is_same_v<T, bool>) {
      if (!it->is_boolean()) throw std::runtime_error("not a boolean");
    } else if constexpr (std::is_same_v<T, std::string>) {
      if (!it->is_string()) throw std::runtime_error("not a string");
    } else if constexpr (std::is_floating_point_v<T>) {
      if (!it->is_number()) throw std::runtime_error("not a number");
    } else if constexpr (std::is_unsigned_v<T>) {
      if (!it->is_number_unsigned()) throw std::runtime_error("not a whole number >= 0");
    } else {
      if (!it->is_number_integer()) throw std::runtime_error("not a whole number");
      if (it->is_number_unsigned() && it->get<std::uint64_t>() > std::numeric_limits<std::int64_t>::max()) {
        throw std::runtime_error("out of range");
      }
      const std::int64_t value = it->get<std::int64_t>();
      if (value < std::numeric_limits<T>::min() || value > std::numeric_limits<T>::max()) {
        throw std::runtime_error("out of range");
      }
    }
    return it->get<T>();
  } catch (const std::exception& e) {
    throw std::runtime_error(fmt::format("\"{}\": {}", key, e.what()));
  }
}

}  // namespace

json ToJson(const EpisodeResult& e) {
  return {{"fault", e.fault},         {"seed", e.seed},           {"injected", e.injected},
          {"refused", e.refused},     {"notes", e.notes},         {"safe_ms", e.safe_ms},
          {"safe_evidence", e.safe_evidence}, {"zero_ms", e.zero_ms}, {"recovered", e.recovered}, {"recover_s", e.recover_s},
          {"reaction", e.reaction},   {"other_restarts", e.other_restarts}, {"contacts", e.contacts}};
}

EpisodeResult EpisodeFromJson(const json& j) {
  if (!j.is_object()) throw std::runtime_error("not an object");
  EpisodeResult e;
  e.fault = Field<std::string>(j, "fault");
  e.seed = Field<std::uint64_t>(j, "seed");
  e.injected = Field<bool>(j, "injected");
  e.refused = Field<bool>(j, "refused");
  e.notes = Field<std::string>(j, "notes");
  e.safe_ms = Field<double>(j, "safe_ms");
  e.safe_evidence = Field<std::string>(j, "safe_evidence");
  e.zero_ms = j.contains("zero_ms") ? Field<double>(j, "zero_ms") : -1.0;  // older files: not measured
  e.recovered = Field<bool>(j, "recovered");
  e.recover_s = Field<double>(j, "recover_s");
  e.reaction = Field<std::string>(j, "reaction");
  e.other_restarts = Field<int>(j, "other_restarts");
  e.contacts = Field<std::int64_t>(j, "contacts");
  if (e.fault.empty()) throw std::runtime_error("\"fault\": empty");
  return e;
}

bool WriteEpisodes(const std::string& path, const std::vector<EpisodeResult>& episodes) {
  json list = json::array();
  for (const EpisodeResult& e : episodes) list.push_back(ToJson(e));
  std::ofstream out(path);
  out << json{{"episodes", list}}.dump(2, ' ', false, json::error_handler_t::replace) << "\n";
  return out.good();
}

std::vector<EpisodeResult> ReadEpisodes(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read");
  const json doc = json::parse(in, nullptr, false);
  if (doc.is_discarded()) throw std::runtime_error(path + ": not JSON");
  const auto list = doc.find("episodes");
  if (!doc.is_object() || list == doc.end() || !list->is_array()) {
    throw std::runtime_error(path + ": no \"episodes\" list");
  }
  std::vector<EpisodeResult> episodes;
  for (std::size_t k = 0; k < list->size(); ++k) {
    try {
      episodes.push_back(EpisodeFromJson((*list)[k]));
    } catch (const std::exception& e) {
      throw std::runtime_error(fmt::format("{}: episode {}: {}", path, k, e.what()));
    }
  }
  return episodes;
}

int NextMissionIndex(const std::string& out_dir) {
  int largest = 0;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(out_dir, error)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_directory() || name.rfind("mission-", 0) != 0) continue;
    const std::string digits = name.substr(8);
    if (digits.empty() || digits.size() > 6 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    largest = std::max(largest, std::stoi(digits));
  }
  return largest + 1;
}

}  // namespace topay::tools
