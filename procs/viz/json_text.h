#pragma once
// JSON text for the browser: value.dump(-1, ' ', false, kReplaceInvalidUtf8). Strings in the
// graph's messages are not checked for UTF-8 (a process name, a status, a failure reason may
// hold any bytes): invalid sequences become U+FFFD instead of nlohmann::json's type_error 316,
// which would end topay-viz on one hostile message (found by tests/fuzz/viz_inputs_fuzz.cc).

#include <nlohmann/json.hpp>

namespace topay::viz {

inline constexpr nlohmann::json::error_handler_t kReplaceInvalidUtf8 = nlohmann::json::error_handler_t::replace;

}  // namespace topay::viz
