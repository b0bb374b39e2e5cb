// Requests the tool makes of a platform, with cpp-httplib's client.
#include "serve/http_client.h"

#include <fmt/format.h>
#include <httplib.h>

#include <condition_variable>
#include <mutex>
#include <thread>

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

HttpAnswer http_get(const std::string& url, const HttpHeaders& headers, const HttpBounds& bounds) {
  auto [origin, path] = split_url(url);
  httplib::Client c = client_for(origin);
  // A watchdog shuts the connection at the deadline, and again until the request has ended
  // (a stop before the connection is made finds no socket yet).
  std::mutex mutex;
  std::condition_variable cv;
  bool done = false, late = false;
  std::thread watchdog([&] {
    std::unique_lock lock(mutex);
    if (cv.wait_until(lock, bounds.deadline, [&] { return done; })) return;
    late = true;
    while (!done) {
      c.stop();
      cv.wait_for(lock, std::chrono::milliseconds(100));
    }
  });
  std::string body;
  bool too_big = false;
  httplib::Result r =
      c.Get(path.c_str(), headers_of(headers), [&](const char* data, std::size_t n) {
        if (n > bounds.max_body_bytes - body.size()) {
          too_big = true;
          return false;
        }
        body.append(data, n);
        return true;
      });
  {
    std::lock_guard lock(mutex);
    done = true;
  }
  cv.notify_all();
  watchdog.join();
  HttpAnswer a = answer_of(r);
  if (too_big || late) {
    a = HttpAnswer{};
    a.error = too_big ? fmt::format("the answer is longer than {} bytes", bounds.max_body_bytes)
                      : "the answer did not come in time";
    return a;
  }
  a.body = std::move(body);
  return a;
}

std::string origin_of(const std::string& url) {
  std::string origin = split_url(url).first;
  for (char& c : origin) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (origin.starts_with("http://") && origin.ends_with(":80")) origin.resize(origin.size() - 3);
  if (origin.starts_with("https://") && origin.ends_with(":443")) origin.resize(origin.size() - 4);
  return origin;
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
