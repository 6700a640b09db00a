#pragma once
// A campaign's results.json: every episode kept so far, written after each campaign (also an
// interrupted one) and read back by `topay-faults --resume`, which counts those episodes and
// runs only the ones still owed. Reading checks every field: a damaged file is an error naming
// the file, the episode and the field, never a half-read campaign.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fault_episode.h"

namespace topay::tools {

nlohmann::json ToJson(const EpisodeResult& episode);

/// The episode of `j` (an object as ToJson writes it). Throws std::runtime_error naming the
/// missing or mistyped field.
EpisodeResult EpisodeFromJson(const nlohmann::json& j);

/// Writes `{"episodes": [...]}` to `path` (texts off the bus: invalid UTF-8 replaced). False if
/// the file could not be written.
bool WriteEpisodes(const std::string& path, const std::vector<EpisodeResult>& episodes);

/// The episodes of a results.json. Throws std::runtime_error naming the file and, for a bad
/// episode, its index and field.
std::vector<EpisodeResult> ReadEpisodes(const std::string& path);

/// 1 + the largest k of the `mission-<k>` folders in `out_dir` (1 if none): where a resumed
/// campaign numbers its missions so that earlier ones are kept.
int NextMissionIndex(const std::string& out_dir);

}  // namespace topay::tools
