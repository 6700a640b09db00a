#pragma once
// The static files of the viewer's page over HTTP: GET and HEAD of regular files under the web
// root ("/" and folders: their index.html), content types by extension, no way out of the root
// ("..", encoded or not, is refused; symlinks leading outside are not followed out).

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "procs/viz/server/http_response.h"

namespace topay::viz {

/// `text` with its %XX escapes decoded; nullopt for a bad escape ("%4", "%zz") or a decoded
/// NUL. "+" stays "+" (this is a path, not a form).
std::optional<std::string> PercentDecode(std::string_view text);

/// Where a request target leads under the web root.
struct WebPath {
  /// 200: `file` is a regular file under the root. 400: malformed target (not origin-form,
  /// bad escape, backslash, NUL) or a ".." segment. 404: no such file, a hidden (".x")
  /// segment, or a path that resolves outside the root.
  unsigned status = 404;
  /// The canonical path of the file (status 200 only).
  std::filesystem::path file;
};

/// Maps `target` ("/app/main.js?v=2": the query and fragment are ignored) to a file under
/// `canonical_root` (which must be canonical: see std::filesystem::canonical). A target
/// ending in "/" (or "/" itself) or naming a folder means that folder's index.html.
WebPath ResolveWebPath(const std::filesystem::path& canonical_root, std::string_view target);

/// The Content-Type of `file` by its extension: html, js / mjs, css, json, map, png, svg,
/// wasm, ico, txt, ...; "application/octet-stream" for the rest.
std::string_view ContentTypeFor(const std::filesystem::path& file);

/// Answers the HTTP requests that are not WebSocket upgrades.
class HttpFiles {
 public:
  /// `web_root`: the folder served; "" (or a missing folder, logged) serves only a short
  /// notice on "/".
  explicit HttpFiles(const std::string& web_root);

  /// The response to `request`: 200 with the file (GET) or its headers only (HEAD), 400,
  /// 404, or 405 for other methods. Keep-alive follows the request.
  HttpResponse Respond(const HttpRequest& request) const;

  /// The canonical web root; nullopt when nothing is served.
  const std::optional<std::filesystem::path>& root() const { return root_; }

 private:
  HttpResponse Notice(const HttpRequest& request) const;
  HttpResponse File(const HttpRequest& request, const std::filesystem::path& file) const;

  std::optional<std::filesystem::path> root_;
};

}  // namespace topay::viz
