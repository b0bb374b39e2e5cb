// Requests the tool makes of a platform (its OpenID configuration, JWKS, token endpoint and
// line items), with cpp-httplib's client.
#pragma once

#include <chrono>
#include <cstddef>
#include <map>
#include <string>

namespace raygrade::serve {

struct HttpAnswer {
  int status = 0;  // 0: no answer (the connection failed)
  std::string body;
  std::string content_type;
  std::string link;   // the Link header (several joined by ", ")
  std::string error;  // why there was no answer
};

using HttpHeaders = std::multimap<std::string, std::string>;

// "http://host:port" and "/path?query" of a URL; throws Refusal (400) when it is not http(s).
std::pair<std::string, std::string> split_url(const std::string& url);

HttpAnswer http_get(const std::string& url, const HttpHeaders& headers = {});

// What one answer may cost: at most `max_body_bytes` of body, the whole request (connecting,
// headers and body) over by `deadline`, however slowly the other side sends.
struct HttpBounds {
  std::size_t max_body_bytes = 0;
  std::chrono::steady_clock::time_point deadline;
};
// http_get within `bounds`: a longer body, or an answer not over by the deadline, is no answer
// (status 0, `error` saying which), its reading stopped.
HttpAnswer http_get(const std::string& url, const HttpHeaders& headers, const HttpBounds& bounds);

// The origin of an http(s) URL (RFC 6454): "scheme://host[:port]", scheme and host in lower
// case, the scheme's default port left out. Throws Refusal (400) when it is not http(s).
std::string origin_of(const std::string& url);

HttpAnswer http_post(const std::string& url, const std::string& body,
                     const std::string& content_type, const HttpHeaders& headers = {});

// A 2xx answer.
bool http_ok(const HttpAnswer& a);
// "what: HTTP 503 <the body's start>", or "what: no answer (why)".
std::string http_failure(const std::string& what, const HttpAnswer& a);

// Form fields as application/x-www-form-urlencoded.
std::string form_encode(const std::map<std::string, std::string>& fields);

}  // namespace raygrade::serve
