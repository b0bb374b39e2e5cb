// People's names compared as people read them: the same letters whatever their case or the
// Unicode form they were typed in.
#pragma once

#include <string>
#include <string_view>

namespace raygrade {

// `s` in Unicode's compatibility normal form with full case folding (NFKC_Casefold, by
// utf8proc): "Émile" typed precomposed or as E + U+0301 gives one key, "STRASSE" and "straße"
// give one key, and default-ignorable characters (zero-width and bidi controls) are dropped.
// Text that is not UTF-8 gets its ASCII letters lowered and is otherwise kept byte for byte.
// The web build has no utf8proc: there ASCII letters alone are lowered.
std::string name_key(std::string_view s);

}  // namespace raygrade
