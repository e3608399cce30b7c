#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace spira::json_read {

// Reading JSON that came from a file (a cell, a plan folder's report.json, a project): every problem
// becomes an InputError that names the file (`what`), the place and what was found there, with `hint`
// saying what to do. Nothing of the JSON library's own wording reaches the user.

// Parses `text`; a syntax error or a number beyond the range of a double is reported with its line
// and column.
nlohmann::json parse(const std::string& text, const std::string& what, const std::string& hint);

// Parses CBOR (RFC 8949) bytes: malformed content is reported with its byte offset, data nested
// deeper than 64 levels is refused, tags are refused.
nlohmann::json parseCbor(std::string_view bytes, const std::string& what, const std::string& hint);

// What a value is, for a message: "the string \"x\"", "the number 5", "an object", ...; quoted text
// is clipped so that a huge value is not echoed back.
std::string describe(const nlohmann::json& v);

// The member `key` of `object`, which must be there and have the type the name says (a whole number
// is an integer, or a floating-point number with no fraction, within the range of int64).
const nlohmann::json& member(const nlohmann::json& object, const char* key, const std::string& what,
                             const std::string& hint);
std::string text(const nlohmann::json& object, const char* key, const std::string& what,
                 const std::string& hint);
double number(const nlohmann::json& object, const char* key, const std::string& what,
              const std::string& hint);
std::int64_t wholeNumber(const nlohmann::json& object, const char* key, const std::string& what,
                         const std::string& hint);
bool flag(const nlohmann::json& object, const char* key, const std::string& what, const std::string& hint);

// The same, `fallback` when `object` has no member `key` (or is not an object); a member of the wrong
// type is still an error.
std::string text(const nlohmann::json& object, const char* key, const std::string& fallback,
                 const std::string& what, const std::string& hint);
double number(const nlohmann::json& object, const char* key, double fallback, const std::string& what,
              const std::string& hint);
std::int64_t wholeNumber(const nlohmann::json& object, const char* key, std::int64_t fallback,
                         const std::string& what, const std::string& hint);

}  // namespace spira::json_read
