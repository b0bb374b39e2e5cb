// Reading problems and banks.
#include "problems/problem.h"

#include <algorithm>
#include <filesystem>
#include <map>

namespace raygrade {

std::vector<std::string> Task::conclusion() const {
  auto parts = derive("");
  if (parts.empty()) return {};
  return parts.back().derivation.conclusion;
}

const std::vector<std::string>& common_problem_keys() {
  static const std::vector<std::string> keys = {
      "id",          "kind",       "title",        "statement", "method", "precision",
      "expected",    "tolerance",  "points",       "tests",     "tags",   "source",
      "conventions", "parameters", "nice_numbers", "mistakes"};
  return keys;
}

namespace {

// The value of `key`, one of the words of `choices`: any other is an error naming them all.
template <typename E>
E read_choice(const Cursor& c, const char* key,
              std::initializer_list<std::pair<std::string_view, E>> choices) {
  std::string v = c.at(key).string();
  std::string words;  // "a", "b" or "c"
  std::size_t n = 0;
  for (const auto& [word, value] : choices) {
    if (word == v) return value;
    words += fmt::format("{}\"{}\"", n == 0 ? "" : n + 1 == choices.size() ? " or " : ", ", word);
    ++n;
  }
  c.at(key).fail(fmt::format("{} is {}, not \"{}\"", key, words, v), "invalid");
}

}  // namespace

Conventions read_conventions(const Cursor& c, Conventions base) {
  if (!c.is_object()) c.fail("conventions is an object", "type");
  c.allow_only({"contained", "facing_away"});
  using C = Conventions::Contained;
  using F = Conventions::FacingAway;
  if (c.has("contained")) {
    base.contained = read_choice<C>(
        c, "contained", {{"either", C::kEither}, {"line", C::kLine}, {"miss", C::kMiss}});
  }
  if (c.has("facing_away")) {
    base.facing_away = read_choice<F>(
        c, "facing_away",
        {{"either", F::kEither}, {"shadow-ray", F::kShadowRay}, {"normal-first", F::kNormalFirst}});
  }
  return base;
}

nlohmann::json vec_json(const Vec3d& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

nlohmann::json hit_json(const Hit& h) {
  nlohmann::json j = {{"t", h.t}, {"point", vec_json(h.point)}, {"normal", vec_json(h.normal)}};
  if (h.barycentric) j["barycentric"] = *h.barycentric;
  return j;
}

nlohmann::json intersection_json(const Intersection& x) {
  nlohmann::json hits = nlohmann::json::array();
  for (const auto& h : x.hits) hits.push_back(hit_json(h));
  nlohmann::json j = {{"hits", hits}};
  if (x.contained) j["contained"] = true;
  return j;
}

Ray read_ray(const Cursor& c) {
  c.allow_only({"origin", "direction", "t_min", "t_max"});
  Ray ray;
  ray.origin = c.at("origin").vec3();
  ray.direction = c.at("direction").nonzero_vec3();
  ray.t_min = c.number_or("t_min", 0);
  ray.t_max = c.number_or("t_max", kInfinity);
  if (ray.t_min > ray.t_max) {
    c.at("t_max").fail(fmt::format("t_max = {} is below t_min = {}", ray.t_max, ray.t_min),
                       "invalid");
  }
  return ray;
}

namespace {

Problem read_plain_problem(const Cursor& c, const Conventions& defaults);

// Reads the plain problem that `values` make of the parameterized problem at `c`. Its faults
// are reported at the problem's place in the file as written.
Problem read_instance(const Cursor& c, std::shared_ptr<const ParameterSet> set,
                      const ParameterValues& values, const Conventions& defaults) {
  nlohmann::json plain = instantiate(c, *set, values);
  auto file = std::make_shared<SourceFile>();
  file->name = c.file_name();
  file->text = plain.dump(2);
  file->root = std::move(plain);
  Problem p;
  try {
    p = read_plain_problem(Cursor(file, &file->root, c.path()), defaults);
  } catch (const Error& e) {
    Diagnostic d = e.diagnostic();
    std::tie(d.line, d.column) = locate(c.file()->text, d.path);
    throw Error(d);
  }
  p.parameters = std::move(set);
  p.template_file = c.file();
  p.template_json = &c.json();
  p.values = values;
  return p;
}

}  // namespace

Problem read_problem(const Cursor& c, const Conventions& defaults) {
  if (c.is_object() && c.has("parameters")) {
    auto set = std::make_shared<const ParameterSet>(read_parameters(c));
    ParameterValues values = set->defaults();
    return read_instance(c, std::move(set), values, defaults);
  }
  if (c.is_object() && c.has("nice_numbers")) (void)read_parameters(c);  // reports the fault
  return read_plain_problem(c, defaults);
}

Problem read_problem_variant(const Problem& base, const ParameterValues& values) {
  Cursor c(base.template_file, base.template_json, base.path);
  return read_instance(c, base.parameters, values, base.file_conventions);
}

namespace {

Problem read_plain_problem(const Cursor& c, const Conventions& defaults) {
  if (!c.is_object()) c.fail("a problem must be a JSON object", "type");
  Problem p;
  p.id = c.at("id").string();
  if (p.id.empty()) c.at("id").fail("the id must not be empty", "invalid");
  p.kind = c.string_or("kind", std::string(kind_table().front().name));
  const KindEntry* entry = nullptr;
  std::vector<std::string> names;
  for (const auto& k : kind_table()) {
    names.emplace_back(k.name);
    if (k.name == p.kind) entry = &k;
  }
  if (!entry) {
    std::string hint = closest_match(p.kind, names);
    c.at("kind").fail(
        hint.empty() ? fmt::format("unknown kind '{}' (known: {})", p.kind, fmt::join(names, ", "))
                     : fmt::format("unknown kind '{}' (did you mean '{}'?)", p.kind, hint),
        "unknown-kind");
  }
  std::vector<std::string> keys = common_problem_keys();
  keys.insert(keys.end(), entry->keys.begin(), entry->keys.end());
  c.allow_only(keys);
  p.title = c.string_or("title", "");
  p.statement = c.string_or("statement", "");
  p.method = c.string_or("method", "");
  if (c.has("precision")) {
    p.precision = c.at("precision").integer();
    if (p.precision < 0 || p.precision > 15) {
      c.at("precision").fail("precision is a number of decimals from 0 to 15", "range");
    }
  }
  if (auto e = c.find("expected")) p.expected = e->json();
  if (auto t = c.find("tolerance")) p.tolerance = t->json();
  if (auto t = c.find("points")) p.points = t->json();
  if (auto t = c.find("tests")) p.tests = t->json();
  p.conventions = defaults;
  p.file_conventions = defaults;
  if (auto t = c.find("conventions")) p.conventions = read_conventions(*t, defaults);
  p.source = c.json();
  p.file = c.file_name();
  p.path = c.path();
  p.source_file = c.file();
  p.task = entry->read(c);
  p.task->follow(p.conventions);
  if (!p.method.empty()) {
    auto methods = p.task->methods();
    if (std::find(methods.begin(), methods.end(), p.method) == methods.end()) {
      c.at("method").fail(fmt::format("unknown method '{}' for this problem (known: {})", p.method,
                                      fmt::join(methods, ", ")),
                          "unknown-method");
    }
  }
  return p;
}

void collect_files(const std::filesystem::path& path, std::vector<std::string>& out,
                   std::vector<Diagnostic>& errors) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    std::vector<std::string> found;
    for (fs::recursive_directory_iterator it(path, ec), end; !ec && it != end; it.increment(ec)) {
      if (it->is_regular_file(ec) && it->path().extension() == ".json") {
        found.push_back(it->path().string());
      }
    }
    std::sort(found.begin(), found.end());
    out.insert(out.end(), found.begin(), found.end());
  } else if (fs::exists(path, ec)) {
    out.push_back(path.string());
  } else {
    errors.push_back(Diagnostic{path.string(), "", 0, 0, Severity::kError, "no such file or folder",
                                "unreadable"});
  }
}

}  // namespace

