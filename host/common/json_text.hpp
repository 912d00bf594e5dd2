#pragma once
// Every JSON document the program writes or returns is made text here:
// strings that are not UTF-8 (a file name of raw bytes, a message quoting
// one) are written with their stray bytes escaped (common/utf8_text.hpp),
// where nlohmann::json's dump() would throw type_error 316 after the work.
#include <string>

#include <nlohmann/json.hpp>

namespace meshparticles {

// `value.dump(indent)` (-1: one line), every string and key valid UTF-8.
std::string json_text(const nlohmann::json& value, int indent = -1);

// `value` as json_text writes it and a reader reads it back: what to compare
// with a document read from a file.
nlohmann::json as_written(const nlohmann::json& value);

}  // namespace meshparticles
