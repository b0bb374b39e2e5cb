// Choosing the database of `raygrade serve` from its options, and what both backends say alike.
#include "serve/store.h"

#include <fmt/format.h>

#include "core/error.h"

namespace raygrade::serve {

bool is_postgres_url(const std::string& database) {
  return database.starts_with("postgresql://") || database.starts_with("postgres://");
}

std::unique_ptr<Store> open_store(const std::string& database, const std::string& dir) {
  if (database.empty()) return open_sqlite_store(dir);
  if (is_postgres_url(database)) return open_postgres_store(database);
  throw Error(Diagnostic{"--database", "", 0, 0, Severity::kError,
                         "the database is a PostgreSQL URL (postgresql://HOST/NAME); leave it out "
                         "for SQLite in the data folder",
                         "database"});
}

std::string redacted_url(const std::string& url) {
  // postgresql://user:password@host/... : the password goes, the rest stays.
  std::size_t scheme = url.find("://");
  if (scheme == std::string::npos) return url;
  std::size_t at = url.find('@', scheme + 3);
  std::size_t slash = url.find('/', scheme + 3);
  if (at == std::string::npos || (slash != std::string::npos && slash < at)) return url;
  std::size_t colon = url.find(':', scheme + 3);
  if (colon == std::string::npos || colon > at) return url;
  return url.substr(0, colon) + ":***" + url.substr(at);
}

std::string newer_schema_message(std::int64_t version) {
  return fmt::format(
      "the database's schema is version {}, newer than this raygrade knows (version {}): it was "
      "upgraded by a newer raygrade; run that version (or newer), or restore a backup made "
      "before the upgrade",
      version, kSchemaVersion);
}

}  // namespace raygrade::serve
