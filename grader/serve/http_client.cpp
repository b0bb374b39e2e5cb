// Requests the tool makes of a platform, with cpp-httplib's client.
#include "serve/http_client.h"

#include <fmt/format.h>
#include <httplib.h>

#include "serve/jwt.h"

namespace raygrade::serve {

namespace {

// Seconds a platform has to answer one request.
constexpr int kTimeoutSeconds = 10;

HttpAnswer answer_of(const httplib::Result& r) {
  HttpAnswer a;
  if (!r) {
    a.error = httplib::to_string(r.error());
    return a;
  }
  a.status = r->status;
  a.body = r->body;
  a.content_type = r->get_header_value("Content-Type");
  auto [from, to] = r->headers.equal_range("Link");
  for (auto it = from; it != to; ++it) a.link += (a.link.empty() ? "" : ", ") + it->second;
  return a;
}

httplib::Client client_for(const std::string& origin) {
  httplib::Client c(origin);
  c.set_connection_timeout(kTimeoutSeconds);
  c.set_read_timeout(kTimeoutSeconds);
  c.set_write_timeout(kTimeoutSeconds);
  c.set_follow_location(false);
  return c;
}

httplib::Headers headers_of(const HttpHeaders& h) { return httplib::Headers(h.begin(), h.end()); }

}  // namespace

std::pair<std::string, std::string> split_url(const std::string& url) {
  std::size_t scheme = url.find("://");
  if (scheme == std::string::npos ||
      (url.compare(0, scheme, "http") != 0 && url.compare(0, scheme, "https") != 0))
    throw Refusal(400, "not an http or https URL: " + url);
  std::size_t path = url.find('/', scheme + 3);
  if (path == std::string::npos) return {url, "/"};
  return {url.substr(0, path), url.substr(path)};
}

HttpAnswer http_get(const std::string& url, const HttpHeaders& headers) {
  auto [origin, path] = split_url(url);
  return answer_of(client_for(origin).Get(path.c_str(), headers_of(headers)));
}

HttpAnswer http_post(const std::string& url, const std::string& body,
                     const std::string& content_type, const HttpHeaders& headers) {
  auto [origin, path] = split_url(url);
  return answer_of(
      client_for(origin).Post(path.c_str(), headers_of(headers), body, content_type.c_str()));
}

bool http_ok(const HttpAnswer& a) { return a.status >= 200 && a.status < 300; }

std::string http_failure(const std::string& what, const HttpAnswer& a) {
  if (a.status == 0) return what + ": no answer (" + a.error + ")";
  return fmt::format("{}: HTTP {} {}", what, a.status, a.body.substr(0, 200));
}

std::string form_encode(const std::map<std::string, std::string>& fields) {
  std::string out;
  for (const auto& [k, v] : fields) {
    if (!out.empty()) out += '&';
    out += httplib::detail::encode_query_param(k) + "=" + httplib::detail::encode_query_param(v);
  }
  return out;
}

}  // namespace raygrade::serve