std::vector<std::string> list_bank_files(const std::vector<std::string>& paths,
                                         std::vector<Diagnostic>& errors) {
  std::vector<std::string> files;
  for (const auto& p : paths) collect_files(p, files, errors);
  return files;
}

std::vector<Cursor> problem_items(const Cursor& root) {
  if (root.is_object() && root.has("problems")) {
    root.allow_only({"problems", "$schema", "title", "description", "conventions"});
    return root.at("problems").items();
  }
  return {root};
}

Bank load_bank(const std::vector<std::string>& paths) {
  Bank bank;
  bank.files = list_bank_files(paths, bank.errors);
  std::map<std::string, std::string> seen;  // id -> where
  for (const auto& name : bank.files) {
    std::shared_ptr<const SourceFile> file;
    try {
      file = load_json_file(name);
    } catch (const Error& e) {
      bank.errors.push_back(e.diagnostic());
      continue;
    }
    Cursor root(file);
    std::vector<Cursor> items;
    try {
      items = problem_items(root);
    } catch (const Error& e) {
      bank.errors.push_back(e.diagnostic());
      continue;
    }
    Conventions conventions;
    try {
      if (root.is_object() && root.has("conventions")) {
        conventions = read_conventions(root.at("conventions"), conventions);
      }
    } catch (const Error& e) {
      bank.errors.push_back(e.diagnostic());
      continue;
    }
    for (const auto& item : items) {
      try {
        Problem p = read_problem(item, conventions);
        auto [it, fresh] = seen.emplace(p.id, fmt::format("{}{}", p.file, p.path));
        if (!fresh)
          item.at("id").fail(fmt::format("duplicate id '{}' (first used at {})", p.id, it->second),
                             "duplicate-id");
        bank.problems.push_back(std::move(p));
      } catch (const Error& e) {
        bank.errors.push_back(e.diagnostic());
      }
    }
  }
  return bank;
}

}  // namespace raygrade
