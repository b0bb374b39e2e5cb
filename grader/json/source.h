// SourceFile: a JSON file read with limits, and the line and column of any JSON path in it.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "core/error.h"

namespace raygrade {

// A file as the file system knows it (st_dev, st_ino): the same file whatever path led to it.
struct FileIdentity {
  std::uint64_t device = 0;
  std::uint64_t inode = 0;
  bool operator==(const FileIdentity&) const = default;
};

// Limits on untrusted JSON. Each is far above what a real bank or submission needs.
// Beyond them a file is rejected with a clear error before nlohmann builds anything, so hostile
// input cannot exhaust the stack (deep nesting) or memory (millions of tiny items).
struct JsonLimits {
  std::size_t max_bytes = 16u << 20;   // 16 MiB: a bank file of ~50,000 problems
  int max_depth = 64;                  // problems nest 6 deep; nlohmann's parser recurses
  std::size_t max_string = 64u << 10;  // 64 KiB: a long problem statement
  std::size_t max_items = 100000;      // items in one array or object: 50,000 problems fit
  // Refuse a file whose last path component is a symbolic link (O_NOFOLLOW): submissions are
  // listed with their links resolved and checked, so a link found when opening one is a swap
  // made after the check.
  bool no_follow = false;
  // The file the submissions' listing found at the path: a file opened there that is another
  // one (a folder on the path replaced by a symbolic link after the listing, which O_NOFOLLOW
  // on the last component does not see) is refused.
  std::optional<FileIdentity> expected;

  // The limits for a student's submission: one student's answers to one assignment.
  static JsonLimits submission() {
    JsonLimits l;
    l.max_bytes = 1u << 20;    // 1 MiB: about 5,000 answers with every step
    l.max_depth = 32;          // a submission nests 5 deep (answers, steps, hits, vectors)
    l.max_string = 16u << 10;  // 16 KiB: a long free-text explanation
    l.max_items = 10000;       // answers, or steps of one answer
    l.no_follow = true;
    return l;
  }
};

struct LocateIndex;

// The implicit default constructor: nlohmann::json's (noexcept) throws only for a type other
// than null, in a branch clang-tidy does not rule out.
// NOLINTNEXTLINE(bugprone-exception-escape)
struct SourceFile {
  std::string name;  // as given on the command line
  std::string text;
  nlohmann::json root;

  // locate() in `text`, in time proportional to the path's depth and the size of what it
  // passes through the first time, and to the depth alone after that: the offsets of the
  // lines and of the elements of each array walked are kept, so that a diagnostic for each
  // of 10,000 problems of one file costs no scan of the whole file each. Safe to call from
  // several threads at once (a bank is shared by the threads that grade a batch).
  std::pair<int, int> locate(std::string_view path) const;

 private:
  mutable std::mutex index_mutex_;
  mutable std::shared_ptr<LocateIndex> index_;
};

// Reads and parses a file. Throws Error naming the file (and line and column) on failure.
std::shared_ptr<const SourceFile> load_json_file(const std::string& path,
                                                 const JsonLimits& limits = {});

// Parses text already in memory; `name` is used in diagnostics.
std::shared_ptr<const SourceFile> parse_json_text(std::string name, std::string text,
                                                  const JsonLimits& limits = {});

// The 1-based line and column where the value at JSON pointer `path` starts; {0, 0} if the
// path cannot be found in the text.
std::pair<int, int> locate(std::string_view text, std::string_view path);

}  // namespace raygrade
