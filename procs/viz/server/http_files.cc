#include "procs/viz/server/http_files.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <iterator>
#include <system_error>
#include <utility>
#include <vector>

#include <boost/beast/http/field.hpp>
#include <boost/beast/http/verb.hpp>
#include <spdlog/spdlog.h>

namespace topay::viz {
namespace {

namespace fs = std::filesystem;
namespace http = boost::beast::http;

int HexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// The target's path part: up to the query or fragment.
std::string_view PathPart(std::string_view target) {
  return target.substr(0, std::min(target.find('?'), target.find('#')));
}

// The segments of a decoded absolute path ("" and "." skipped); status 400 / 404 on a bad one.
unsigned SplitSegments(std::string_view path, std::vector<std::string>* segments) {
  std::size_t start = 1;  // path[0] == '/'
  while (start <= path.size()) {
    const std::size_t end = std::min(path.find('/', start), path.size());
    const std::string_view segment = path.substr(start, end - start);
    start = end + 1;
    if (segment.empty() || segment == ".") continue;
    if (segment == ".." || segment.find('\\') != std::string_view::npos) return 400;
    if (segment.front() == '.') return 404;  // hidden files (.git, .env, ...) are never served
    segments->emplace_back(segment);
  }
  return 200;
}

bool IsUnder(const fs::path& file, const fs::path& root) {
  const auto [root_end, file_end] =
      std::mismatch(root.begin(), root.end(), file.begin(), file.end());
  return root_end == root.end() && file_end != file.end();
}

// `path` made canonical, followed into its index.html when it is a folder; nullopt if missing.
std::optional<fs::path> CanonicalFile(const fs::path& path) {
  std::error_code error;
  fs::path file = fs::canonical(path, error);
  if (error) return std::nullopt;
  if (fs::is_directory(file, error)) {
    file = fs::canonical(file / "index.html", error);
    if (error) return std::nullopt;
  }
  if (!fs::is_regular_file(file, error)) return std::nullopt;
  return file;
}

std::optional<std::string> ReadFile(const fs::path& file) {
  std::ifstream stream(file, std::ios::binary);
  if (!stream) return std::nullopt;
  std::string contents{std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
  if (stream.bad()) return std::nullopt;
  return contents;
}

// The file's size as a decimal string (for HEAD: Content-Length without the body).
std::optional<std::string> FileSizeOnly(const fs::path& file) {
  std::error_code error;
  const std::uintmax_t size = fs::file_size(file, error);
  if (error) return std::nullopt;
  return std::to_string(size);
}

}  // namespace

std::optional<std::string> PercentDecode(std::string_view text) {
  std::string decoded;
  decoded.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (c == '%') {
      if (i + 2 >= text.size()) return std::nullopt;
      const int high = HexValue(text[i + 1]);
      const int low = HexValue(text[i + 2]);
      if (high < 0 || low < 0) return std::nullopt;
      c = static_cast<char>(high * 16 + low);
      i += 2;
    }
    if (c == '\0') return std::nullopt;
    decoded.push_back(c);
  }
  return decoded;
}

WebPath ResolveWebPath(const fs::path& canonical_root, std::string_view target) {
  const std::string_view raw_path = PathPart(target);
  if (raw_path.empty() || raw_path.front() != '/') return {400, {}};
  const std::optional<std::string> path = PercentDecode(raw_path);
  if (!path) return {400, {}};
  std::vector<std::string> segments;
  if (const unsigned status = SplitSegments(*path, &segments); status != 200) return {status, {}};
  fs::path candidate = canonical_root;
  for (const std::string& segment : segments) candidate /= segment;
  if (segments.empty() || path->back() == '/') candidate /= "index.html";
  const std::optional<fs::path> file = CanonicalFile(candidate);
  if (!file || !IsUnder(*file, canonical_root)) return {404, {}};
  return {200, *file};
}

std::string_view ContentTypeFor(const fs::path& file) {
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 14> kTypes{{
      {".html", "text/html; charset=utf-8"},
      {".htm", "text/html; charset=utf-8"},
      {".js", "text/javascript; charset=utf-8"},
      {".mjs", "text/javascript; charset=utf-8"},
      {".css", "text/css; charset=utf-8"},
      {".json", "application/json"},
      {".map", "application/json"},
      {".png", "image/png"},
      {".svg", "image/svg+xml"},
      {".wasm", "application/wasm"},
      {".ico", "image/x-icon"},
      {".txt", "text/plain; charset=utf-8"},
      {".jpg", "image/jpeg"},
      {".woff2", "font/woff2"},
  }};
  const std::string extension = file.extension().string();
  for (const auto& [known, type] : kTypes) {
    if (extension == known) return type;
  }
  return "application/octet-stream";
}

HttpFiles::HttpFiles(const std::string& web_root) {
  if (web_root.empty()) return;
  std::error_code error;
  fs::path root = fs::canonical(web_root, error);
  if (error || !fs::is_directory(root, error)) {
    spdlog::warn("viz server: web root '{}' is not a folder: serving no files", web_root);
    return;
  }
  root_ = std::move(root);
}

HttpResponse HttpFiles::Respond(const HttpRequest& request) const {
  const unsigned version = request.version();
  const bool keep_alive = request.keep_alive();
  if (request.method() != http::verb::get && request.method() != http::verb::head) {
    HttpResponse response = PlainResponse(http::status::method_not_allowed,
                                          "Only GET and HEAD are allowed.\n", version, keep_alive);
    response.set(http::field::allow, "GET, HEAD");
    return response;
  }
  if (!root_) return Notice(request);
  const WebPath path = ResolveWebPath(*root_, ToStd(request.target()));
  if (path.status == 400) {
    return PlainResponse(http::status::bad_request, "Bad request target.\n", version, keep_alive);
  }
  if (path.status != 200) {
    return PlainResponse(http::status::not_found, "Not found.\n", version, keep_alive);
  }
  return File(request, path.file);
}

HttpResponse HttpFiles::Notice(const HttpRequest& request) const {
  if (PathPart(ToStd(request.target())) != "/") {
    return PlainResponse(http::status::not_found, "Not found.\n", request.version(),
                         request.keep_alive());
  }
  HttpResponse response = PlainResponse(
      http::status::ok, "topay-viz: no web root is configured; connect a Foxglove client.\n",
      request.version(), request.keep_alive());
  if (request.method() == http::verb::head) response.body().clear();
  return response;
}

HttpResponse HttpFiles::File(const HttpRequest& request, const fs::path& file) const {
  const bool head = request.method() == http::verb::head;
  std::optional<std::string> contents = head ? FileSizeOnly(file) : ReadFile(file);
  if (!contents) {
    return PlainResponse(http::status::not_found, "Not found.\n", request.version(),
                         request.keep_alive());
  }
  HttpResponse response{http::status::ok, request.version()};
  SetCommonHeaders(response);
  response.set(http::field::content_type, ToBeast(ContentTypeFor(file)));
  response.keep_alive(request.keep_alive());
  if (head) {
    response.set(http::field::content_length, *contents);  // the size, no body
  } else {
    response.body() = std::move(*contents);
    response.prepare_payload();
  }
  return response;
}

}  // namespace topay::viz
