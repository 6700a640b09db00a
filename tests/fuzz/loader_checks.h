#pragma once
// The loaders' error contract as the loader targets check it: a target catches exactly the
// error type its loader documents (anything else, e.g. std::bad_alloc, std::out_of_range or a
// yaml-cpp exception passing through, ends the run) and checks the error with these: a
// message that is not empty and names the file (or the source name given for a text).

#include <exception>
#include <stdexcept>
#include <string>

#include <yaml-cpp/exceptions.h>

#include "core/common/error.h"
#include "tests/fuzz/fuzz_check.h"

namespace topay::fuzz {

/// what() is not empty and contains `source`.
inline void CheckErrorNamesSource(const std::exception& error, const std::string& source) {
  const std::string what = error.what();
  FuzzCheck(!what.empty(), "an error has a message");
  FuzzCheck(what.find(source) != std::string::npos, "an error message names the file");
}

/// A ConfigError about the file `source`.
inline void CheckConfigError(const ConfigError& error, const std::string& source) {
  CheckErrorNamesSource(error, source);
  FuzzCheck(error.file() == source, "a ConfigError's file is the one loaded");
}

/// A loader documented to throw std::runtime_error: its own, not yaml-cpp's passed through
/// (YAML::Exception is a std::runtime_error, without the file's name).
inline void CheckRuntimeError(const std::runtime_error& error, const std::string& source) {
  FuzzCheck(dynamic_cast<const YAML::Exception*>(&error) == nullptr,
            "a loader's error is its own, not yaml-cpp's passed through");
  CheckErrorNamesSource(error, source);
}

}  // namespace topay::fuzz
