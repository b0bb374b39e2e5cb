// Escaping of text that users control (names, ids, formulas, free text) for every output
// format, and safe file names.
#pragma once

#include <set>
#include <string>
#include <string_view>

namespace raygrade {

// &, <, >, " and ' as entities, control characters other than tab and line breaks dropped:
// safe in HTML and XML text and attribute values.
std::string html_escape(std::string_view s);
// html_escape's text with '{' and '}' as &#123; and &#125; too: for text a platform passes
// through a template that substitutes braces (PrairieLearn's mustache pass, Moodle's {name}
// and {=formula} of a calculated question); the browser shows the entity as the brace.
std::string html_escape_braces(std::string_view s);
// The same for XML (JUnit): the text of xml_text, with &, <, >, " and ' as entities.
std::string xml_escape(std::string_view s);
// Text that XML 1.0 allows, for a writer that escapes &, < and > itself (pugixml): control
// characters other than tab and line breaks, C1 controls and reordering controls are dropped,
// and ill-formed UTF-8 (a lone surrogate's bytes among them) and the noncharacters U+FFFE and
// U+FFFF become U+FFFD, so the document always parses. `changed`, when given, counts the
// characters dropped or replaced.
std::string xml_text(std::string_view s, std::size_t* changed = nullptr);
// Markdown: backslash before every character Markdown or inline HTML could act on; line
// breaks become spaces.
std::string markdown_escape(std::string_view s);
// LaTeX text mode: \ { } $ & # ^ _ % ~ escaped.
std::string latex_escape(std::string_view s);
// A CSV cell: control characters written as printable() writes them (\x1B, \x00, \x0A),
// quoted when needed, and a leading = + - @ neutralised with a leading apostrophe so
// spreadsheets do not run it as a formula.
std::string csv_cell(std::string_view s);

// A CSV field with RFC 4180's quoting alone (quoted when it holds a comma, a quote or a line
// break), for cells handed back unchanged to the platform that wrote them (Moodle's worksheet:
// its "-" must stay "-").
std::string csv_field(std::string_view s);
// Plain text for terminals and .txt files: control characters other than tab and newline
// (terminal escape sequences among them) and C1 controls are dropped.
std::string text_escape(std::string_view s);
// A file name made from an id: only [A-Za-z0-9._-], never "." or "..", never empty, at most
// 100 bytes; other bytes become '_'. It cannot name a path outside its folder.
std::string safe_file_name(std::string_view id);
// safe_file_name(id), with "-2", "-3", ... added until no name in `taken` is the same when
// letters are compared without case (as macOS's and Windows's file systems compare them); the
// chosen name, in lower case, is added to `taken`.
std::string unique_file_name(std::string_view id, std::set<std::string>& taken);
// ASCII letters in lower case; every other byte (UTF-8 sequences among them) unchanged.
std::string ascii_lower(std::string s);

// True when `s` is well-formed UTF-8 (no overlong forms, surrogates or code points above
// U+10FFFF).
bool is_valid_utf8(std::string_view s);
// The offset of the first byte of `s` that starts no well-formed UTF-8 sequence, or npos.
std::size_t first_invalid_utf8(std::string_view s);
// Text quoted in a diagnostic or printed to a terminal: well-formed UTF-8 is kept, control
// characters (escape sequences included) and ill-formed bytes become \xNN, and the result is
// cut after `max_bytes` of input with "...". Always valid UTF-8 with no control characters.
std::string printable(std::string_view s, std::size_t max_bytes = std::string_view::npos);

}  // namespace raygrade
