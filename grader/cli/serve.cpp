// raygrade serve: the LTI 1.3 tool (docs/lti.md); `raygrade serve register` stores a platform
// registered by hand.
#include <fmt/format.h>
#include <pthread.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <thread>

#include "cli/command.h"
#include "serve/outbox.h"
#include "serve/server.h"
#include "serve/store.h"

namespace raygrade::cli {
// Named rather than anonymous: a unity batch shares one anonymous namespace.
namespace serve_internal {

struct ServeCliOptions {
  std::string data;
  std::string database;
  std::string listen = "127.0.0.1:0";
  std::string public_url;
  std::string assignments;
  serve::ManualRegistration registration;
};

int run_serve(const ServeCliOptions& o) {
  if (o.data.empty() || o.assignments.empty()) {
    fmt::print(stderr, "raygrade serve: give --data and --assignments\n");
    return kExitBadInput;
  }
  std::size_t colon = o.listen.rfind(':');
  int port = -1;
  if (colon != std::string::npos) {
    try {
      port = std::stoi(o.listen.substr(colon + 1));
    } catch (const std::exception&) {
      port = -1;
    }
  }
  if (port < 0 || port > 65535) {
    fmt::print(stderr, "raygrade serve: --listen is HOST:PORT (127.0.0.1:8080; port 0: any)\n");
    return kExitBadInput;
  }
  std::string host = o.listen.substr(0, colon);
  serve::ServeOptions options;
  options.data_dir = o.data;
  options.public_url = o.public_url;
  options.assignments_dir = o.assignments;
  options.database = o.database;
  // One line per request and per score not delivered, on standard error, with the time.
  std::mutex log_mutex;
  options.log = [&log_mutex](const std::string& line) {
    std::string now = serve::iso_time_ms(serve::now_ms());
    std::lock_guard lock(log_mutex);
    fmt::print(stderr, "{} {}\n", now, line);
  };
  // The outbox's first retry and its lease, shortened by the tests.
  for (auto [name, value] : {std::pair{"RAYGRADE_OUTBOX_BASE_MS", &options.outbox_base_ms},
                             std::pair{"RAYGRADE_OUTBOX_LEASE_MS", &options.outbox_lease_ms}}) {
    const char* text = std::getenv(name);
    if (!text) continue;
    try {
      *value = std::max(1L, std::stol(text));
    } catch (const std::exception&) {
      fmt::print(stderr, "raygrade serve: {} is not a number of ms\n", name);
      return kExitBadInput;
    }
  }
  // SIGINT and SIGTERM stop the server from a thread of their own: every thread started
  // from here on inherits the blocked mask, so that the signals reach that thread alone.
  // SIGUSR1 ends that thread when the server stopped otherwise.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  sigaddset(&stop_signals, SIGUSR1);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
  serve::LtiServer server(options);
  for (const auto& w : server.warnings())
    fmt::print(stderr, "raygrade serve: left out: {}\n", format_diagnostic(w));
  int bound = server.bind(host, port);
  const std::string& url = server.public_url();
  fmt::print("raygrade serve: listening on http://{}:{}\n", host, bound);
  fmt::print("registration URL: {}/lti/register\n", url);
  fmt::print("login URL: {}/lti/login\n", url);
  fmt::print("launch URL: {}/lti/launch\n", url);
  fmt::print("JWKS URL: {}/lti/jwks\n", url);
  fmt::print("database: {}\n",
             o.database.empty() ? o.data + "/raygrade.sqlite" : serve::redacted_url(o.database));
  std::fflush(stdout);
  std::thread waiter([&] {
    int signal = 0;
    sigwait(&stop_signals, &signal);
    server.stop();
  });
  server.run();
  // Stopped by a signal: the waiter has returned. Stopped otherwise: wake it.
  pthread_kill(waiter.native_handle(), SIGUSR1);
  waiter.join();
  return kExitOk;
}

int run_register(const ServeCliOptions& o) {
  const serve::ManualRegistration& r = o.registration;
  if ((o.data.empty() && o.database.empty()) || r.issuer.empty() || r.client_id.empty() ||
      r.deployment_id.empty() || r.auth_url.empty() || r.token_url.empty() || r.jwks_url.empty()) {
    fmt::print(stderr,
               "raygrade serve register: give --data (or --database), --issuer, --client-id, "
               "--deployment-id, "
               "--auth-url, --token-url and --jwks-url\n");
    return kExitBadInput;
  }
  serve::register_platform(o.data, o.database, r);
  fmt::print(stderr, "Registered {} (client {}, deployment {}).\n", r.issuer, r.client_id,
             r.deployment_id);
  return kExitOk;
}

}  // namespace serve_internal

Runner setup_serve(CLI::App& sub) {
  using namespace serve_internal;  // NOLINT: this file's own functions
  auto o = std::make_shared<ServeCliOptions>();
  sub.add_option("--data", o->data, "the folder of the database (made when missing)");
  sub.add_option("--database", o->database,
                 "a PostgreSQL URL (postgresql://HOST/NAME) shared by several servers; default: "
                 "SQLite in the data folder");
  sub.add_option("--listen", o->listen, "HOST:PORT to listen on (port 0: any free port)");
  sub.add_option("--public-url", o->public_url,
                 "the URL browsers and platforms reach it at (default: http://HOST:PORT bound)");
  sub.add_option("--assignments", o->assignments, "the folder of assignment files offered");
  CLI::App* reg = sub.add_subcommand("register", "store a platform registered by hand");
  reg->add_option("--data", o->data, "the folder of the SQLite database");
  reg->add_option("--database", o->database, "a PostgreSQL URL, rather than SQLite in --data");
  reg->add_option("--issuer", o->registration.issuer, "the platform's issuer")->required();
  reg->add_option("--client-id", o->registration.client_id, "the client id it gave the tool")
      ->required();
  reg->add_option("--deployment-id", o->registration.deployment_id, "the deployment id")
      ->required();
  reg->add_option("--auth-url", o->registration.auth_url, "its OIDC authorization endpoint")
      ->required();
  reg->add_option("--token-url", o->registration.token_url, "its OAuth 2 token endpoint")
      ->required();
  reg->add_option("--jwks-url", o->registration.jwks_url, "its JWKS URL")->required();
  return [o, reg] { return reg->parsed() ? run_register(*o) : run_serve(*o); };
}

}  // namespace raygrade::cli
