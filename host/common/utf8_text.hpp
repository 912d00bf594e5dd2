#pragma once
// Text that may not be UTF-8 made so: Linux file names are bytes, and a name
// such as $'\xff.off' must neither break a JSON report (nlohmann::json
// refuses invalid UTF-8 when it writes) nor a Python message (decoded as
// UTF-8). Each byte that is not part of a valid UTF-8 sequence is written
// as the four characters \xHH, as Python's "backslashreplace" writes it.
#include <string>
#include <string_view>

namespace meshparticles {

// `text` unchanged when it is valid UTF-8 (no overlong forms, surrogates or
// code points past U+10FFFF: what JSON writers refuse); else with each
// stray byte as \xHH.
std::string escaped_utf8(std::string_view text);

}  // namespace meshparticles
