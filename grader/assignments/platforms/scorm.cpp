// The SCORM package of an assignment: its generic practice page as the package's one SCO, and
// imsmanifest.xml, the content package's manifest (SCORM 1.2 or 2004 4th edition).
#include "assignments/platforms/scorm.h"

#include <fmt/format.h>

#include <pugixml.hpp>
#include <sstream>

#include "assignments/handout.h"
#include "assignments/platforms/scorm_assets.h"
#include "assignments/variants.h"
#include "core/escape.h"

namespace raygrade {
namespace {

// What differs between the two versions' manifests: SCORM 1.2 packages by IMS Content
// Packaging 1.1.2 with ADL's adlcp_rootv1p2 extension, SCORM 2004 by IMS CP 1.1.4 (namespace
// imscp_v1p1) with adlcp_v1p3, whose attribute is spelt scormType.
struct ScormFlavour {
  std::string_view version;         // on the command line
  std::string_view cp_namespace;    // the manifest's own elements
  std::string_view adl_namespace;   // adlcp:
  std::string_view schema_version;  // <metadata><schemaversion>
  std::string_view type_attribute;  // the resource's SCO flag
  std::string_view cp_schema;       // the schemas' file names, for xsi:schemaLocation
  std::string_view adl_schema;
};

constexpr ScormFlavour kScorm12{"1.2",
                                "http://www.imsproject.org/xsd/imscp_rootv1p1p2",
                                "http://www.adlnet.org/xsd/adlcp_rootv1p2",
                                "1.2",
                                "adlcp:scormtype",
                                "imscp_rootv1p1p2.xsd",
                                "adlcp_rootv1p2.xsd"};
constexpr ScormFlavour kScorm2004{"2004",
                                  "http://www.imsglobal.org/xsd/imscp_v1p1",
                                  "http://www.adlnet.org/xsd/adlcp_v1p3",
                                  "2004 4th Edition",
                                  "adlcp:scormType",
                                  "imscp_v1p1.xsd",
                                  "adlcp_v1p3.xsd"};

const ScormFlavour& flavour(std::string_view version) {
  return version == kScorm2004.version ? kScorm2004 : kScorm12;
}

// An identifier of the manifest (an XML ID: a letter first, then letters, digits, '-', '_'
// and '.'), from the assignment's id.
std::string xml_id(std::string_view prefix, std::string_view id) {
  std::string out(prefix);
  for (char c : id) {
    bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                 c == '-' || c == '_' || c == '.';
    out += plain ? c : '_';
  }
  return out;
}

// At most `limit` characters (code points) of UTF-8 text: IMS CP 1.1.2 bounds a title at 200.
std::string clipped(const std::string& text, std::size_t limit) {
  std::size_t chars = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80 && chars++ == limit) {
      return text.substr(0, i);
    }
  }
  return text;
}

// imsmanifest.xml: one organization with one item, whose resource is the page (a SCO) with
// every file of the package listed.
std::string manifest(const AssignmentSpec& spec, const ScormFlavour& f,
                     const std::vector<std::string>& files) {
  pugi::xml_document doc;
  auto declaration = doc.append_child(pugi::node_declaration);
  declaration.append_attribute("version") = "1.0";
  declaration.append_attribute("encoding") = "UTF-8";
  auto root = doc.append_child("manifest");
  root.append_attribute("identifier") = xml_id("raygrade-", spec.id).c_str();
  root.append_attribute("version") = "1";
  root.append_attribute("xmlns") = std::string(f.cp_namespace).c_str();
  root.append_attribute("xmlns:adlcp") = std::string(f.adl_namespace).c_str();
  root.append_attribute("xmlns:xsi") = "http://www.w3.org/2001/XMLSchema-instance";
  root.append_attribute("xsi:schemaLocation") =
      fmt::format("{} {} {} {}", f.cp_namespace, f.cp_schema, f.adl_namespace, f.adl_schema)
          .c_str();
  auto metadata = root.append_child("metadata");
  metadata.append_child("schema").text() = "ADL SCORM";
  metadata.append_child("schemaversion").text() = std::string(f.schema_version).c_str();

  std::string title = clipped(spec.title.empty() ? spec.id : spec.title, 200);
  std::string organization = xml_id("organization-", spec.id);
  std::string resource = xml_id("resource-", spec.id);
  auto organizations = root.append_child("organizations");
  organizations.append_attribute("default") = organization.c_str();
  auto org = organizations.append_child("organization");
  org.append_attribute("identifier") = organization.c_str();
  org.append_child("title").text() = title.c_str();
  auto item = org.append_child("item");
  item.append_attribute("identifier") = xml_id("item-", spec.id).c_str();
  item.append_attribute("identifierref") = resource.c_str();
  item.append_child("title").text() = title.c_str();

  auto res = root.append_child("resources").append_child("resource");
  res.append_attribute("identifier") = resource.c_str();
  res.append_attribute("type") = "webcontent";
  res.append_attribute(std::string(f.type_attribute).c_str()) = "sco";
  res.append_attribute("href") = files.front().c_str();
  for (const auto& file : files) res.append_child("file").append_attribute("href") = file.c_str();

  std::ostringstream out;
  doc.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
  return out.str();
}

}  // namespace

