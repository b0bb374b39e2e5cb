// Names as keys, through utf8proc.
#include "core/name_key.h"

#include <cstdlib>
#include <memory>

#include "core/escape.h"

#if RAYGRADE_HAS_UTF8PROC
#include <utf8proc.h>
#endif

namespace raygrade {

std::string name_key(std::string_view s) {
  // ASCII alone: its NFKC_Casefold is its lower case (and no ASCII character is ignorable).
  bool ascii = true;
  for (unsigned char c : s) ascii = ascii && c < 0x80;
  if (ascii) return ascii_lower(std::string(s));
#if RAYGRADE_HAS_UTF8PROC
  if (!is_valid_utf8(s)) return ascii_lower(std::string(s));
  utf8proc_uint8_t* folded = nullptr;
  auto options = static_cast<utf8proc_option_t>(
      UTF8PROC_STABLE | UTF8PROC_COMPAT | UTF8PROC_COMPOSE | UTF8PROC_CASEFOLD | UTF8PROC_IGNORE);
  utf8proc_ssize_t n = utf8proc_map(reinterpret_cast<const utf8proc_uint8_t*>(s.data()),
                                    static_cast<utf8proc_ssize_t>(s.size()), &folded, options);
  std::unique_ptr<utf8proc_uint8_t, decltype(&std::free)> owned(folded, &std::free);
  if (n < 0) return ascii_lower(std::string(s));  // out of memory, or text utf8proc refuses
  return std::string(reinterpret_cast<const char*>(folded), static_cast<std::size_t>(n));
#else
  return ascii_lower(std::string(s));
#endif
}

}  // namespace raygrade
