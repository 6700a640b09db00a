// The static files: percent-decoding, the mapping of targets to files under the web root (no
// way out: "..", encoded or not, backslashes, symlinks leading outside, hidden files), the
// content types, and the responses (GET, HEAD, 404, 405, keep-alive, no-cache).
#include "procs/viz/server/http_files.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include <boost/beast/http/field.hpp>

namespace topay::viz {
namespace {

namespace fs = std::filesystem;
namespace http = boost::beast::http;

void WriteFile(const fs::path& path, const std::string& contents) {
  std::ofstream(path, std::ios::binary) << contents;
}

// root/{index.html, app.js, style.css, .hidden, sub/{index.html, page.html}, link_out,
// dirlink} and secret.txt beside root.
class HttpFilesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "viz_http_files_XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    base_ = fs::canonical(pattern);
    root_ = base_ / "root";
    fs::create_directories(root_ / "sub");
    WriteFile(root_ / "index.html", "<html>index</html>");
    WriteFile(root_ / "app.js", "console.log(1);");
    WriteFile(root_ / "style.css", "body{}");
    WriteFile(root_ / ".hidden", "hidden");
    WriteFile(root_ / "sub" / "index.html", "sub index");
    WriteFile(root_ / "sub" / "page.html", "sub page");
    WriteFile(base_ / "secret.txt", "SECRET");
    fs::create_symlink(base_ / "secret.txt", root_ / "link_out");
    fs::create_symlink(base_, root_ / "dirlink");
  }
  void TearDown() override { fs::remove_all(base_); }

  WebPath Resolve(std::string_view target) const { return ResolveWebPath(root_, target); }

  static HttpRequest Request(http::verb method, std::string target, bool keep_alive = true) {
    HttpRequest request{method, target, 11};
    request.keep_alive(keep_alive);
    return request;
  }

  fs::path base_;
  fs::path root_;
};

TEST(PercentDecodeTest, DecodesEscapesAndRefusesBadOnes) {
  EXPECT_EQ(PercentDecode("/a%20b"), "/a b");
  EXPECT_EQ(PercentDecode("%2e%2E"), "..");
  EXPECT_EQ(PercentDecode("a+b"), "a+b");
  EXPECT_EQ(PercentDecode(""), "");
  EXPECT_EQ(PercentDecode("%4"), std::nullopt);
  EXPECT_EQ(PercentDecode("%"), std::nullopt);
  EXPECT_EQ(PercentDecode("%zz"), std::nullopt);
  EXPECT_EQ(PercentDecode("a%00b"), std::nullopt);
}

TEST_F(HttpFilesTest, ResolvesFilesAndIndexes) {
  EXPECT_EQ(Resolve("/").file, root_ / "index.html");
  EXPECT_EQ(Resolve("/index.html").file, root_ / "index.html");
  EXPECT_EQ(Resolve("/app.js?v=2#top").file, root_ / "app.js");
  EXPECT_EQ(Resolve("//app.js").file, root_ / "app.js");
  EXPECT_EQ(Resolve("/./app.js").file, root_ / "app.js");
  EXPECT_EQ(Resolve("/%61pp.js").file, root_ / "app.js");
  EXPECT_EQ(Resolve("/sub").file, root_ / "sub" / "index.html");
  EXPECT_EQ(Resolve("/sub/").file, root_ / "sub" / "index.html");
  EXPECT_EQ(Resolve("/sub/page.html").status, 200u);
}

TEST_F(HttpFilesTest, MissingFilesAre404) {
  EXPECT_EQ(Resolve("/missing.js").status, 404u);
  EXPECT_EQ(Resolve("/sub/missing/").status, 404u);
  EXPECT_EQ(Resolve("/app.js/").status, 404u);  // a file is no folder
}

TEST_F(HttpFilesTest, TraversalIsRefused) {
  EXPECT_EQ(Resolve("/../secret.txt").status, 400u);
  EXPECT_EQ(Resolve("/sub/../../secret.txt").status, 400u);
  EXPECT_EQ(Resolve("/%2e%2e/secret.txt").status, 400u);
  EXPECT_EQ(Resolve("/%2E%2E/secret.txt").status, 400u);
  EXPECT_EQ(Resolve("/..%2fsecret.txt").status, 400u);
  EXPECT_EQ(Resolve("/sub/%2e%2e%2f%2e%2e%2fsecret.txt").status, 400u);
  EXPECT_EQ(Resolve("/..\\secret.txt").status, 400u);
  EXPECT_EQ(Resolve("/sub/..%5c..%5csecret.txt").status, 400u);
  EXPECT_EQ(Resolve("/%252e%252e/secret.txt").status, 404u);  // decoded once: a name, no file
  EXPECT_EQ(Resolve("/sub/..").status, 400u);
}