const std::vector<std::string>& scorm_versions() {
  static const std::vector<std::string> versions = {std::string(kScorm12.version),
                                                    std::string(kScorm2004.version)};
  return versions;
}

LmsPackage scorm_package(const LmsExportInput& in, const std::string& out) {
  const AssignmentSpec& spec = *in.spec;
  if (has_per_student_numbers(spec, in.bank->problems)) {
    throw Error(Diagnostic{spec.file, "/variants", 0, 0, Severity::kError,
                           "each student has their own numbers, but a SCORM package is one page "
                           "for the whole class, which cannot know whose numbers to grade: set "
                           "\"per_student\": false (one set of numbers for everyone) to export it",
                           "scorm-per-student"});
  }
  const ScormFlavour& f = flavour(in.version);
  PracticeAssets assets = practice_assets(spec, read_file_bytes(in.grader_js));
  // The page reports to the LMS around it: scorm_page.js runs first and reads the version.
  assets.lms_data = {{"scorm", std::string(f.version)}};
  assets.lms_script = kScormScript;
  assets.kept =
      "Your answers are kept in this browser and, when the page is opened from your course's "
      "site, by the site too; each Check sends it your score on the whole assignment.";
  // The generic page: the LMS launches the same package for every student.
  Handout page =
      make_handout(spec, student_problems(spec, in.bank->problems, ""), nullptr, &assets);

  std::vector<ZipEntry> entries = {{"index.html", std::move(page.html), false}};
  std::vector<std::string> files;
  files.reserve(entries.size());
  for (const auto& e : entries) files.push_back(e.name);
  entries.insert(entries.begin(), ZipEntry{"imsmanifest.xml", manifest(spec, f, files), false});

  LmsPackage p;
  p.files = entries;
  std::string zip_name = safe_file_name(spec.id) + "-scorm.zip";
  std::string zipped;
  if (zip_available()) {
    p.files.push_back({zip_name, zip_archive(entries), false});
    zipped = fmt::format("{}/{} (and the same files in {}/)", out, zip_name, out);
  } else {
    zipped = fmt::format(
        "{0}/imsmanifest.xml and {0}/index.html (this raygrade was built without libzip: zip "
        "the two files, at the zip's top level, into {1})",
        out, zip_name);
  }
  p.next_step = fmt::format(
      "Wrote {}: a SCORM {} package of {} ({} problem{}, one page for the whole class, graded "
      "in the student's browser with {}). Upload the zip as a SCORM package (Moodle: the SCORM "
      "package activity; Canvas and Blackboard: import it as SCORM content).",
      zipped, f.schema_version, spec.id, spec.problems.size(), spec.problems.size() == 1 ? "" : "s",
      in.grader_js.string());
  return p;
}

LmsExport Scorm::lms_export() {
  LmsExport e;
  e.summary =
      "the practice page as a SCORM package for any LMS (Moodle, Canvas, Blackboard): graded in "
      "the student's browser, the score sent to the LMS";
  e.make = &scorm_package;
  e.takes_grader_js = true;
  e.grader_js_help =
      "raygrade.js of the web build (scripts/build-web.sh), which grades the practice page in "
      "the student's browser";
  e.versions = scorm_versions();
  e.version_option = "--scorm";
  e.version_help = "the SCORM version (default 1.2; 2004 is 4th edition)";
  return e;
}

}  // namespace raygrade
