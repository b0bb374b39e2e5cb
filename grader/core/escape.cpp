// Escaping for output formats.
#include "core/escape.h"

#include <fmt/format.h>

namespace raygrade {

namespace {

// The length of the well-formed UTF-8 sequence starting at s[i], or 0 if it is ill-formed
// (ranges from the Unicode Standard, table 3-7).
std::size_t utf8_sequence_length(std::string_view s, std::size_t i) {
  auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  unsigned char c = byte(i);
  if (c < 0x80) return 1;
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;
  if (c >= 0xC2 && c <= 0xDF) {
    n = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    n = 3;
    if (c == 0xE0) lo = 0xA0;  // no overlong forms
    if (c == 0xED) hi = 0x9F;  // no surrogates
  } else if (c >= 0xF0 && c <= 0xF4) {
    n = 4;
    if (c == 0xF0) lo = 0x90;  // no overlong forms
    if (c == 0xF4) hi = 0x8F;  // nothing above U+10FFFF
  } else {
    return 0;
  }
  if (i + n > s.size()) return 0;
  if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k) {
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  }
  return n;
}

// A C0 control character other than tab and the line breaks: not allowed in HTML or XML text
// (a terminal escape sequence typed into a name), so the escapers drop it.
bool is_disallowed_control(char c) {
  return static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r';
}

// A directional formatting character that reorders the text around it (U+202A to U+202E,
// U+2066 to U+2069: embeddings, overrides, isolates) starts at s[i]: shown as written, it can
// make a name or a statement read as something else. The escapers drop it (the marks U+200E,
// U+200F and U+061C, which reorder nothing beyond their neighbours, are kept).
bool is_bidi_control_at(std::string_view s, std::size_t i) {
  if (i + 2 >= s.size() || s[i] != '\xE2') return false;
  auto b1 = static_cast<unsigned char>(s[i + 1]), b2 = static_cast<unsigned char>(s[i + 2]);
  return (b1 == 0x80 && b2 >= 0xAA && b2 <= 0xAE) || (b1 == 0x81 && b2 >= 0xA6 && b2 <= 0xA9);
}

// A C1 control (U+0080 to U+009F, bytes C2 80 to C2 9F) starts at s[i].
bool is_c1_control_at(std::string_view s, std::size_t i) {
  return s[i] == '\xC2' && i + 1 < s.size() && static_cast<unsigned char>(s[i + 1]) < 0xA0;
}

}  // namespace

std::string html_escape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    char c = s[i];
    // C1 controls (U+0080 to U+009F, bytes C2 80 to C2 9F) are not allowed in HTML either.
    if (is_c1_control_at(s, i)) {
      ++i;
      continue;
    }
    if (is_bidi_control_at(s, i)) {
      i += 2;
      continue;
    }
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default:
        // DEL is not allowed in HTML text either.
        if (!is_disallowed_control(c) && c != '\x7F') out += c;
    }
  }
  return out;
}

std::string xml_text(std::string_view s, std::size_t* changed) {
  std::string out;
  out.reserve(s.size());
  std::size_t n_changed = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    char c = s[i];
    auto u = static_cast<unsigned char>(c);
    if (is_disallowed_control(c) || c == '\x7F') {
      ++n_changed;
      continue;
    }
    if (is_c1_control_at(s, i) || is_bidi_control_at(s, i)) {
      i += is_c1_control_at(s, i) ? 1 : 2;
      ++n_changed;
      continue;
    }
    if (u < 0x80) {
      out += c;
      continue;
    }
    // XML parsers reject a whole document over one ill-formed byte, and over the noncharacters
    // U+FFFE and U+FFFF, which XML 1.0's Char excludes: U+FFFD instead.
    std::size_t n = utf8_sequence_length(s, i);
    if (n == 3 && s.substr(i, 2) == "\xEF\xBF" && static_cast<unsigned char>(s[i + 2]) >= 0xBE) {
      n = 0;
      i += 2;
    }
    if (n == 0) {
      out += "\xEF\xBF\xBD";
      ++n_changed;
    } else {
      out.append(s.substr(i, n));
      i += n - 1;
    }
  }
  if (changed) *changed = n_changed;
  return out;
}

std::string html_escape_braces(std::string_view s) {
  std::string out;
  for (char c : html_escape(s)) {
    if (c == '{') {
      out += "&#123;";
    } else if (c == '}') {
      out += "&#125;";
    } else {
      out += c;
    }
  }
  return out;
}

