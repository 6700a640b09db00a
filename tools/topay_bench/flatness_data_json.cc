#include "tools/topay_bench/flatness_data_json.h"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "core/common/error.h"

namespace topay::bench {
namespace {

using Json = nlohmann::ordered_json;
constexpr const char* kFormat = "topay-flatness-trajectory";

Json Rows(const Eigen::MatrixXd& m) {
  Json rows = Json::array();
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    Json row = Json::array();
    for (Eigen::Index c = 0; c < m.cols(); ++c) row.push_back(m(r, c));
    rows.push_back(row);
  }
  return rows;
}

// A reader that names the file and field of every error.
struct Reader {
  std::string file;

  [[noreturn]] void Fail(const std::string& field, const std::string& message) const {
    throw ConfigError(file, field, message);
  }
  const nlohmann::json& Member(const nlohmann::json& doc, const std::string& key) const {
    if (!doc.contains(key)) Fail(key, "missing");
    return doc.at(key);
  }
  double Number(const nlohmann::json& value, const std::string& field) const {
    if (!value.is_number() || !std::isfinite(value.get<double>())) {
      Fail(field, "expected a finite number");
    }
    return value.get<double>();
  }
  Eigen::VectorXd Vector(const nlohmann::json& value, const std::string& field) const {
    if (!value.is_array()) Fail(field, "expected an array of numbers");
    Eigen::VectorXd v(static_cast<Eigen::Index>(value.size()));
    for (std::size_t i = 0; i < value.size(); ++i) {
      v(static_cast<Eigen::Index>(i)) = Number(value[i], field + "[" + std::to_string(i) + "]");
    }
    return v;
  }
  Eigen::MatrixXd Matrix(const nlohmann::json& doc, const std::string& key,
                         Eigen::Index cols) const {
    const nlohmann::json& value = Member(doc, key);
    if (!value.is_array() || value.size() < 3) Fail(key, "expected at least 3 rows (x, y, q..)");
    Eigen::MatrixXd m(static_cast<Eigen::Index>(value.size()), cols);
    for (std::size_t r = 0; r < value.size(); ++r) {
      const std::string field = key + "[" + std::to_string(r) + "]";
      const Eigen::VectorXd row = Vector(value[r], field);
      if (row.size() != cols) Fail(field, "expected " + std::to_string(cols) + " numbers");
      m.row(static_cast<Eigen::Index>(r)) = row.transpose();
    }
    return m;
  }
};

}  // namespace

std::string FlatnessDataToJson(const FlatnessTrajectoryData& data) {
  Json doc;
  doc["format"] = kFormat;
  doc["version"] = 1;
  doc["start_yaw_rad"] = data.start_yaw_rad;
  doc["end_yaw_rad"] = data.end_yaw_rad;
  doc["durations_s"] = std::vector<double>(data.durations_s.data(),
                                           data.durations_s.data() + data.durations_s.size());
  doc["head"] = Rows(data.head);
  doc["tail"] = Rows(data.tail);
  doc["waypoints"] = Rows(data.waypoints);
  return doc.dump(1) + "\n";
}

void WriteFlatnessDataJson(const std::string& path, const FlatnessTrajectoryData& data) {
  std::ofstream file(path, std::ios::binary);
  file << FlatnessDataToJson(data);
  file.close();
  if (!file) throw ConfigError(path, "", "cannot write the file");
}

FlatnessTrajectoryData ReadFlatnessDataJson(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw ConfigError(path, "", "cannot open the file");
  std::ostringstream text;
  text << file.rdbuf();
  return FlatnessDataFromJson(text.str(), path);
}

FlatnessTrajectoryData FlatnessDataFromJson(const std::string& text, const std::string& file_name) {
  const Reader r{file_name};
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    r.Fail("", std::string("malformed JSON: ") + e.what());
  }
  if (!doc.is_object()) r.Fail("", "expected a JSON object");
  const nlohmann::json& format = r.Member(doc, "format");
  if (!format.is_string() || format.get<std::string>() != kFormat) {
    r.Fail("format", std::string("expected \"") + kFormat + "\"");
  }
  if (r.Number(r.Member(doc, "version"), "version") != 1.0) r.Fail("version", "expected 1");
  FlatnessTrajectoryData data;
  data.start_yaw_rad = r.Number(r.Member(doc, "start_yaw_rad"), "start_yaw_rad");
  data.end_yaw_rad = r.Number(r.Member(doc, "end_yaw_rad"), "end_yaw_rad");
  data.durations_s = r.Vector(r.Member(doc, "durations_s"), "durations_s");
  if (data.durations_s.size() == 0) r.Fail("durations_s", "no pieces");
  for (Eigen::Index j = 0; j < data.durations_s.size(); ++j) {
    if (!(data.durations_s(j) > 0.0)) {
      r.Fail("durations_s[" + std::to_string(j) + "]", "must be > 0");
    }
  }
  data.head = r.Matrix(doc, "head", 3);
  data.tail = r.Matrix(doc, "tail", 3);
  data.waypoints = r.Matrix(doc, "waypoints", data.durations_s.size() - 1);
  if (data.tail.rows() != data.head.rows() || data.waypoints.rows() != data.head.rows()) {
    r.Fail("tail", "head, tail and waypoints must have the same number of rows");
  }
  return data;
}

}  // namespace topay::bench