TEST_F(HttpFilesTest, SymlinksLeadingOutsideAndHiddenFilesAre404) {
  EXPECT_EQ(Resolve("/link_out").status, 404u);
  EXPECT_EQ(Resolve("/dirlink/secret.txt").status, 404u);
  EXPECT_EQ(Resolve("/.hidden").status, 404u);
  EXPECT_EQ(Resolve("/%2ehidden").status, 404u);
}

TEST_F(HttpFilesTest, MalformedTargetsAre400) {
  EXPECT_EQ(Resolve("").status, 400u);
  EXPECT_EQ(Resolve("app.js").status, 400u);
  EXPECT_EQ(Resolve("http://127.0.0.1/app.js").status, 400u);
  EXPECT_EQ(Resolve("*").status, 400u);
  EXPECT_EQ(Resolve("/app%2").status, 400u);
  EXPECT_EQ(Resolve("/app%00.js").status, 400u);
}

TEST(ContentTypeTest, ByExtension) {
  EXPECT_EQ(ContentTypeFor("a/index.html"), "text/html; charset=utf-8");
  EXPECT_EQ(ContentTypeFor("main.js"), "text/javascript; charset=utf-8");
  EXPECT_EQ(ContentTypeFor("style.css"), "text/css; charset=utf-8");
  EXPECT_EQ(ContentTypeFor("x.json"), "application/json");
  EXPECT_EQ(ContentTypeFor("main.js.map"), "application/json");
  EXPECT_EQ(ContentTypeFor("logo.png"), "image/png");
  EXPECT_EQ(ContentTypeFor("icon.svg"), "image/svg+xml");
  EXPECT_EQ(ContentTypeFor("mod.wasm"), "application/wasm");
  EXPECT_EQ(ContentTypeFor("blob"), "application/octet-stream");
}

TEST_F(HttpFilesTest, GetServesTheFileWithItsType) {
  const HttpFiles files(root_.string());
  const HttpResponse response = files.Respond(Request(http::verb::get, "/app.js"));
  EXPECT_EQ(response.result(), http::status::ok);
  EXPECT_EQ(response.body(), "console.log(1);");
  EXPECT_EQ(response[http::field::content_type], "text/javascript; charset=utf-8");
  EXPECT_EQ(response[http::field::cache_control], "no-cache");
  EXPECT_EQ(response[http::field::content_length], "15");
  EXPECT_TRUE(response.keep_alive());
  const HttpResponse index = files.Respond(Request(http::verb::get, "/", false));
  EXPECT_EQ(index.body(), "<html>index</html>");
  EXPECT_FALSE(index.keep_alive());
}

TEST_F(HttpFilesTest, HeadSendsTheHeadersOnly) {
  const HttpFiles files(root_.string());
  const HttpResponse response = files.Respond(Request(http::verb::head, "/style.css"));
  EXPECT_EQ(response.result(), http::status::ok);
  EXPECT_EQ(response.body(), "");
  EXPECT_EQ(response[http::field::content_length], "6");
  EXPECT_EQ(response[http::field::content_type], "text/css; charset=utf-8");
}

TEST_F(HttpFilesTest, ErrorsAnswerWithTheirStatus) {
  const HttpFiles files(root_.string());
  EXPECT_EQ(files.Respond(Request(http::verb::get, "/nope")).result(), http::status::not_found);
  const HttpResponse traversal = files.Respond(Request(http::verb::get, "/%2e%2e/secret.txt"));
  EXPECT_EQ(traversal.result(), http::status::bad_request);
  EXPECT_EQ(traversal.body().find("SECRET"), std::string::npos);
  const HttpResponse post = files.Respond(Request(http::verb::post, "/"));
  EXPECT_EQ(post.result(), http::status::method_not_allowed);
  EXPECT_EQ(post[http::field::allow], "GET, HEAD");
  EXPECT_EQ(files.Respond(Request(http::verb::delete_, "/app.js")).result(),
            http::status::method_not_allowed);
}

TEST_F(HttpFilesTest, NoWebRootServesANoticeOnly) {
  const HttpFiles files("");
  EXPECT_FALSE(files.root());
  const HttpResponse notice = files.Respond(Request(http::verb::get, "/"));
  EXPECT_EQ(notice.result(), http::status::ok);
  EXPECT_NE(notice.body().find("topay-viz"), std::string::npos);
  EXPECT_EQ(files.Respond(Request(http::verb::get, "/index.html")).result(),
            http::status::not_found);
  EXPECT_FALSE(HttpFiles((base_ / "no_such_folder").string()).root());
  EXPECT_FALSE(HttpFiles((base_ / "secret.txt").string()).root());
}

}  // namespace
}  // namespace topay::viz