std::string xml_escape(std::string_view s) {
  std::string out;
  for (char c : xml_text(s)) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string markdown_escape(std::string_view s) {
  static constexpr std::string_view kSpecial = "\\`*_{}[]()#+-.!|<>&$~";
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    char c = s[i];
    // A line break would end a table row or start a heading: text stays on its line.
    if (c == '\n' || c == '\r') {
      out += ' ';
      continue;
    }
    // Control characters (terminal escape sequences, NUL) and reordering marks: dropped, as
    // text_escape drops them, since Markdown is read on terminals too.
    if (is_disallowed_control(c) || c == '\x7F') continue;
    if (is_c1_control_at(s, i) || is_bidi_control_at(s, i)) {
      i += is_c1_control_at(s, i) ? 1 : 2;
      continue;
    }
    if (kSpecial.find(c) != std::string_view::npos) out += '\\';
    out += c;
  }
  return out;
}

std::string latex_escape(std::string_view s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '\\': out += "\\textbackslash{}"; break;
      case '{': out += "\\{"; break;
      case '}': out += "\\}"; break;
      case '$': out += "\\$"; break;
      case '&': out += "\\&"; break;
      case '#': out += "\\#"; break;
      case '^': out += "\\textasciicircum{}"; break;
      case '_': out += "\\_"; break;
      case '%': out += "\\%"; break;
      case '~': out += "\\textasciitilde{}"; break;
      default: out += c;
    }
  }
  return out;
}

std::string csv_field(std::string_view s) {
  if (s.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(s);
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string csv_cell(std::string_view s) {
  // Control characters (NUL, tab, line breaks and escape sequences among them) and C1 controls
  // become \xNN and \uNNNN: a gradebook on a terminal cannot retitle or clear it, and a cell
  // cannot start with a NUL or a line feed that a spreadsheet would skip to reach a formula.
  std::string v = printable(s);
  if (!v.empty() && (v[0] == '=' || v[0] == '+' || v[0] == '-' || v[0] == '@')) {
    v.insert(v.begin(), '\'');
  }
  return csv_field(v);
}

std::string text_escape(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    auto u = static_cast<unsigned char>(s[i]);
    if ((u < 0x20 && u != '\t' && u != '\n') || u == 0x7f) continue;
    if (is_c1_control_at(s, i)) {
      ++i;  // a C1 control (U+0080 to U+009F)
      continue;
    }
    if (is_bidi_control_at(s, i)) {
      i += 2;
      continue;
    }
    out += s[i];
  }
  return out;
}

std::string safe_file_name(std::string_view id) {
  std::string out;
  for (char c : id) {
    bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
              c == '.' || c == '_' || c == '-';
    out += ok ? c : '_';
    if (out.size() >= 100) break;
  }
  if (out.empty() || out.find_first_not_of('.') == std::string::npos) out = "_" + out;
  // Never a leading '.' (hidden, or a path of dots) nor '-' (read as an option by commands,
  // and as a formula by spreadsheets, whose guard would then change the name in an index).
  if (out[0] == '.' || out[0] == '-') out[0] = '_';
  return out;
}

std::string ascii_lower(std::string s) {
  for (char& c : s)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return s;
}

std::string unique_file_name(std::string_view id, std::set<std::string>& taken) {
  std::string base = safe_file_name(id), name = base;
  for (int n = 2; !taken.insert(ascii_lower(name)).second; ++n)
    name = fmt::format("{}-{}", base, n);
  return name;
}

std::size_t first_invalid_utf8(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    std::size_t n = utf8_sequence_length(s, i);
    if (n == 0) return i;
    i += n;
  }
  return std::string_view::npos;
}

bool is_valid_utf8(std::string_view s) { return first_invalid_utf8(s) == std::string_view::npos; }

std::string printable(std::string_view s, std::size_t max_bytes) {
  std::string out;
  std::size_t i = 0;
  while (i < s.size() && i < max_bytes) {
    auto c = static_cast<unsigned char>(s[i]);
    std::size_t n = utf8_sequence_length(s, i);
    if (n == 0 || c < 0x20 || c == 0x7F) {
      out += fmt::format("\\x{:02X}", c);
      ++i;
    } else if (n == 2 && is_c1_control_at(s, i)) {
      // C1 controls (U+0080 to U+009F): some terminals act on them as on escape sequences.
      out += fmt::format("\\u{:04X}", static_cast<unsigned char>(s[i + 1]));
      i += 2;
    } else if (is_bidi_control_at(s, i)) {
      // Reordering marks: shown by their code point, so that a quoted name reads as typed.
      out +=
          fmt::format("\\u{:04X}", 0x2000 + ((static_cast<unsigned char>(s[i + 1]) - 0x80) << 6) +
                                       (static_cast<unsigned char>(s[i + 2]) - 0x80));
      i += 3;
    } else {
      out.append(s.substr(i, n));
      i += n;
    }
  }
  if (i < s.size()) out += "...";
  return out;
}

}  // namespace raygrade
